// Drawing the scene at one sample position: the shading program every technique shares, in two
// forms (colour only; colour + the RSAA G-buffer), and the colour targets of a 1x pass.
#pragma once

#include "runtime/rsaa_pass.h"

#include <glm/glm.hpp>

#include "runtime/fullscreen.h"
#include "runtime/gl_objects.h"
#include "runtime/gpu_scene.h"

namespace rsaa {

class SceneRenderer {
 public:
  // facet_materials: the G-buffer program writes facets' materials
  // (RsaaSettings::facet_materials, shaders/scene_facet_material.glsl) instead of their draw's.
  explicit SceneRenderer(bool facet_materials = false);

  // Sets the frame uniforms on `program` and draws the scene with the image translated by
  // `jitter_ndc` (see jitter_ndc_for_sample), depth-tested with `depth_func` (GL_GREATER for
  // reverse Z). The caller binds the framebuffer.
  static void draw(const GpuScene& scene, const View& view, glm::vec2 jitter_ndc, GLuint program,
                   GLenum depth_func = GL_LESS);
  // The same into the viewport the caller has set: RsaaPass's pre-pass callbacks, whose viewport
  // the pass sets (a multiple of the image for a cell pattern's draw).
  static void draw_in_current_viewport(const GpuScene& scene, const View& view, glm::vec2 jitter_ndc, GLuint program,
                                       GLenum depth_func = GL_LESS);

  GLuint shade_program() const { return shade_.get(); }
  // The 1x frame RSAA post-processes: clears `targets` and draws the scene into them with the
  // G-buffer program, the image translated by `jitter_ndc`. Leaves the default framebuffer bound.
  void draw_gbuffer(const GpuScene& scene, const View& view, const RsaaTargets& targets,
                    glm::vec2 jitter_ndc = {0.0f, 0.0f}) const;
  // Also writes location 1: RG16UI compressed face normal, location 2: R32UI primitive id + 1.
  GLuint gbuffer_program() const { return gbuffer_.get(); }

 private:
  gl::Program shade_, gbuffer_;
};

// Clears a framebuffer's colour attachment 0 to the scene background and its depth to 1.
void clear_to_background(GLuint framebuffer, const GpuScene& scene);

}  // namespace rsaa
