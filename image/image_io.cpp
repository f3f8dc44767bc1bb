#include "image/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/util/atomic_file.h"
#include "core/util/colour.h"

namespace rsaa {
namespace {

bool is_float_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext == ".exr" || ext == ".hdr";
}

// Where the colour and alpha channels are, from the channel count and OpenImageIO's alpha index.
struct Layout {
  int colour_channels = 0;  // 1 (grey) or 3 (RGB)
  int alpha = -1;           // channel index, -1: none
  int read_end = 0;         // channels [0, read_end) are read
};

Layout layout_of(const std::string& name, const OIIO::ImageSpec& spec) {
  const int n = spec.nchannels, a = spec.alpha_channel;
  const auto refuse = [&](const std::string& why) -> Layout {
    throw std::runtime_error(name + ": " + std::to_string(n) + " channels (" + why +
                             "); expected grey, grey+alpha, RGB or RGBA");
  };
  Layout l;
  if (n == 1) {
    l = {1, -1, 1};
  } else if (n == 2) {
    if (a != 1) return refuse("two channels, the second not marked as alpha");
    l = {1, 1, 2};
  } else if (n >= 3) {
    if (a >= 0 && a < 3) return refuse("alpha among the first three");
    if (a >= 8) return refuse("alpha in channel " + std::to_string(a));
    l = {3, a, a >= 0 ? a + 1 : 3};
  } else {
    return refuse("none");
  }
  return l;
}

}  // namespace

DecodedImage decode_image(const std::string& name, const std::string& bytes, const ImageBudget& budget) {
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  // Straight alpha as stored, so that compositing is done once, here, in linear light.
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(name, &config, &memory);
  if (!in)
    throw std::runtime_error(name + ": cannot read " + budget.what + " (" + OIIO::geterror() + ")");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw std::runtime_error(name + ": " + budget.what + " has no pixels");
  const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
  if (spec.width > budget.max_side || spec.height > budget.max_side || pixels > budget.max_pixels)
    throw LimitError(name + ": " + budget.what + " declares " + std::to_string(spec.width) +
                             "x" + std::to_string(spec.height) + " pixels; the limit is " +
                             std::to_string(budget.max_side) + " per side and " +
                             std::to_string(budget.max_pixels) + " pixels");
  if (spec.depth > 1) throw std::runtime_error(name + ": volume images are not read");
  const Layout layout = layout_of(name, spec);

  DecodedImage d;
  d.width = spec.width;
  d.height = spec.height;
  d.float_format = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                   spec.format.basetype == OIIO::TypeDesc::HALF ||
                   spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  d.premultiplied = layout.alpha >= 0 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0;
  d.rgba.resize(pixels * 4);
  // A band of rows at a time: the channels read may be more than the four kept.
  const int band = std::max(1, int((std::size_t{1} << 20) / (std::size_t(spec.width) * layout.read_end)));
  std::vector<float> rows;
  for (int y0 = 0; y0 < spec.height; y0 += band) {
    const int y1 = std::min(spec.height, y0 + band);
    rows.resize(std::size_t(y1 - y0) * spec.width * layout.read_end);
    if (!in->read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, layout.read_end,
                            OIIO::TypeDesc::FLOAT, rows.data()))
      throw std::runtime_error(name + ": cannot read pixels (" + in->geterror() + ")");
    for (std::size_t i = 0; i < std::size_t(y1 - y0) * spec.width; ++i) {
      const float* p = &rows[i * layout.read_end];
      float* out = &d.rgba[(std::size_t(y0) * spec.width + i) * 4];
      for (int c = 0; c < 3; ++c) out[c] = p[layout.colour_channels == 3 ? c : 0];
      out[3] = layout.alpha >= 0 ? p[layout.alpha] : 1.0f;
    }
  }
  return d;
}

DecodedImage read_decoded_image(const std::string& path, const ImageBudget& budget) {
  return decode_image(path, read_whole_file(path, budget.file_bytes, budget.what), budget);
}

namespace {

// Linear colour of one decoded pixel, alpha composited over black. A NaN alpha gives NaN.
Rgb linear_pixel(const DecodedImage& d, std::size_t i) {
  const float* p = &d.rgba[4 * i];
  float v[3];
  for (int c = 0; c < 3; ++c) v[c] = d.float_format ? p[c] : srgb_to_linear(p[c]);
  const float alpha = std::isfinite(p[3]) ? std::clamp(p[3], 0.0f, 1.0f) : p[3];
  if (!d.premultiplied)
    for (float& x : v) x *= alpha;
  return {v[0], v[1], v[2]};
}

}  // namespace

void write_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw std::runtime_error(path + ": empty image");
  const bool linear = is_float_format(path);
  const std::filesystem::path target(path);
  // Keep the extension so that OpenImageIO picks the same format for the temporary file.
  const std::filesystem::path temporary = temporary_path_beside(path);
  remove_stale_temporaries(target.parent_path().empty() ? "." : target.parent_path().string());
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": no image format for this extension");
  const std::size_t n = image.pixels.size();
  bool ok;
  if (linear) {
    std::vector<float> values(n * 3);
    for (std::size_t i = 0; i < n; ++i) {
      const Rgb p = image.pixels[i];
      values[3 * i + 0] = std::isfinite(p.r) ? p.r : 0.0f;
      values[3 * i + 1] = std::isfinite(p.g) ? p.g : 0.0f;
      values[3 * i + 2] = std::isfinite(p.b) ? p.b : 0.0f;
    }
    ok = out->open(temporary.string(), OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT)) &&
         out->write_image(OIIO::TypeDesc::FLOAT, values.data());
  } else {
    const DisplayImage display = to_display(image);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    ok = out->open(temporary.string(), spec) &&
         out->write_image(OIIO::TypeDesc::UINT8, display.rgb.data());
  }
  ok = out->close() && ok;
  if (!ok) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(path + ": cannot write image (" + out->geterror() + ")");
  }
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(path + ": cannot write image (" + error.message() + ")");
  }
}

Image read_image(const std::string& path) {
  const DecodedImage d = read_decoded_image(path);
  Image image(d.width, d.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = linear_pixel(d, i);
  return image;
}

DisplayImage to_display(const Image& image) {
  DisplayImage d{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 3), 0};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const Rgb p = image.pixels[i];
    d.non_finite_pixels += !(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
    d.rgb[3 * i + 0] = linear_to_srgb8(p.r);
    d.rgb[3 * i + 1] = linear_to_srgb8(p.g);
    d.rgb[3 * i + 2] = linear_to_srgb8(p.b);
  }
  return d;
}

DisplayImage read_display_image(const std::string& path) {
  const DecodedImage d = read_decoded_image(path);
  DisplayImage out{d.width, d.height, std::vector<std::uint8_t>(std::size_t(d.width) * d.height * 3), 0};
  for (std::size_t i = 0; i < std::size_t(d.width) * d.height; ++i) {
    const float* p = &d.rgba[4 * i];
    if (!d.float_format && p[3] == 1.0f) {
      // Opaque 8-bit pixels are taken as stored: no decode/encode round trip.
      for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(p[c] * 255.0f));
      continue;
    }
    const Rgb v = linear_pixel(d, i);
    out.non_finite_pixels += !(std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b));
    out.rgb[3 * i + 0] = linear_to_srgb8(v.r);
    out.rgb[3 * i + 1] = linear_to_srgb8(v.g);
    out.rgb[3 * i + 2] = linear_to_srgb8(v.b);
  }
  return out;
}

}  // namespace rsaa
