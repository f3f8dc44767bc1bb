#include "runtime/gl_objects.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>

#include "runtime/gl_context.h"

namespace rsaa::gl {

void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
void delete_program(GLuint id) { glDeleteProgram(id); }
void delete_query(GLuint id) { glDeleteQueries(1, &id); }
void delete_sampler(GLuint id) { glDeleteSamplers(1, &id); }

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

void upload_texels_2d(GLuint texture, int width, int height, GLenum format, GLenum type, const void* data) {
  // The unpack parameters and their defaults (GL 4.5 table 8.1).
  const struct {
    GLenum name;
    GLint initial;
  } parameters[] = {{GL_UNPACK_SWAP_BYTES, GL_FALSE}, {GL_UNPACK_LSB_FIRST, GL_FALSE}, {GL_UNPACK_ROW_LENGTH, 0},
                    {GL_UNPACK_IMAGE_HEIGHT, 0},     {GL_UNPACK_SKIP_ROWS, 0},       {GL_UNPACK_SKIP_PIXELS, 0},
                    {GL_UNPACK_SKIP_IMAGES, 0},      {GL_UNPACK_ALIGNMENT, 4}};
  GLint saved[std::size(parameters)] = {}, unpack_buffer = 0;
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  for (std::size_t i = 0; i < std::size(parameters); ++i) {
    glGetIntegerv(parameters[i].name, &saved[i]);
    glPixelStorei(parameters[i].name, parameters[i].initial);
  }
  glTextureSubImage2D(texture, 0, 0, 0, width, height, format, type, data);
  for (std::size_t i = 0; i < std::size(parameters); ++i) glPixelStorei(parameters[i].name, saved[i]);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpack_buffer));
}

Sampler make_sampler(GLenum filter) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  check("make_sampler");
  return Sampler(id);
}

namespace {

// Attaches `colour` (in order) and `depth` to framebuffer `id`.
void attach_all(GLuint id, const std::vector<Attachment>& colour, Attachment depth) {
  const auto attach = [&](GLenum point, const Attachment& a) {
    if (a.layer >= 0)
      glNamedFramebufferTextureLayer(id, point, a.texture, 0, a.layer);
    else
      glNamedFramebufferTexture(id, point, a.texture, 0);
  };
  for (std::size_t i = 0; i < colour.size(); ++i) attach(GLenum(GL_COLOR_ATTACHMENT0 + i), colour[i]);
  if (depth.texture) {
    GLint stencil_bits = 0;  // a depth-stencil texture attaches both
    glGetTextureLevelParameteriv(depth.texture, 0, GL_TEXTURE_STENCIL_SIZE, &stencil_bits);
    attach(stencil_bits > 0 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth);
  }
}

void require_complete(GLuint id) {
  const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer incomplete (status " + std::to_string(status) + ")");
}

}  // namespace

Framebuffer make_framebuffer(const std::vector<Attachment>& colour, Attachment depth) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  Framebuffer fb(id);
  attach_all(id, colour, depth);
  std::vector<GLenum> buffers;
  for (std::size_t i = 0; i < colour.size(); ++i) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  glNamedFramebufferDrawBuffers(id, GLsizei(buffers.size()), buffers.data());
  require_complete(id);
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
    return framebuffer_.get();
  }
  // The same names, attached again: a texture deleted while this framebuffer was not bound stays
  // attached to it, and a driver that reuses names (most do; Mesa with force_gl_names_reuse) gives
  // its name to the next texture made, which this framebuffer would then never reach (the pass
  // wrote into the deleted texture and left the engine's new output untouched). Attaching the
  // object already attached changes nothing.
  attach_all(framebuffer_.get(), colour, depth);
  require_complete(framebuffer_.get());
  return framebuffer_.get();
}

