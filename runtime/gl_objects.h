// Owning handles for GL objects and a shader program builder. Move-only.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <utility>
#include <vector>

namespace rsaa::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  GLuint get() const { return id_; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

void delete_texture(GLuint id);
void delete_framebuffer(GLuint id);
void delete_buffer(GLuint id);
void delete_vertex_array(GLuint id);
void delete_program(GLuint id);
void delete_query(GLuint id);
void delete_sampler(GLuint id);

using Texture = Handle<delete_texture>;
using Framebuffer = Handle<delete_framebuffer>;
using Buffer = Handle<delete_buffer>;
using VertexArray = Handle<delete_vertex_array>;
using Program = Handle<delete_program>;
using Query = Handle<delete_query>;
using Sampler = Handle<delete_sampler>;

// An immutable 2D (or 2D-array when layers > 0, or multisample when samples > 0) texture.
Texture make_texture_2d(GLenum internal_format, int width, int height, GLenum filter = GL_NEAREST);
Texture make_texture_2d_array(GLenum internal_format, int width, int height, int layers);
Texture make_texture_2d_multisample(GLenum internal_format, int width, int height, int samples);
// Uploads width x height texels of `data` (client memory, tightly packed) into level 0 of
// `texture`, whatever pixel unpack state the caller left (a bound GL_PIXEL_UNPACK_BUFFER would
// turn the pointer into an offset, GL_UNPACK_ROW_LENGTH or SKIP_* would read elsewhere); that
// state is as it was after.
void upload_texels_2d(GLuint texture, int width, int height, GLenum format, GLenum type, const void* data);
// A sampler object with `filter` for minification and magnification (no mipmaps), clamped to
// the edge, no depth comparison: read through it, a texture's own sampling parameters (and its
// completeness under them) do not matter.
Sampler make_sampler(GLenum filter);

// A framebuffer with the given colour attachments (in order) and an optional depth attachment;
// throws GlError if incomplete. layer >= 0 attaches that layer of an array texture.
struct Attachment {
  GLuint texture = 0;
  int layer = -1;
};
Framebuffer make_framebuffer(const std::vector<Attachment>& colour, Attachment depth = {});

// A framebuffer for caller-provided output textures, made again only when their names change: a
// new framebuffer every frame costs llvmpipe more than the frame itself (it re-specialises
// shaders). The textures are attached again at every get() (a deleted texture's name may come
// back as another texture).
class CachedFramebuffer {
 public:
  GLuint get(const std::vector<Attachment>& colour, Attachment depth = {});

 private:
  std::vector<GLuint> key_;
  Framebuffer framebuffer_;
};

// Compiles and links; `sources` per stage are concatenated after "#version 450 core" and the
// defines. Throws GlError with the info log and the stage name.
struct ShaderStage {
  GLenum stage;
  std::string source;
};
Program make_program(const std::vector<ShaderStage>& stages, const std::string& defines,
                     const std::string& label);

}  // namespace rsaa::gl

namespace rsaa::gl {

// A buffer bound at an indexed binding point (GL_UNIFORM_BUFFER or GL_SHADER_STORAGE_BUFFER), as
// SavedState and SavedComputeState keep it: saved by save_indexed_buffer(), put back by
// restore_indexed_buffer().
struct IndexedBufferBinding {
  GLenum target;
  int binding;
  GLint buffer;
  GLint64 start, size;
};
IndexedBufferBinding save_indexed_buffer(GLenum target, int binding);
void restore_indexed_buffer(const IndexedBufferBinding& b);

// Saves on construction and restores on destruction the GL state a pass changes: framebuffer
// bindings, viewports, current program, depth test/function/mask/ranges, polygon offset, blending and colour mask of
// every draw buffer, scissor tests (every viewport index's), face culling, polygon mode, sRGB writes, rasterizer discard, sample
// shading, the vertex array, textures and sampler objects, uniform buffers (below, and the generic
// GL_UNIFORM_BUFFER binding, which binding an indexed one also sets). So that a pass dropped into
// an engine leaves the engine's state as it found it.
class SavedState {
 public:
  // Also saves the textures bound to `texture_units` (every target: glBindTextures with a zero
  // name unbinds them all) and the uniform buffers bound at `uniform_bindings`.
  SavedState(std::vector<int> texture_units, std::vector<int> uniform_bindings = {});
  ~SavedState();
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;
  static constexpr int kTextureTargets = 11;  // every texture target of GL 4.5

