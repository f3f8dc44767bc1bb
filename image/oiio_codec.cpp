// The OpenImageIO side of image_io, built as the module librsaa_oiio.so (see oiio_codec.h).
#include "image/oiio_codec.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/util/atomic_file.h"

namespace rsaa {
namespace {

// Where the colour and alpha channels are, from the channel count and OpenImageIO's alpha index.
struct Layout {
  int colour_channels = 0;  // 1 (grey) or 3 (RGB)
  int alpha = -1;           // channel index, -1: none
  int read_end = 0;         // channels [0, read_end) are read
};

// OpenImageIO's alpha index, or where a channel is named alpha when the index points nowhere (its
// GIF reader reports four channels, "A" the fourth, and alpha index 4: read as given, every pixel
// was taken with a stride of five channels).
int alpha_index(const OIIO::ImageSpec& spec) {
  if (spec.alpha_channel >= 0 && spec.alpha_channel < spec.nchannels) return spec.alpha_channel;
  for (int c = 0; c < spec.nchannels && c < int(spec.channelnames.size()); ++c)
    if (spec.channelnames[std::size_t(c)] == "A" || spec.channelnames[std::size_t(c)] == "Alpha") return c;
  return -1;
}

Layout layout_of(const std::string& name, const OIIO::ImageSpec& spec) {
  const int n = spec.nchannels, a = alpha_index(spec);
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

DecodedImage decode(const std::string& name, const std::string& bytes, const ImageBudget& budget) {
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
  // Pixels are read as a width x height grid from the top-left: a data window moved off the
  // origin, or a display window other than it (EXR), would be compared and resampled shifted.
  if (spec.x != 0 || spec.y != 0 || spec.full_x != 0 || spec.full_y != 0 || spec.full_width != spec.width ||
      spec.full_height != spec.height)
    throw std::runtime_error(name + ": its data window (" + std::to_string(spec.width) + "x" +
                             std::to_string(spec.height) + " at " + std::to_string(spec.x) + "," +
                             std::to_string(spec.y) + ") is not its display window (" +
                             std::to_string(spec.full_width) + "x" + std::to_string(spec.full_height) + " at " +
                             std::to_string(spec.full_x) + "," + std::to_string(spec.full_y) +
                             "); only images whose pixels fill the display window from 0,0 are read");
  const Layout layout = layout_of(name, spec);

  DecodedImage d;
  d.width = spec.width;
  d.height = spec.height;
  d.float_format = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                   spec.format.basetype == OIIO::TypeDesc::HALF ||
                   spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  d.premultiplied = layout.alpha >= 0 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0;
  d.rgba.resize(pixels * 4);
  // A band of rows at a time: the channels read may be more than the four kept. A tiled file is
  // read by whole rows of tiles (OpenImageIO 2.4's read_scanlines died of SIGFPE on tiled files).
  const bool tiled = spec.tile_width > 0 && spec.tile_height > 0;
  const std::size_t row_floats = std::size_t(spec.width) * std::size_t(layout.read_end);
  int band = std::max(1, int((std::size_t{1} << 20) / row_floats));
  if (tiled) {
    constexpr std::size_t kMaxBandFloats = std::size_t{1} << 26;  // 256 MiB of floats
    if (std::size_t(spec.tile_height) * row_floats > kMaxBandFloats)
      throw LimitError(name + ": " + budget.what + " has tiles " + std::to_string(spec.tile_width) + "x" +
                       std::to_string(spec.tile_height) + " pixels high; a row of them takes more than " +
                       std::to_string(kMaxBandFloats * 4 >> 20) + " MiB to read");
    band = std::max(1, band / spec.tile_height) * spec.tile_height;
  }
  std::vector<float> rows;
  for (int y0 = 0; y0 < spec.height; y0 += band) {
    const int y1 = std::min(spec.height, y0 + band);
    rows.resize(std::size_t(y1 - y0) * row_floats);
    const bool read = tiled ? in->read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1, spec.z,
                                             spec.z + 1, 0, layout.read_end, OIIO::TypeDesc::FLOAT, rows.data())
                            : in->read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, layout.read_end,
                                                 OIIO::TypeDesc::FLOAT, rows.data());
    if (!read) throw std::runtime_error(name + ": cannot read pixels (" + in->geterror() + ")");
    for (std::size_t i = 0; i < std::size_t(y1 - y0) * spec.width; ++i) {
      const float* p = &rows[i * layout.read_end];
      float* out = &d.rgba[(std::size_t(y0) * spec.width + i) * 4];
      for (int c = 0; c < 3; ++c) out[c] = p[layout.colour_channels == 3 ? c : 0];
      out[3] = layout.alpha >= 0 ? p[layout.alpha] : 1.0f;
    }
  }
  return d;
}

// `bytes` into the new file `file`, every write checked.
bool write_new_file(const std::string& file, const std::vector<unsigned char>& bytes, std::string& error) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return error = std::strerror(errno), false;
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = std::string("write failed: ") + std::strerror(n < 0 ? errno : ENOSPC);
      ::close(fd);
      return false;
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) return error = std::string("write failed: ") + std::strerror(errno), false;
  return true;
}

bool write(const std::string& format_name, const std::string& file, int width, int height, bool floats,
           const void* pixels, std::string& error) {
  auto out = OIIO::ImageOutput::create(format_name);
  if (!out) {
    // OIIO says why (a plugin that could not start its threads under a process limit reads as
    // "no format" otherwise).
    const std::string why = OIIO::geterror();
    return error = "OpenImageIO could not create its '" + format_name + "' writer" +
                   (why.empty() ? " and gave no reason (its plugin could not start: a process or memory limit?)"
                                : ": " + why),
           false;
  }
  OIIO::ImageSpec spec(width, height, 3, floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (!floats) spec.attribute("oiio:ColorSpace", "sRGB");
  // OIIO's PNG writer did not report a full disk: a truncated PNG was renamed into place. PNG,
  // EXR and JPEG are encoded in memory (byte for byte the same files) and written with checked
  // writes; other formats (TIFF's in-memory output is broken in OIIO 2.4) are read back.
  const std::string name = out->format_name();
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput proxy(encoded);
  const bool in_memory = (name == "png" || name == "openexr" || name == "jpeg") && out->supports("ioproxy") &&
                         out->set_ioproxy(&proxy);
  bool ok = out->open(file, spec) && out->write_image(spec.format, pixels);
  ok = out->close() && ok;
  if (!ok) return error = out->geterror(), false;
  if (in_memory) return write_new_file(file, encoded, error);
  auto in = OIIO::ImageInput::open(file);
  std::vector<float> back(std::size_t(width) * height * 3);
  if (!in || !in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()))
    return error = "the file written does not read back (a full disk?)", false;
  return true;
}

}  // namespace
}  // namespace rsaa

extern "C" const rsaa::OiioCodec* rsaa_oiio_codec() {
  static const rsaa::OiioCodec codec{rsaa::decode, rsaa::write};
  return &codec;
}