namespace {

const char* stage_name(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_COMPUTE_SHADER: return "compute";
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

namespace rsaa::gl {

namespace {

// What decides which samples a fragment writes and how a written value combines (an engine may
// turn them on for its own draws; the multisample pre-pass's codes and any integer code depend on
// them): set_pass_state() turns GL_MULTISAMPLE on and the others off, SavedState restores them.
constexpr GLenum kSampleCaps[] = {GL_MULTISAMPLE, GL_SAMPLE_MASK, GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE,
                                  GL_SAMPLE_ALPHA_TO_ONE, GL_COLOR_LOGIC_OP};

// Every texture target a unit has, with its binding query: SavedState puts back all of them, so
// that nothing a pass binds on a unit (glBindTextures with a zero name unbinds every target)
// takes an engine's cube map or 3D texture there.
struct TextureTargetBinding {
  GLenum target, binding;
};
constexpr TextureTargetBinding kTextureTargetBindings[] = {
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY}};
static_assert(std::size(kTextureTargetBindings) == SavedState::kTextureTargets, "one binding saved per target");

}  // namespace

IndexedBufferBinding save_indexed_buffer(GLenum target, int binding) {
  const bool uniform = target == GL_UNIFORM_BUFFER;
  IndexedBufferBinding b{target, binding, 0, 0, 0};
  glGetIntegeri_v(uniform ? GL_UNIFORM_BUFFER_BINDING : GL_SHADER_STORAGE_BUFFER_BINDING, GLuint(binding), &b.buffer);
  glGetInteger64i_v(uniform ? GL_UNIFORM_BUFFER_START : GL_SHADER_STORAGE_BUFFER_START, GLuint(binding), &b.start);
  glGetInteger64i_v(uniform ? GL_UNIFORM_BUFFER_SIZE : GL_SHADER_STORAGE_BUFFER_SIZE, GLuint(binding), &b.size);
  return b;
}

void restore_indexed_buffer(const IndexedBufferBinding& b) {
  // A range of size 0 was bound whole (glBindBufferBase) or not at all.
  if (b.buffer != 0 && b.size > 0)
    glBindBufferRange(b.target, GLuint(b.binding), GLuint(b.buffer), GLintptr(b.start), GLsizeiptr(b.size));
  else
    glBindBufferBase(b.target, GLuint(b.binding), GLuint(b.buffer));
}

SavedState::SavedState(std::vector<int> texture_units, std::vector<int> uniform_bindings) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  GLint viewports = 1;
  glGetIntegerv(GL_MAX_VIEWPORTS, &viewports);
  viewports_.resize(4 * std::size_t(viewports));
  depth_ranges_.resize(2 * std::size_t(viewports));
  for (GLuint i = 0; i < GLuint(viewports); ++i) {
    glGetFloati_v(GL_VIEWPORT, i, &viewports_[4 * i]);
    glGetDoublei_v(GL_DEPTH_RANGE, i, &depth_ranges_[2 * i]);
    scissor_tests_.push_back(glIsEnabledi(GL_SCISSOR_TEST, i));
  }
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  // A program deleted while current lives only until another is made current: the pass's draws
  // end it, so there is nothing to restore (glUseProgram would fail with GL_INVALID_VALUE).
  GLint deleted = GL_FALSE;
  if (program_) glGetProgramiv(GLuint(program_), GL_DELETE_STATUS, &deleted);
  if (deleted) program_ = 0;
  depth_test_ = glIsEnabled(GL_DEPTH_TEST);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func_);
  polygon_offset_fill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
  framebuffer_srgb_ = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  stencil_test_ = glIsEnabled(GL_STENCIL_TEST);
  const GLenum stencil_queries[2][7] = {
      {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
       GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK},
      {GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL,
       GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS, GL_STENCIL_BACK_WRITEMASK}};
  for (int face = 0; face < 2; ++face)
    for (int i = 0; i < 7; ++i) glGetIntegerv(stencil_queries[face][i], &stencil_[face][i]);
  sample_shading_ = glIsEnabled(GL_SAMPLE_SHADING);
  cull_face_ = glIsEnabled(GL_CULL_FACE);
  rasterizer_discard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
  static_assert(std::size(kSampleCaps) == sizeof(sample_caps_) / sizeof(sample_caps_[0]), "one flag per capability");
  for (std::size_t i = 0; i < std::size(kSampleCaps); ++i) sample_caps_[i] = glIsEnabled(kSampleCaps[i]);
  glGetIntegerv(GL_POLYGON_MODE, polygon_mode_);
  GLint draw_buffers = 1;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &draw_buffers);
  for (GLuint i = 0; i < GLuint(draw_buffers); ++i) {
    DrawBufferState d{};
    d.blend = glIsEnabledi(GL_BLEND, i);
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, d.colour_mask);
    draw_buffers_.push_back(d);
  }
  glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &min_sample_shading_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
  for (int unit : texture_units) {
    UnitTextures t{unit, {}, 0};
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glGetIntegerv(GL_SAMPLER_BINDING, &t.sampler);
    for (int k = 0; k < kTextureTargets; ++k) glGetIntegerv(kTextureTargetBindings[k].binding, &t.textures[k]);
    textures_.push_back(t);
  }
  glActiveTexture(GLenum(active_texture_));
  for (int binding : uniform_bindings) uniform_buffers_.push_back(save_indexed_buffer(GL_UNIFORM_BUFFER, binding));
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &generic_uniform_buffer_);
}

