// What the example "engines" own themselves, independent of rsaa: a headless OpenGL 4.5 core
// context made with plain EGL, GL from the Khronos headers with prototypes resolved by the
// system's libOpenGL (no epoxy, no rsaa GL wrapper), a shader-program helper and a PPM writer.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace engine {

// A surfaceless Mesa EGL display and a 4.5 core context, current on this thread.
class HeadlessGl {
 public:
  HeadlessGl() {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw std::runtime_error("EGL has no eglGetPlatformDisplayEXT");
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr))
      throw std::runtime_error("cannot initialise a surfaceless EGL display");
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT ||
        !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("cannot make an OpenGL 4.5 core context current");
  }
  ~HeadlessGl() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

inline std::string read_text_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Compiles each stage (its source follows "#version 450 core") and links. Throws with the log.
inline GLuint make_program(const std::vector<std::pair<GLenum, std::string>>& stages) {
  const GLuint program = glCreateProgram();
  char log[4096] = "";
  for (const auto& [stage, source] : stages) {
    const GLuint shader = glCreateShader(stage);
    const std::string text = "#version 450 core\n" + source;
    const char* pointer = text.c_str();
    glShaderSource(shader, 1, &pointer, nullptr);
    glCompileShader(shader);
    GLint compiled = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    if (!compiled) throw std::runtime_error(std::string("shader compile error: ") + log);
    glAttachShader(program, shader);
    glDeleteShader(shader);
  }
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  glGetProgramInfoLog(program, sizeof log, nullptr, log);
  if (!linked) throw std::runtime_error(std::string("program link error: ") + log);
  return program;
}

// A vertex array reading float attributes: {location, buffer binding, components, first float}.
struct FloatAttribute {
  GLuint location, binding;
  GLint components;
  GLuint first_float;
};
inline GLuint make_vertex_array(const std::vector<FloatAttribute>& attributes) {
  GLuint vao;
  glCreateVertexArrays(1, &vao);
  for (const FloatAttribute& a : attributes) {
    glEnableVertexArrayAttrib(vao, a.location);
    glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE,
                              a.first_float * GLuint(sizeof(float)));
    glVertexArrayAttribBinding(vao, a.location, a.binding);
  }
  return vao;
}

inline GLuint make_texture(GLenum format, int width, int height, GLenum filter = GL_NEAREST) {
  GLuint texture;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

// A linear RGBA float texture written as an 8-bit sRGB binary PPM, top row first.
inline void write_ppm(const std::string& path, GLuint texture, int width, int height) {
  std::vector<float> rgba(std::size_t(width) * height * 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "P6\n" << width << " " << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y)  // GL rows are bottom-up
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = std::fmin(std::fmax(rgba[(std::size_t(y) * width + x) * 4 + c], 0.0f), 1.0f);
        const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
        out.put(char(int(s * 255.0f + 0.5f)));
      }
  if (!out) throw std::runtime_error("cannot write " + path);
}

inline void check_gl(const char* where) {
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char text[96];
    std::snprintf(text, sizeof text, "GL error 0x%04X in %s", unsigned(error), where);
    throw std::runtime_error(text);
  }
}

}  // namespace engine
