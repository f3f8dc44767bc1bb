// The RSAA pass as an engine would drop it in (the one public header of the runtime's RSAA):
// per-subsample similarity pre-pass + post-process, for any of the 12 variants of the paper.
//
// The engine renders its 1x frame into four targets of width x height:
//   colour            RGBA16F (linear), GL_LINEAR filtering, clamp to edge
//   centre_normal     RG16UI: rsaa_encode_normal(geometric normal) (0 = background)
//   centre_primitive  R32UI: unique triangle id + 1 (0 = background); drives the shortcut
//   centre_depth      DEPTH_COMPONENT32F
// (SceneRenderer::gbuffer_program() writes exactly these; shaders/scene_shade.frag shows how;
// RsaaTargets allocates them.)
// Then it calls render_subsamples() with a callback that draws its geometry once per subsample
// with the program given (vertex attributes: 0 position, 1 normal, 2 uv, 3 albedo; uniforms
// u_view, u_projection, u_jitter_ndc), and resolve() into its output texture.
#pragma once

#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "core/sample_pattern.h"
#include "runtime/gl_objects.h"

namespace rsaa {

struct RsaaSettings {
  std::string pattern = "d3d8x";  // d3d8x | d3d4x | gl4x (the driver's 4x pattern)
  // sadp: the paper's SADP; depth: the paper's depth alternative (relative depth difference);
  // sadp-plane (ours): SADP or the gap between the surfaces' planes along the view ray, whichever
  // is larger, so that silhouettes over surfaces seen at grazing angles are found.
  std::string similarity = "sadp-plane";
  int auth = 0;                   // 0 none, 1 post-pass (halve offsets), 2 pre-pass (reclassify)
  float threshold = 0.4f;         // SADP units (sadp, sadp-plane), or percent of depth (depth)
  int code_bits = 8;              // 8 | 16 | 32: storage per subsample similarity
  bool output_mask = false;       // resolve() also writes the mask (R32UI) for tests
};

struct RsaaFrame {
  GLuint colour = 0, centre_normal = 0, centre_primitive = 0, centre_depth = 0;
  int width = 0, height = 0;
  glm::mat4 inverse_projection{1.0f};  // unjittered
};

// The four 1x targets above, allocated, for an engine that has none of its own.
class RsaaTargets {
 public:
  RsaaTargets(int width, int height);
  // Colour to `background` (linear RGB), normal and primitive to 0 (background), depth to 1.
  void clear(const float background[3]) const;
  // Binds the framebuffer: colour at location 0, normal 1, primitive 2, and depth.
  void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get()); }
  RsaaFrame frame(const glm::mat4& inverse_projection) const;
  static constexpr double kBytesPerPixel = 8 + 4 + 4 + 4;
  GLuint colour() const { return colour_.get(); }

 private:
  int width_, height_;
  gl::Texture colour_, normal_, primitive_, depth_;
  gl::Framebuffer framebuffer_;
};

// The 4x pattern of this GL driver, in pixel space (needs a current context).
SamplePattern query_gl_sample_pattern(int samples = 4);

class RsaaPass {
 public:
  using DrawGeometry = std::function<void(GLuint program, glm::vec2 jitter_ndc)>;

  // Needs a current GL 4.5 context. Throws std::invalid_argument for bad settings and
  // std::runtime_error when the baked table does not match the pattern's positions.
  RsaaPass(const RsaaSettings& settings, int width, int height);

  void render_subsamples(const RsaaFrame& frame, const DrawGeometry& draw_geometry);
  // Writes the anti-aliased colour into `output` (RGBA16F), and the mask into `mask_output`
  // (R32UI) when settings.output_mask.
  void resolve(const RsaaFrame& frame, GLuint output, GLuint mask_output = 0);

  const SamplePattern& pattern() const { return pattern_; }
  // Bytes per pixel of the similarity codes this pass keeps.
  double code_bytes_per_pixel() const { return pattern_.size() * settings_.code_bits / 8.0; }

 private:
  RsaaSettings settings_;
  SamplePattern pattern_;
  int width_, height_;
  gl::Texture codes_, subsample_depth_;
  std::vector<gl::Framebuffer> subsample_targets_;
  gl::Program subsample_program_, post_program_;
  gl::CachedFramebuffer resolve_target_;
};

}  // namespace rsaa
