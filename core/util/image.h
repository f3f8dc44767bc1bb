// Linear-light RGB images in memory, top row first (row index grows with pixel-space +y).
#pragma once

#include <vector>

namespace rsaa {

struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;  // width * height, row-major, row 0 = top

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h)) {}
  Rgb& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// Bilinear fetch at (x, y) in image pixel coordinates (pixel (i, j) has its centre at (i, j)),
// clamping to the edge as GL_CLAMP_TO_EDGE does.
Rgb bilinear_fetch(const Image& image, double x, double y);

}  // namespace rsaa
