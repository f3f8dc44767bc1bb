// A Scene uploaded to GL: one vertex/index buffer, its textures, and a draw call per range.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "runtime/gl_objects.h"
#include "runtime/scene.h"

namespace rsaa {

// The texture unit the renderer's G-buffer program reads the per-triangle facet colours from
// (RsaaSettings::facet_colours_unit's default for the pass's pre-pass program): free while the
// scene draws (its texture at 0, RsaaPass's pre-pass textures at 13-15 by default).
constexpr int kFacetColourUnit = 12;

class GpuScene {
 public:
  // with_facet_colours: also finds the scene's facets (runtime/smoothing_groups.h; seconds for
  // millions of triangles) for the programs of RSAA's facet edges, on by default since they are
  // rsaa's default (a caller that knows its techniques passes needs_facet_colours()).
  explicit GpuScene(const Scene& scene, bool with_facet_colours = true);

  // Draws every triangle with `program` bound. Attribute locations: 0 position, 1 normal, 2 uv,
  // 3 albedo, 4 filter alpha. Sets u_texture (unit 0), u_has_texture, u_primitive_base (so that
  // primitive ids are unique across draw calls), u_material and u_texture_anisotropy when the
  // program has them, and binds the facet colours (per triangle, runtime/smoothing_groups.h) at
  // the unit a program's u_facet_colours names (unbound again after the draw; throws
  // std::logic_error for such a program when the scene was uploaded without them). Binds the
  // point lights (uniform block binding 4) for every shading pass that follows.
  void draw(GLuint program) const;

  glm::vec3 background() const { return background_; }
  std::size_t triangle_count() const { return triangles_; }
  bool has_facet_colours() const { return has_facet_colours_; }

 private:
  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_, point_lights_, facet_colours_;
  gl::Texture facet_colour_texture_;
  std::vector<gl::Texture> textures_;
  std::vector<DrawRange> draws_;
  glm::vec3 background_;
  float texture_anisotropy_ = 1.0f;
  std::size_t triangles_ = 0;
  bool has_facet_colours_ = false;
};

// The matrices of one frame.
struct View {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  int width = 0, height = 0;
  glm::mat4 inverse_projection() const { return glm::inverse(projection); }
};
View make_view(const Camera& camera, int width, int height);

}  // namespace rsaa
