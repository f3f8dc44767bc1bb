// A Scene uploaded to GL: one vertex/index buffer, its textures, and a draw call per range.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "runtime/gl_objects.h"
#include "runtime/scene.h"

namespace rsaa {

// The texture unit GpuScene::draw binds the per-triangle facet colours to: free while the scene
// draws (its texture at 0, RsaaPass's pre-pass textures at 13-15 with RsaaSettings' defaults).
constexpr int kFacetColourUnit = 12;

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);

  // Draws every triangle with `program` bound. Attribute locations: 0 position, 1 normal, 2 uv,
  // 3 albedo, 4 filter alpha. Sets u_texture (unit 0), u_has_texture, u_primitive_base (so that
  // primitive ids are unique across draw calls), u_material and u_texture_anisotropy when the
  // program has them, and u_facet_colours (a usamplerBuffer on unit kFacetColourUnit: per
  // triangle, runtime/smoothing_groups.h) for the facet edges' programs. Binds the point lights
  // (uniform block binding 4) for every shading pass that follows.
  void draw(GLuint program) const;

  glm::vec3 background() const { return background_; }
  std::size_t triangle_count() const { return triangles_; }

 private:
  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_, point_lights_, facet_colours_;
  gl::Texture facet_colour_texture_;
  std::vector<gl::Texture> textures_;
  std::vector<DrawRange> draws_;
  glm::vec3 background_;
  float texture_anisotropy_ = 1.0f;
  std::size_t triangles_ = 0;
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
