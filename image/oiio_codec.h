// The interface between rsaa_image and the OpenImageIO module (librsaa_oiio.so), which image_io
// loads with dlopen on the first image read or written. OpenImageIO pulls in OpenVDB and its
// logger, log4cplus, whose static initialiser starts threads and aborts the process when it
// cannot (under a small process limit, ulimit -u): linked into rsaa, that happened before main
// for every subcommand. Loaded only where images are used, the rest of rsaa runs under any limit
// and image commands fail with a message instead (image_io.cpp checks first).
#pragma once

#include <string>

#include "image/image_io.h"

namespace rsaa {

struct OiioCodec {
  // decode_image's work (image_io.h): throws std::runtime_error / LimitError naming `name`.
  DecodedImage (*decode)(const std::string& name, const std::string& bytes, const ImageBudget& budget);
  // Writes `width` x `height` RGB pixels into `file`, in the format of `format_name`'s extension:
  // float linear values when `floats`, else 8-bit sRGB. False with `error` set when it fails.
  bool (*write)(const std::string& format_name, const std::string& file, int width, int height, bool floats,
                const void* pixels, std::string& error);
};

}  // namespace rsaa

// The module's one entry point (C linkage: looked up by name with dlsym).
extern "C" const rsaa::OiioCodec* rsaa_oiio_codec();
