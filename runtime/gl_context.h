// The GL context layer: a headless context through EGL (surfaceless Mesa, no X server) for
// tests, benchmarks and `rsaa render`. Everything else in runtime/ only needs a current GL 4.5
// core context, whoever made it (the GLFW viewer makes its own).
#pragma once

#include <stdexcept>
#include <string>

namespace rsaa::gl {

class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws GlError naming `where` if the GL error flag is set (and drains it).
void check(const char* where);
// At the start of a call into the library: throws GlError if the GL error flag is already set
// (and drains it), naming `call` and saying the error came from an earlier GL call of the
// caller's. Without it a library call reported the engine's stray error as its own, from
// wherever it next checked, after changing part of what it was to do. Throws GlError too when no
// context is current.
void check_none_pending(const char* call);

// Throws GlError (naming `call` when given) when the current context is older than 4.5.
void require_gl45(const char* call = nullptr);

class HeadlessContext {
 public:
  HeadlessContext();  // throws GlError with the EGL error when no context can be made
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace rsaa::gl
