#include "image/image_io.h"

#include <dlfcn.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "core/util/atomic_file.h"
#include "core/util/colour.h"
#include "core/util/parallel.h"
#include "image/oiio_codec.h"

namespace rsaa {
namespace {

bool is_float_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext == ".exr" || ext == ".hdr";
}

// log4cplus (loaded with OpenImageIO through OpenVDB) starts this many threads as it loads and
// ends the process when it cannot (measured: 4 in liblog4cplus 2.0.8).
constexpr int kThreadsStartedByTheModule = 4;

std::string process_limit_text() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NPROC, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return "";
  return " (ulimit -u " + std::to_string(limit.rlim_cur) + ")";
}

std::string address_space_limit_text() {
  const std::uint64_t limit = address_space_limit();
  return limit ? " (ulimit -v " + std::to_string(limit >> 10) + ")" : "";
}

// What the process prints if it is ended while the module loads (the terminate handler below):
// written before the load, since the handler must not allocate.
char g_load_failure[1024];
std::size_t g_load_failure_length = 0;

void write_stderr(const char* text, std::size_t length) {
  while (length > 0) {
    const ssize_t n = ::write(2, text, length);
    if (n <= 0) return;
    text += n, length -= std::size_t(n);
  }
}

[[noreturn]] void on_terminate_while_loading() {
  write_stderr(g_load_failure, g_load_failure_length);
  if (const std::exception_ptr active = std::current_exception()) {
    try {
      std::rethrow_exception(active);
    } catch (const std::exception& e) {
      write_stderr(" (", 2), write_stderr(e.what(), std::strlen(e.what())), write_stderr(")", 1);
    } catch (...) {
    }
  }
  write_stderr("\n", 1);
  ::_exit(1);
}

// dlopen with a terminate handler in place: the check of load_codec leaves a race (another
// process of this user can start between it and the load), and log4cplus then calls
// std::terminate from its static initialiser. The process still ends (nothing can be done
// inside a static initialiser), but with a message naming what failed and why, and status 1.
void* load_module_ending_clearly(const char* path) {
  const std::string message =
      "rsaa: error: the process ended while loading the image module (" + std::string(path) +
      "): OpenImageIO's logger (log4cplus, loaded with OpenVDB) could not start the " +
      std::to_string(kThreadsStartedByTheModule) +
      " threads it starts as it loads, and a thread it cannot start ends the process; the process limit" +
      process_limit_text() + " or the address-space limit" + address_space_limit_text() +
      " was reached after rsaa checked there was room (another process of this user may have started); raise "
      "the limit or end other processes of this user";
  g_load_failure_length = std::min(message.size(), sizeof g_load_failure);
  std::memcpy(g_load_failure, message.data(), g_load_failure_length);
  const std::terminate_handler previous = std::set_terminate(on_terminate_while_loading);
  void* module = ::dlopen(path, RTLD_NOW | RTLD_LOCAL);
  std::set_terminate(previous);
  return module;
}

const OiioCodec& load_codec() {
  if (threads_that_can_start(kThreadsStartedByTheModule) < kThreadsStartedByTheModule)
    throw std::runtime_error(
        "images cannot be read or written here: OpenImageIO's logger (log4cplus, loaded with "
        "OpenVDB) starts " + std::to_string(kThreadsStartedByTheModule) +
        " threads when it loads and ends the process when it cannot, and they cannot start here: the process limit" +
        process_limit_text() + " or the address-space limit" + address_space_limit_text() +
        " leaves no room for them (a thread's stack needs address space too); raise the limits (ulimit -u, "
        "ulimit -v) or end other processes of this user");
  // The installed module relative to this executable first (an install under another prefix,
  // or moved, carries its own), then the build's, then the configured install prefix's.
  std::vector<std::string> paths;
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((executable.parent_path() / RSAA_OIIO_MODULE_FROM_BINDIR).lexically_normal().string());
  paths.insert(paths.end(), {RSAA_OIIO_MODULE, RSAA_OIIO_MODULE_INSTALLED});
  std::string tried;
  for (const std::string& name : paths) {
    const char* path = name.c_str();
    void* module = load_module_ending_clearly(path);
    if (!module) {
      tried += std::string(" ") + ::dlerror() + ";";
      continue;
    }
    using Entry = const OiioCodec* (*)();
    if (const auto entry = reinterpret_cast<Entry>(::dlsym(module, "rsaa_oiio_codec"))) return *entry();
    tried += std::string(" ") + path + ": no rsaa_oiio_codec;";
  }
  // Under an address-space limit the loader fails to map the module's libraries ("failed to map
  // segment from shared object"): say which limit.
  const std::string limit = address_space_limit_text();
  throw std::runtime_error("cannot load the image module (OpenImageIO):" + tried +
                           (limit.empty() ? "" : " the address-space limit" + limit +
                                                     " may be too small for it; raise it (ulimit -v unlimited)"));
}

// Loaded once, on first use; a failure is reported again on every use.
const OiioCodec& codec() {
  static std::string failure;
  static const OiioCodec* const loaded = [] () -> const OiioCodec* {
    try {
      return &load_codec();
    } catch (const std::runtime_error& e) {
      failure = e.what();
      return nullptr;
    }
  }();
  if (!loaded) throw std::runtime_error(failure);
  return *loaded;
}

}  // namespace

void require_image_module() { codec(); }

DecodedImage decode_image(const std::string& name, const std::string& bytes, const ImageBudget& budget) {
  return codec().decode(name, bytes, budget);
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
  check_replaceable(path);  // as every other output: a device or a link is not replaced by the rename
  const bool linear = is_float_format(path);
  const std::filesystem::path target(path);
  // Keep the extension so that OpenImageIO picks the same format for the temporary file.
  const std::filesystem::path temporary = temporary_path_beside(path);
  remove_stale_temporaries(target.parent_path().empty() ? "." : target.parent_path().string());
  const std::size_t n = image.pixels.size();
  std::vector<float> values;
  DisplayImage display;
  if (linear) {
    values.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i) {
      const Rgb p = image.pixels[i];
      values[3 * i + 0] = std::isfinite(p.r) ? p.r : 0.0f;
      values[3 * i + 1] = std::isfinite(p.g) ? p.g : 0.0f;
      values[3 * i + 2] = std::isfinite(p.b) ? p.b : 0.0f;
    }
  } else {
    display = to_display(image);
  }
  std::string error;
  if (!codec().write(path, temporary.string(), image.width, image.height, linear,
                     linear ? static_cast<const void*>(values.data()) : display.rgb.data(), error)) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(path + ": cannot write image (" + error + ")");
  }
  std::error_code rename_error;
  std::filesystem::rename(temporary, target, rename_error);
  if (rename_error) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(path + ": cannot write image (" + rename_error.message() + ")");
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
