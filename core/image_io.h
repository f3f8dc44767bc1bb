// Image files through OpenImageIO. PNG and other 8-bit formats hold sRGB-encoded values, EXR
// holds linear floats; in memory an Image is always linear (docs/conventions.md section 5).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace rsaa {

// Writes atomically (temporary file in the same directory, then rename). The format follows the
// extension. Non-finite values are written as 0. Throws std::runtime_error naming the path.
void write_image(const std::string& path, const Image& image);

// Reads any format OpenImageIO knows into linear RGB (8-bit files are sRGB-decoded; alpha and
// extra channels dropped; grey replicated). Throws std::runtime_error naming the path.
Image read_image(const std::string& path);

// 8-bit sRGB display values, RGB interleaved, top row first: what PSNR is measured on.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};
DisplayImage to_display(const Image& image);
DisplayImage read_display_image(const std::string& path);

}  // namespace rsaa
