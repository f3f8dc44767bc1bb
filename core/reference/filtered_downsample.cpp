#include "core/reference/filtered_downsample.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rsaa {

const FilterTaps& small_filter_taps() {
  static const FilterTaps taps = {{{0, 0}, {0.5, 1}, {1, -0.5}, {-0.5, -1}, {-1, 0.5}}};
  return taps;
}

const FilterTaps& large_filter_taps() {
  static const FilterTaps taps = {{{0, 0}, {1, 2}, {2, -1}, {-1, -2}, {-2, 1}}};
  return taps;
}

namespace {

// The average of bilinear fetches at the taps around supersampled position (cx, cy).
Rgb average_of_taps(const Image& image, double cx, double cy, const FilterTaps& taps) {
  double r = 0, g = 0, b = 0;
  for (const Vec2& t : taps) {
    const Rgb c = bilinear_fetch(image, cx + t.x, cy + t.y);
    r += c.r, g += c.g, b += c.b;
  }
  return {float(r / taps.size()), float(g / taps.size()), float(b / taps.size())};
}

}  // namespace

Image filtered_downsample(const Image& hi, const std::vector<float>& alpha, int kernel) {
  if (kernel < 1 || kernel > 3) throw std::invalid_argument("filtered SSAA kernel must be 1, 2 or 3");
  if (hi.width % 2 || hi.height % 2 || hi.width == 0 || hi.height == 0)
    throw std::invalid_argument("filtered SSAA needs an even-sized supersampled image, not " +
                                std::to_string(hi.width) + "x" + std::to_string(hi.height));
  if (alpha.size() != hi.pixels.size())
    throw std::invalid_argument("filtered SSAA: alpha has " + std::to_string(alpha.size()) + " values for " +
                                std::to_string(hi.pixels.size()) + " pixels");
  Image alpha_image(hi.width, hi.height);  // alpha in the red channel, to reuse the fetch
  for (std::size_t i = 0; i < alpha.size(); ++i) alpha_image.pixels[i].r = alpha[i];
  Image out(hi.width / 2, hi.height / 2);
  const FilterTaps centre_only = {{{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}};
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      // The output pixel's centre is the corner between supersampled texels 2x and 2x + 1.
      const double cx = 2.0 * x + 0.5, cy = 2.0 * y + 0.5;
      if (kernel == 1) {
        out.at(x, y) = average_of_taps(hi, cx, cy, centre_only);
        continue;
      }
      const Rgb small = average_of_taps(hi, cx, cy, small_filter_taps());
      if (kernel == 2) {
        out.at(x, y) = small;
        continue;
      }
      const Rgb large = average_of_taps(hi, cx, cy, large_filter_taps());
      const float a = std::clamp(average_of_taps(alpha_image, cx, cy, small_filter_taps()).r, 0.0f, 1.0f);
      out.at(x, y) = {large.r + a * (small.r - large.r), large.g + a * (small.g - large.g),
                      large.b + a * (small.b - large.b)};
    }
  return out;
}

}  // namespace rsaa
