// Scenes: triangle meshes with per-vertex albedo and optional textures, from the built-in
// procedural set (`builtin:NAME`) or any model assimp reads.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/camera.h"

namespace rsaa {

struct SceneVertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // smooth shading normal
  glm::vec2 uv{0.0f};
  glm::vec3 albedo{0.8f};  // linear
  float filter_alpha = 1.0f;  // ssaa-filtered kernel 3: 1 = small kernel (sharp), 0 = large (soft)
};

// 8-bit sRGB RGBA texture, top row first.
struct TextureImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// A run of triangles drawn with one texture (-1: none).
struct DrawRange {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  int texture = -1;
};

struct Scene {
  std::string name;
  std::vector<SceneVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
  std::vector<DrawRange> draws;
  std::vector<TextureImage> textures;
  glm::vec3 background{0.05f, 0.06f, 0.09f};  // linear clear colour
  std::optional<Camera> camera;               // a built-in view; else frame the bounds

  std::size_t triangle_count() const { return indices.size() / 3; }
  // Axis-aligned bounds of the vertices that triangles use.
  glm::vec3 bounds_min() const;
  glm::vec3 bounds_max() const;
};

const std::vector<std::string>& builtin_scene_names();

// "builtin:NAME" or a model path. Throws std::runtime_error naming the scene on any problem:
// unknown built-in, missing/unreadable file, no triangles, non-finite positions.
Scene load_scene(const std::string& spec);

// load_scene with a time limit: some broken files make assimp 5.2 loop forever (a PLY header
// cut inside a property list does). The loader runs on its own thread; past the limit this
// throws std::runtime_error naming the file, and the stuck thread is left behind, so the caller
// should end the process soon (the command line does).
Scene load_scene_within(const std::string& spec, double seconds);

Scene builtin_scene(const std::string& name);
Scene load_model(const std::string& path);

// The scene with every position, and its built-in camera (eye, target, near and far), multiplied
// by `factor` (> 0, finite): the same picture in other units, for the tests that a technique's
// result does not depend on the asset's units.
Scene scaled_scene(Scene scene, float factor);

// A short name for reports and file names: "builtin:default" -> "default",
// "/a/b/Engine.glb" -> "Engine".
std::string scene_short_name(const std::string& spec);

// The camera to use: explicit, else the scene's own, else one that frames the bounds.
Camera choose_camera(const Scene& scene, const std::optional<Camera>& requested);

}  // namespace rsaa
