#include "runtime/gpu_scene.h"

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "runtime/coplanar_draws.h"
#include "runtime/gl_context.h"
#include "runtime/smoothing_groups.h"

namespace rsaa {

GpuScene::GpuScene(const Scene& scene, bool with_facet_colours)
    : draws_(scene.draws),
      background_(scene.background),
      texture_anisotropy_(scene.texture_anisotropy),
      triangles_(scene.triangle_count()) {
  GLuint id;
  glCreateBuffers(1, &id);
  vertices_ = gl::Buffer(id);
  glNamedBufferStorage(id, GLsizeiptr(scene.vertices.size() * sizeof(SceneVertex)),
                       scene.vertices.data(), 0);
  glCreateBuffers(1, &id);
  indices_ = gl::Buffer(id);
  glNamedBufferStorage(id, GLsizeiptr(scene.indices.size() * sizeof(std::uint32_t)),
                       scene.indices.data(), 0);
  glCreateVertexArrays(1, &id);
  vao_ = gl::VertexArray(id);
  glVertexArrayVertexBuffer(id, 0, vertices_.get(), 0, sizeof(SceneVertex));
  glVertexArrayElementBuffer(id, indices_.get());
  const struct {
    GLuint location;
    GLint size;
    std::size_t offset;
  } attributes[] = {{0, 3, offsetof(SceneVertex, position)},
                    {1, 3, offsetof(SceneVertex, normal)},
                    {2, 2, offsetof(SceneVertex, uv)},
                    {3, 3, offsetof(SceneVertex, albedo)},
                    {4, 1, offsetof(SceneVertex, filter_alpha)}};
  for (const auto& a : attributes) {
    glEnableVertexArrayAttrib(id, a.location);
    glVertexArrayAttribFormat(id, a.location, a.size, GL_FLOAT, GL_FALSE, GLuint(a.offset));
    glVertexArrayAttribBinding(id, a.location, 0);
  }
  for (std::size_t d = 0; d < scene.draws.size(); ++d)
    if (scene.draws[d].first_index % 3 != 0 || scene.draws[d].index_count % 3 != 0)
      throw std::invalid_argument("scene '" + scene.name + "': draw " + std::to_string(d) +
                                  " does not start and end on a triangle (first index " +
                                  std::to_string(scene.draws[d].first_index) + ", " +
                                  std::to_string(scene.draws[d].index_count) + " indices)");
  if (!(scene.texture_anisotropy >= 1.0f && scene.texture_anisotropy <= kMaxTextureAnisotropy))
    throw std::invalid_argument("scene '" + scene.name + "': texture anisotropy " +
                                std::to_string(scene.texture_anisotropy) + " is not within 1.." +
                                std::to_string(int(kMaxTextureAnisotropy)));
  for (const TextureImage& t : scene.textures) {
    GLuint tex;
    glCreateTextures(GL_TEXTURE_2D, 1, &tex);
    const int levels = 1 + int(std::floor(std::log2(std::max(t.width, t.height))));
    glTextureStorage2D(tex, levels, GL_SRGB8_ALPHA8, t.width, t.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows are stored top first; GL's first row is the bottom one, and the loader already
    // flipped v, so upload as is.
    glTextureSubImage2D(tex, 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
    glGenerateTextureMipmap(tex);
    glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_REPEAT);
    textures_.emplace_back(tex);
  }
  if (scene.point_lights.size() > std::size_t(kMaxScenePointLights))
    throw std::invalid_argument("a scene has at most " + std::to_string(kMaxScenePointLights) + " point lights");
  // std140 ScenePointLights of shaders/shading.glsl: count, then positions+radii, then colours.
  std::vector<float> block(4 + 8 * kMaxScenePointLights, 0.0f);
  const int count = int(scene.point_lights.size());
  std::memcpy(block.data(), &count, sizeof count);
  for (int i = 0; i < count; ++i) {
    const PointLight& p = scene.point_lights[i];
    float* position = &block[4 + 4 * i];
    float* colour = &block[4 + 4 * kMaxScenePointLights + 4 * i];
    position[0] = p.position.x, position[1] = p.position.y, position[2] = p.position.z, position[3] = p.radius;
    colour[0] = p.colour.r, colour[1] = p.colour.g, colour[2] = p.colour.b;
  }
  glCreateBuffers(1, &id);
  point_lights_ = gl::Buffer(id);
  glNamedBufferStorage(id, GLsizeiptr(block.size() * sizeof(float)), block.data(), 0);

  if (with_facet_colours) {
    std::vector<std::uint8_t> facets = facet_colours(scene);
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    // More triangles than a buffer texture holds: none is a facet (the shader reads 0 past the
    // buffer's size), said once.
    if (facets.size() > std::size_t(max_texels)) {
      std::fprintf(stderr, "scene '%s': %zu triangles are more than this driver's buffer textures hold (%d): no facet edges\n",
                   scene.name.c_str(), facets.size(), max_texels);
      facets.assign(1, kNotAFacet);
    }
    if (facets.empty()) facets.push_back(kNotAFacet);
    glCreateBuffers(1, &id);
    facet_colours_ = gl::Buffer(id);
    glNamedBufferStorage(id, GLsizeiptr(facets.size()), facets.data(), 0);
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
    facet_colour_texture_ = gl::Texture(id);
    glTextureBuffer(id, GL_R8UI, facet_colours_.get());
    has_facet_colours_ = true;
  }
  gl::check("uploading the scene");
}

void GpuScene::draw(GLuint program) const {
  const GLint facet_colours = glGetUniformLocation(program, "u_facet_colours");
  if (facet_colours >= 0 && !has_facet_colours_)
    throw std::logic_error("a facet edges program draws a scene uploaded without facet colours (GpuScene(scene, true))");
  glBindBufferBase(GL_UNIFORM_BUFFER, 4, point_lights_.get());
  glBindVertexArray(vao_.get());
  const GLint has_texture = glGetUniformLocation(program, "u_has_texture");
  const GLint primitive_base = glGetUniformLocation(program, "u_primitive_base");
  const GLint material = glGetUniformLocation(program, "u_material");
  const GLint depth_bias = glGetUniformLocation(program, "u_depth_bias");
  const GLint texture = glGetUniformLocation(program, "u_texture");
  if (texture >= 0) glProgramUniform1i(program, texture, 0);
  GLint facet_unit = -1;
  if (facet_colours >= 0) {
    glGetUniformiv(program, facet_colours, &facet_unit);
    glBindTextureUnit(GLuint(facet_unit), facet_colour_texture_.get());
  }
  const GLint anisotropy = glGetUniformLocation(program, "u_texture_anisotropy");
  if (anisotropy >= 0) glProgramUniform1f(program, anisotropy, texture_anisotropy_);
  for (const DrawRange& d : draws_) {
    const bool textured = d.texture >= 0 && d.texture < int(textures_.size());
    if (has_texture >= 0) glProgramUniform1i(program, has_texture, textured);
    if (primitive_base >= 0) glProgramUniform1ui(program, primitive_base, d.first_index / 3);
    if (material >= 0) glProgramUniform1ui(program, material, d.material);
    // NDC depth spans 2 for window depth's 1.
    if (depth_bias >= 0) glProgramUniform1f(program, depth_bias, 2.0f * kCoplanarDepthStep * float(d.depth_rank));
    if (textured) glBindTextureUnit(0, textures_[d.texture].get());
    glDrawElements(GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(std::size_t(d.first_index) * sizeof(std::uint32_t)));
  }
  glBindVertexArray(0);
  if (facet_unit >= 0) glBindTextureUnit(GLuint(facet_unit), 0);
}

View make_view(const Camera& camera, int width, int height) {
  View v;
  v.view = camera.view();
  v.projection = camera.projection(float(width) / float(height));
  v.width = width;
  v.height = height;
  return v;
}

}  // namespace rsaa
