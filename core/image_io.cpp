#include "core/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "core/colour.h"

namespace rsaa {
namespace {

bool is_float_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext == ".exr" || ext == ".hdr";
}

struct RawImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;  // as stored, 8-bit scaled to [0, 1]
  bool float_format = false;
};

RawImage read_raw(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error(path + ": cannot read image (" + OIIO::geterror() + ")");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw std::runtime_error(path + ": image has no pixels");
  if (std::int64_t(spec.width) * spec.height > (std::int64_t{1} << 28))
    throw std::runtime_error(path + ": image too large");
  RawImage raw;
  raw.width = spec.width;
  raw.height = spec.height;
  raw.channels = spec.nchannels;
  raw.float_format = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                     spec.format.basetype == OIIO::TypeDesc::HALF ||
                     spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  raw.values.resize(std::size_t(raw.width) * raw.height * raw.channels);
  if (!in->read_image(0, 0, 0, raw.channels, OIIO::TypeDesc::FLOAT, raw.values.data()))
    throw std::runtime_error(path + ": cannot read pixels (" + in->geterror() + ")");
  return raw;
}

float channel(const RawImage& raw, std::size_t pixel, int c) {
  return raw.values[pixel * raw.channels + std::min(c, raw.channels - 1)];
}

}  // namespace

void write_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw std::runtime_error(path + ": empty image");
  const bool linear = is_float_format(path);
  const std::filesystem::path target(path);
  // Keep the extension so that OpenImageIO picks the same format for the temporary file.
  const std::filesystem::path temporary =
      target.parent_path() / ("." + target.stem().string() + ".tmp-" +
                              std::to_string(::getpid()) + target.extension().string());
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
  const RawImage raw = read_raw(path);
  Image image(raw.width, raw.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    float v[3];
    for (int c = 0; c < 3; ++c) {
      const float x = channel(raw, i, c);
      v[c] = raw.float_format ? (std::isfinite(x) ? x : 0.0f) : srgb_to_linear(x);
    }
    image.pixels[i] = {v[0], v[1], v[2]};
  }
  return image;
}

DisplayImage to_display(const Image& image) {
  DisplayImage d{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 3)};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    d.rgb[3 * i + 0] = linear_to_srgb8(image.pixels[i].r);
    d.rgb[3 * i + 1] = linear_to_srgb8(image.pixels[i].g);
    d.rgb[3 * i + 2] = linear_to_srgb8(image.pixels[i].b);
  }
  return d;
}

DisplayImage read_display_image(const std::string& path) {
  const RawImage raw = read_raw(path);
  if (raw.float_format) return to_display(read_image(path));
  DisplayImage d{raw.width, raw.height, std::vector<std::uint8_t>(std::size_t(raw.width) * raw.height * 3)};
  for (std::size_t i = 0; i < std::size_t(raw.width) * raw.height; ++i)
    for (int c = 0; c < 3; ++c)
      d.rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(channel(raw, i, c) * 255.0f));
  return d;
}

}  // namespace rsaa
