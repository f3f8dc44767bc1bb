#include "runtime/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <string>

#include "core/util/parallel.h"

namespace rsaa::gl {
namespace {

std::string hex(unsigned v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%04x", v);
  return b;
}

}  // namespace

void check(const char* where) {
  GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  throw GlError(std::string("GL error ") + hex(first) + " in " + where);
}

void check_none_pending(const char* call) {
  // Without a current context every GL call does nothing and reads zeros: the library would
  // report a 0x0 size limit or "not a texture" instead of the cause.
  if (glGetString(GL_VERSION) == nullptr)
    throw GlError(std::string(call) + ": no OpenGL context is current on this thread (make the engine's GL 4.5 "
                  "context current first)");
  GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  throw GlError(std::string("GL error ") + hex(first) + " was already set when " + call +
                " was called: an earlier GL call of the caller's failed (" + call + " did nothing)");
}

void require_gl45(const char* call) {
  const int version = epoxy_gl_version();
  if (version < 45)
    throw GlError((call ? std::string(call) + ": " : std::string()) + "OpenGL 4.5 is required; the context offers " +
                  std::to_string(version / 10) + "." + std::to_string(version % 10));
}

// Threads kept free for what starts after the context: OpenImageIO's logger (4, image_io.cpp)
// and one loader or worker thread.
constexpr int kThreadsKeptFree = 5;

HeadlessContext::HeadlessContext() {
  // Mesa llvmpipe reserves several hundred MiB of address space as a context starts (its
  // threads, LLVM): under ulimit -v 300-500 MB it crashed inside the driver (SIGSEGV), below that
  // EGL failed without saying why. Refused up front, naming the limit.
  constexpr std::uint64_t kLeastAddressSpace = std::uint64_t{1} << 30;
  if (const std::uint64_t limit = address_space_limit(); limit != 0 && limit < kLeastAddressSpace)
    throw GlError("the address-space limit (ulimit -v " + std::to_string(limit >> 10) + ") is below the " +
                  std::to_string(kLeastAddressSpace >> 20) +
                  " MiB rsaa requires for an OpenGL context (Mesa llvmpipe crashed under less); raise it "
                  "(ulimit -v unlimited)");
  fit_llvmpipe_threads_to_process_limit(kThreadsKeptFree);
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    throw GlError("EGL lacks EGL_MESA_platform_surfaceless (install libegl-mesa0)");
  EGLDisplay display =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
    throw GlError("cannot initialise the surfaceless EGL display (EGL error " +
                  hex(eglGetError()) + ")");
  if (!eglBindAPI(EGL_OPENGL_API)) throw GlError("EGL cannot bind the OpenGL API");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) {
    const EGLint error = eglGetError();
    eglTerminate(display);
    throw GlError("cannot create an OpenGL 4.5 core context (EGL error " + hex(error) + ")");
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    eglTerminate(display);
    throw GlError("cannot make the EGL context current");
  }
  display_ = display;
  context_ = context;
  require_gl45();
}

HeadlessContext::~HeadlessContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string HeadlessContext::renderer() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

}  // namespace rsaa::gl