SavedState::~SavedState() {
  for (const UnitTextures& t : textures_) {
    glActiveTexture(GLenum(GL_TEXTURE0 + t.unit));
    for (int k = 0; k < kTextureTargets; ++k) glBindTexture(kTextureTargetBindings[k].target, GLuint(t.textures[k]));
    glBindSampler(GLuint(t.unit), GLuint(t.sampler));
  }
  glActiveTexture(GLenum(active_texture_));
  for (const IndexedBufferBinding& u : uniform_buffers_) restore_indexed_buffer(u);
  // After the indexed ones, which set it too: an engine's glBufferSubData(GL_UNIFORM_BUFFER, ...)
  // would otherwise write into the buffer at the pass's binding (or fail with none there).
  glBindBuffer(GL_UNIFORM_BUFFER, GLuint(generic_uniform_buffer_));
  glBindVertexArray(GLuint(vertex_array_));
  for (GLuint i = 0; i < GLuint(draw_buffers_.size()); ++i) {
    const DrawBufferState& d = draw_buffers_[i];
    d.blend ? glEnablei(GL_BLEND, i) : glDisablei(GL_BLEND, i);
    glColorMaski(i, d.colour_mask[0], d.colour_mask[1], d.colour_mask[2], d.colour_mask[3]);
  }
  cull_face_ ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
  rasterizer_discard_ ? glEnable(GL_RASTERIZER_DISCARD) : glDisable(GL_RASTERIZER_DISCARD);
  for (std::size_t i = 0; i < std::size(kSampleCaps); ++i)
    sample_caps_[i] ? glEnable(kSampleCaps[i]) : glDisable(kSampleCaps[i]);
  // A core context sets both faces alike (and accepts GL_FRONT_AND_BACK only); a compatibility one
  // may have them differ.
  if (polygon_mode_[0] == polygon_mode_[1]) {
    glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygon_mode_[0]));
  } else {
    glPolygonMode(GL_FRONT, GLenum(polygon_mode_[0]));
    glPolygonMode(GL_BACK, GLenum(polygon_mode_[1]));
  }
  for (GLuint i = 0; i < GLuint(scissor_tests_.size()); ++i)
    scissor_tests_[i] ? glEnablei(GL_SCISSOR_TEST, i) : glDisablei(GL_SCISSOR_TEST, i);
  sample_shading_ ? glEnable(GL_SAMPLE_SHADING) : glDisable(GL_SAMPLE_SHADING);
  glMinSampleShading(min_sample_shading_);
  glDepthFunc(GLenum(depth_func_));
  glDepthMask(depth_mask_);
  glDepthRangeArrayv(0, GLsizei(depth_ranges_.size() / 2), depth_ranges_.data());
  polygon_offset_fill_ ? glEnable(GL_POLYGON_OFFSET_FILL) : glDisable(GL_POLYGON_OFFSET_FILL);
  framebuffer_srgb_ ? glEnable(GL_FRAMEBUFFER_SRGB) : glDisable(GL_FRAMEBUFFER_SRGB);
  depth_test_ ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
  for (int face = 0; face < 2; ++face) {
    const GLenum side = face == 0 ? GL_FRONT : GL_BACK;
    const GLint* f = stencil_[face];
    glStencilFuncSeparate(side, GLenum(f[0]), f[1], GLuint(f[2]));
    glStencilOpSeparate(side, GLenum(f[3]), GLenum(f[4]), GLenum(f[5]));
    glStencilMaskSeparate(side, GLuint(f[6]));
  }
  stencil_test_ ? glEnable(GL_STENCIL_TEST) : glDisable(GL_STENCIL_TEST);
  glUseProgram(GLuint(program_));
  glViewportArrayv(0, GLsizei(viewports_.size() / 4), viewports_.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_framebuffer_));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_framebuffer_));
}

SavedComputeState::SavedComputeState(std::vector<int> storage_bindings, std::vector<int> image_units) {
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &generic_storage_buffer_);
  glGetIntegerv(GL_DISPATCH_INDIRECT_BUFFER_BINDING, &dispatch_indirect_buffer_);
  for (int binding : storage_bindings) storage_buffers_.push_back(save_indexed_buffer(GL_SHADER_STORAGE_BUFFER, binding));
  for (int unit : image_units) {
    ImageUnit i{unit, 0, 0, 0, GL_READ_ONLY, GL_R8, GL_FALSE};
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, GLuint(unit), &i.texture);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, GLuint(unit), &i.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, GLuint(unit), &i.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, GLuint(unit), &i.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, GLuint(unit), &i.format);
    glGetBooleani_v(GL_IMAGE_BINDING_LAYERED, GLuint(unit), &i.layered);
    images_.push_back(i);
  }
}

SavedComputeState::~SavedComputeState() {
  for (const IndexedBufferBinding& b : storage_buffers_) restore_indexed_buffer(b);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(generic_storage_buffer_));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, GLuint(dispatch_indirect_buffer_));
  for (const ImageUnit& i : images_)
    glBindImageTexture(GLuint(i.unit), GLuint(i.texture), i.level, i.layered, i.layer, GLenum(i.access),
                       GLenum(i.format));
}

