// Image files through OpenImageIO. PNG and other 8-bit formats hold sRGB-encoded values, EXR
// holds linear floats; in memory an Image is always linear (docs/conventions.md section 5).
//
// Reading is bounded: only regular files (no FIFO or device), at most ImageBudget::file_bytes,
// and the declared size is checked against the budget before any pixel is allocated. Channels
// are read by the file's layout: grey, grey+alpha, RGB, RGBA (extra channels after RGB(A) are
// ignored; other layouts are refused). Alpha is composited over black: straight alpha (PNG)
// multiplies the linear colour, premultiplied alpha (EXR) is already composited.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/util/image.h"

namespace rsaa {

struct ImageBudget {
  std::uint64_t file_bytes;  // the file itself
  int max_side;              // width and height each
  std::uint64_t max_pixels;  // width * height
  const char* what;          // "image", "texture": names the kind in messages
};
// Images that rsaa compares or reads: renders go up to 8192x8192.
constexpr ImageBudget kImageBudget{std::uint64_t{512} << 20, 16384, std::uint64_t{1} << 26, "image"};
// Textures of models: each is decoded and uploaded whole.
constexpr ImageBudget kTextureBudget{std::uint64_t{256} << 20, 8192, std::uint64_t{1} << 24, "texture"};

// An image file decoded into four channels per pixel (R, G, B, A; alpha 1 when the file has
// none; grey replicated), values as stored: 8-bit formats scaled to [0, 1] and sRGB-encoded,
// float formats linear. `premultiplied`: the colour already carries the alpha (EXR).
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
  bool float_format = false;
  bool premultiplied = false;
};

// Decodes `bytes`, the contents of a file called `name` (its extension picks the format).
// Throws std::runtime_error naming `name` when the format is unknown, the declared size is over
// the budget (LimitError; the message gives both), the layout is not one of the four, or decoding fails.
DecodedImage decode_image(const std::string& name, const std::string& bytes, const ImageBudget& budget);
// Reads `path` under the budget's file checks, then decodes it.
DecodedImage read_decoded_image(const std::string& path, const ImageBudget& budget = kImageBudget);

// Loads the image module (OpenImageIO) now instead of on first use: a command that will write
// images says at once, before its renders, when it cannot (under a process or address-space limit
// the load failed only after minutes of work). Throws std::runtime_error saying why.
void require_image_module();

// Writes atomically (temporary file in the same directory, then rename). The format follows the
// extension. Non-finite values are written as 0. Throws std::runtime_error naming the path.
void write_image(const std::string& path, const Image& image);

// Reads any format OpenImageIO knows into linear RGB, alpha composited over black (8-bit files
// are sRGB-decoded). NaN and infinite values of float files are kept as they are. Throws
// std::runtime_error naming the path.
Image read_image(const std::string& path);

// 8-bit sRGB display values, RGB interleaved, top row first: what PSNR is measured on.
// `non_finite_pixels` counts pixels whose linear value had a NaN or infinite channel (encoded
// as 0): a comparison involving them is undefined, not "equal".
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::uint64_t non_finite_pixels = 0;
};
DisplayImage to_display(const Image& image);
DisplayImage read_display_image(const std::string& path);

}  // namespace rsaa