 private:
  struct UnitTextures {
    int unit;
    GLint textures[kTextureTargets];  // in the order of kTextureTargetBindings in gl_objects.cpp
    GLint sampler;
  };
  struct DrawBufferState {
    GLboolean blend;
    GLboolean colour_mask[4];
  };
  GLint draw_framebuffer_ = 0, read_framebuffer_ = 0, program_ = 0;
  GLboolean depth_test_ = GL_FALSE, depth_mask_ = GL_TRUE;
  // Per viewport index (glViewport, glDepthRange and glDisable(GL_SCISSOR_TEST) set every one): its
  // rectangle (floats, as glViewportIndexedf takes it), depth range and scissor test.
  std::vector<GLfloat> viewports_;
  std::vector<GLdouble> depth_ranges_;
  std::vector<GLboolean> scissor_tests_;
  GLboolean sample_shading_ = GL_FALSE, cull_face_ = GL_FALSE, rasterizer_discard_ = GL_FALSE;
  // GL_MULTISAMPLE, the sample mask and coverage operations and the colour logic op (kSampleCaps).
  GLboolean sample_caps_[6] = {};
  GLint polygon_mode_[2] = {GL_FILL, GL_FILL};  // GL_POLYGON_MODE reports front and back
  GLboolean polygon_offset_fill_ = GL_FALSE, framebuffer_srgb_ = GL_FALSE;
  GLfloat min_sample_shading_ = 0.0f;
  GLint depth_func_ = GL_LESS, vertex_array_ = 0, active_texture_ = GL_TEXTURE0;
  // Stencil test and, per face (front, back): function, reference (as GL reports it: clamped
  // to the stencil bits of the framebuffer bound when saved), value mask, the three operations
  // and the write mask.
  GLboolean stencil_test_ = GL_FALSE;
  GLint stencil_[2][7] = {};
  std::vector<UnitTextures> textures_;
  std::vector<DrawBufferState> draw_buffers_;  // blending and colour mask of every draw buffer
  std::vector<IndexedBufferBinding> uniform_buffers_;
  GLint generic_uniform_buffer_ = 0;
};

// Saves and restores what a compute pass changes beside SavedState: the shader storage buffers
// at `storage_bindings` (and the generic GL_SHADER_STORAGE_BUFFER binding), the images bound to
// `image_units` and the GL_DISPATCH_INDIRECT_BUFFER binding.
class SavedComputeState {
 public:
  SavedComputeState(std::vector<int> storage_bindings, std::vector<int> image_units);
  ~SavedComputeState();
  SavedComputeState(const SavedComputeState&) = delete;
  SavedComputeState& operator=(const SavedComputeState&) = delete;

 private:
  struct ImageUnit {
    int unit;
    GLint texture, level, layer, access, format;
    GLboolean layered;
  };
  GLint generic_storage_buffer_ = 0, dispatch_indirect_buffer_ = 0;
  std::vector<IndexedBufferBinding> storage_buffers_;
  std::vector<ImageUnit> images_;
};

// The state a pass draws with, whatever the engine left: clears and writes reach every pixel
// (no scissor, all masks on, no culling, filled polygons, no rasterizer discard, no polygon
// offset), no blending, no stencil test, depth range [0, 1], depth test on (GL_LESS) or off;
// every sample of a multisample target written (GL_MULTISAMPLE on, no sample mask, coverage
// value or alpha to coverage/one) and the codes written as they are (no logic op).
void set_pass_state(bool depth_test);

// The internal format of a texture's level 0.
GLenum internal_format_of(GLuint texture);

// Throws std::invalid_argument naming `what` unless `texture` is an existing 2D texture of
// `internal_format` and width x height (a missing or wrong binding is an error, not garbage).
void require_texture(GLuint texture, GLenum internal_format, int width, int height,
                     const std::string& what);
// The same for a texture that may have any of `internal_formats` (the message lists them all). A
// depth-stencil one must be read as depth (GL_DEPTH_STENCIL_TEXTURE_MODE). Every texture given
// must have the identity swizzle: a texture read applies it, image loads, stores and copies not.
void require_texture(GLuint texture, const std::vector<GLenum>& internal_formats, int width, int height,
                     const std::string& what);

}  // namespace rsaa::gl