void set_pass_state(bool depth_test) {
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_RASTERIZER_DISCARD);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDepthRange(0.0, 1.0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_STENCIL_TEST);
  glStencilMask(0xFFFFFFFFu);
  for (GLenum cap : kSampleCaps) cap == GL_MULTISAMPLE ? glEnable(cap) : glDisable(cap);
  depth_test ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
}

namespace {

std::string format_name(GLenum format) {
  switch (format) {
    case GL_RGBA16F: return "GL_RGBA16F";
    case GL_RG16UI: return "GL_RG16UI";
    case GL_R32UI: return "GL_R32UI";
    case GL_RG32UI: return "GL_RG32UI";
    case GL_DEPTH_COMPONENT32F: return "GL_DEPTH_COMPONENT32F";
    case GL_DEPTH_COMPONENT24: return "GL_DEPTH_COMPONENT24";
    case GL_DEPTH_COMPONENT16: return "GL_DEPTH_COMPONENT16";
    case GL_DEPTH24_STENCIL8: return "GL_DEPTH24_STENCIL8";
    case GL_DEPTH32F_STENCIL8: return "GL_DEPTH32F_STENCIL8";
    case GL_RGBA8: return "GL_RGBA8";
    case GL_SRGB8_ALPHA8: return "GL_SRGB8_ALPHA8";
    case GL_RGBA32F: return "GL_RGBA32F";
    case GL_R11F_G11F_B10F: return "GL_R11F_G11F_B10F";
    case GL_RGB10_A2: return "GL_RGB10_A2";
    case GL_RG16F: return "GL_RG16F";
    case GL_R32F: return "GL_R32F";
  }
  char hex[24];
  std::snprintf(hex, sizeof hex, "format 0x%04X", unsigned(format));
  return hex;
}

}  // namespace

GLenum internal_format_of(GLuint texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return GLenum(format);
}

void require_texture(GLuint texture, GLenum internal_format, int width, int height,
                     const std::string& what) {
  require_texture(texture, std::vector<GLenum>{internal_format}, width, height, what);
}

void require_texture(GLuint texture, const std::vector<GLenum>& internal_formats, int width, int height,
                     const std::string& what) {
  std::string formats;
  for (std::size_t k = 0; k < internal_formats.size(); ++k)
    formats += (k == 0 ? "" : k + 1 == internal_formats.size() ? " or " : ", ") + format_name(internal_formats[k]);
  const std::string needs = ", needs a " + std::to_string(width) + "x" + std::to_string(height) + " " + formats +
                            " 2D texture";
  if (texture == 0 || !glIsTexture(texture))
    throw std::invalid_argument(what + ": " + std::to_string(texture) + " is not a texture" + needs);
  GLint target = 0, w = 0, h = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
  const GLenum format = internal_format_of(texture);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
  const bool known = std::find(internal_formats.begin(), internal_formats.end(), format) != internal_formats.end();
  if (target != GL_TEXTURE_2D || !known || w != width || h != height)
    throw std::invalid_argument(what + ": texture " + std::to_string(texture) + " is a " +
                                std::to_string(w) + "x" + std::to_string(h) + " " +
                                format_name(format) +
                                (target == GL_TEXTURE_2D ? "" : " non-2D") + " texture" + needs);
  if (format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8) {
    GLint mode = GL_DEPTH_COMPONENT;
    glGetTextureParameteriv(texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
    if (mode != GL_DEPTH_COMPONENT)
      throw std::invalid_argument(what + ": texture " + std::to_string(texture) +
                                  " reads as stencil (GL_DEPTH_STENCIL_TEXTURE_MODE); the pass reads its depth");
  }
  // Passes read (texelFetch, level 0 = the base level) and write (images, framebuffers) level 0.
  GLint base_level = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_BASE_LEVEL, &base_level);
  if (base_level != 0)
    throw std::invalid_argument(what + ": texture " + std::to_string(texture) + " has GL_TEXTURE_BASE_LEVEL " +
                                std::to_string(base_level) + "; the pass reads and writes level 0, so it needs 0");
  // Texture reads apply a swizzle and image loads, blits and copies do not: a swizzled texture
  // would be read two ways within one pass.
  GLint swizzle[4] = {};
  glGetTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  const GLint identity[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
  for (int c = 0; c < 4; ++c)
    if (swizzle[c] != identity[c])
      throw std::invalid_argument(what + ": texture " + std::to_string(texture) + " has a GL_TEXTURE_SWIZZLE_" +
                                  "RGBA"[c] + " other than its own channel; the pass needs the identity swizzle");
}

}  // namespace rsaa::gl
