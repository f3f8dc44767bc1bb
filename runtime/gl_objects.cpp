#include "runtime/gl_objects.h"

#include "runtime/gl_context.h"

namespace rsaa::gl {

void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
void delete_program(GLuint id) { glDeleteProgram(id); }
void delete_query(GLuint id) { glDeleteQueries(1, &id); }

Texture make_texture_2d(GLenum internal_format, int width, int height, GLenum filter) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, internal_format, width, height);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, filter);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, filter);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check("make_texture_2d");
  return Texture(id);
}

Texture make_texture_2d_array(GLenum internal_format, int width, int height, int layers) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  glTextureStorage3D(id, 1, internal_format, width, height, layers);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  check("make_texture_2d_array");
  return Texture(id);
}

Texture make_texture_2d_multisample(GLenum internal_format, int width, int height, int samples) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
  glTextureStorage2DMultisample(id, samples, internal_format, width, height, GL_TRUE);
  check("make_texture_2d_multisample");
  return Texture(id);
}

Framebuffer make_framebuffer(const std::vector<Attachment>& colour, Attachment depth) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  Framebuffer fb(id);
  std::vector<GLenum> buffers;
  const auto attach = [&](GLenum point, const Attachment& a) {
    if (a.layer >= 0)
      glNamedFramebufferTextureLayer(id, point, a.texture, 0, a.layer);
    else
      glNamedFramebufferTexture(id, point, a.texture, 0);
  };
  for (std::size_t i = 0; i < colour.size(); ++i) {
    attach(GLenum(GL_COLOR_ATTACHMENT0 + i), colour[i]);
    buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  if (depth.texture) attach(GL_DEPTH_ATTACHMENT, depth);
  glNamedFramebufferDrawBuffers(id, GLsizei(buffers.size()), buffers.data());
  const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer incomplete (status " + std::to_string(status) + ")");
  check("make_framebuffer");
  return fb;
}

GLuint CachedFramebuffer::get(const std::vector<Attachment>& colour, Attachment depth) {
  std::vector<GLuint> key;
  for (const Attachment& a : colour) key.insert(key.end(), {a.texture, GLuint(a.layer)});
  key.insert(key.end(), {depth.texture, GLuint(depth.layer)});
  if (key != key_ || !framebuffer_.get()) {
    framebuffer_ = make_framebuffer(colour, depth);
    key_ = key;
  }
  return framebuffer_.get();
}

namespace {

const char* stage_name(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_FRAGMENT_SHADER: return "fragment";
    default: return "shader";
  }
}

}  // namespace

Program make_program(const std::vector<ShaderStage>& stages, const std::string& defines,
                     const std::string& label) {
  Program program(glCreateProgram());
  std::vector<GLuint> shaders;
  for (const ShaderStage& s : stages) {
    const GLuint shader = glCreateShader(s.stage);
    const std::string text = "#version 450 core\n" + defines + "#line 1\n" + s.source;
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint length = 0;
      glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
      std::string log(std::size_t(std::max(length, 1)), '\0');
      glGetShaderInfoLog(shader, length, nullptr, log.data());
      glDeleteShader(shader);
      for (GLuint sh : shaders) glDeleteShader(sh);
      throw GlError(label + ": " + stage_name(s.stage) + " shader does not compile:\n" + log);
    }
    glAttachShader(program.get(), shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program.get());
  for (GLuint sh : shaders) glDeleteShader(sh);
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.get(), length, nullptr, log.data());
    throw GlError(label + ": program does not link:\n" + log);
  }
  check(label.c_str());
  return program;
}

}  // namespace rsaa::gl
