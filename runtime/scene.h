// Scenes: triangle meshes with per-vertex albedo and optional textures, from the built-in
// procedural set (`builtin:NAME`) or any model assimp reads.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/reference/scene_shading.h"
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
  // The draw's material: one id per appearance (a model's materials of equal base colour and
  // texture share it; 0 in the built-in scenes but builtin:coplanar). RSAA's material edges
  // (RsaaSettings::material_edges) tell coplanar parts apart by it.
  std::uint32_t material = 0;
  // Coplanar overlaps with earlier draws resolved by draw order (runtime/coplanar_draws.h): the
  // vertex stage moves the draw back along the view rays by depth_rank x kCoplanarDepthStep of
  // window depth.
  std::uint32_t depth_rank = 0;
};

// Texture filtering of the scene's shaders (shaders/scene_shading.glsl): up to this many
// trilinear probes along a texture footprint's long axis, unless a caller asks otherwise
// (`--anisotropy`), at most kMaxTextureAnisotropy.
constexpr float kDefaultTextureAnisotropy = 16.0f;
constexpr float kMaxTextureAnisotropy = 16.0f;

struct Scene {
  std::string name;
  std::vector<SceneVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
  std::vector<DrawRange> draws;
  std::vector<TextureImage> textures;
  glm::vec3 background{0.05f, 0.06f, 0.09f};  // linear clear colour
  std::optional<Camera> camera;               // a built-in view; else frame the bounds
  // Extra lights beside the fixed one (view space; none unless a caller adds them: the bench's
  // --lights). Every technique shades with them where it shades (shaders/shading.glsl).
  std::vector<PointLight> point_lights;
  // How textures are filtered: the largest anisotropy a lookup may use, 1..kMaxTextureAnisotropy
  // (1 = trilinear only). Engines filter anisotropically; trilinear alone blurs a texture seen at
  // a grazing angle to the mip level of its compressed direction.
  float texture_anisotropy = kDefaultTextureAnisotropy;

  std::size_t triangle_count() const { return indices.size() / 3; }
  // Axis-aligned bounds of the vertices that triangles use.
  glm::vec3 bounds_min() const;
  glm::vec3 bounds_max() const;
};

const std::vector<std::string>& builtin_scene_names();

// Budgets of model loading (docs/reliability.md): the model file and each file it refers to,
// the vertices and faces copied out of the importer, and the texels of all its textures (each
// texture also within kTextureBudget of image/image_io.h).
constexpr std::uint64_t kMaxModelFileBytes = std::uint64_t{256} << 20;
// What assimp may allocate while importing a model (runtime/allocation_budget.h): a floor, plus
// so much per byte of the files it reads (the model and the files it refers to), at most
// kImportBytesMax. Measured over the 320 models in /usr/share/assimp/models that load: at most
// 219 MiB (a 86 KB .blend with subdivision; a 2.7 KB .ac with subdivision: 213 MiB), and about
// 16 MiB of assimp's own for any file (tests/test_model_budget.cpp measures it).
constexpr std::uint64_t kImportBytesFloor = std::uint64_t{512} << 20;
constexpr std::uint64_t kImportBytesPerInputByte = 64;
constexpr std::uint64_t kImportBytesMax = std::uint64_t{4} << 30;
constexpr std::uint64_t kMaxSceneVertices = std::uint64_t{1} << 24;
constexpr std::uint64_t kMaxSceneTriangles = std::uint64_t{1} << 25;
constexpr std::uint64_t kMaxSceneTexels = std::uint64_t{1} << 26;
// Coordinates a model may have and still render as it would at unit scale (measured with a
// tetrahedron framed automatically: equal images from scale 1e-5 to 3e9; scale 1e-6 and 1e10
// differ, 1e30 showed only the background; offset from the origin by 1e4 times its size it
// is within 63 dB, by 3e4 times only 43 dB).
constexpr double kMaxSceneCoordinate = 1e9;
constexpr double kMinSceneExtent = 1e-5;
constexpr double kMinExtentToPosition = 1e-4;
// Throws std::runtime_error starting with `what` when the scene's bounds are outside these.
void check_frameable(const Scene& scene, const std::string& what);

// Stack of the loader thread: importers recurse per node level, 350 to 700 bytes each (measured:
// a glTF node chain 800,000 deep loads, 1.5 million overflows); the main thread's 8 MiB
// overflowed at 20,000. Deeper files are stopped by a fault guard that names the scene.
constexpr std::size_t kLoaderStackBytes = std::size_t{512} << 20;

// Normals for a model that has none (assimp generates them, averaging the faces that meet at a
// vertex position): faces meeting at more than this angle keep their own normals (a crease).
// Building models (IFC) are planar solids: averaged across their 90-degree corners, a flat wall
// or floor slab shades as a curved blob and coplanar triangles meet with different shading
// (test SceneLoading.BuildingModelsShadeTheirFlatFacesFlat); 60 degrees keeps tessellated arcs
// (columns, round windows) smooth. Other formats keep assimp's 175 degrees (smooth everywhere):
// a low-poly character without normals (COB/dwarf.cob) turns faceted at any crease angle below 90.
constexpr float kBuildingCreaseDegrees = 60.0f;
constexpr float kSmoothCreaseDegrees = 175.0f;
float generated_normals_crease_degrees(const std::string& path);

// "builtin:NAME" or a model path. Throws std::runtime_error naming the scene on any problem:
// unknown built-in, missing/unreadable file, no triangles, non-finite positions.
Scene load_scene(const std::string& spec);

// load_scene with a time limit: some broken files make assimp 5.2 loop forever (a PLY header
// cut inside a property list does). The loader runs on its own thread; past the limit this
// throws std::runtime_error naming the file, and the stuck thread is left behind, so the caller
// should end the process soon (the command line does). The thread has a kLoaderStackBytes
// stack; when no thread can be started (a process limit), this throws naming the scene.
Scene load_scene_within(const std::string& spec, double seconds);

Scene builtin_scene(const std::string& name);
// What an import took (for the budget's measurement, tests/test_model_budget.cpp): the bytes
// of the files it read and the most memory it held at once.
struct ImportMeasurement {
  std::uint64_t input_bytes = 0;
  std::int64_t peak_bytes = 0;
};
Scene load_model(const std::string& path, ImportMeasurement* measurement = nullptr);

// load_model in two steps: the import (assimp, which a malformed file can crash: run in a child
// process by load_scene_within) and the decoding of the textures it names.
struct TextureSource {
  std::string name;  // the file, or the model and the embedded texture's name; empty: none
  bool embedded = false;
  std::string bytes, format_hint;  // an embedded texture's encoded bytes and format
};
struct ImportedModel {
  Scene scene;  // each draw's `texture` is its material until with_textures
  std::vector<TextureSource> textures;  // per material
};
ImportedModel import_model(const std::string& path, ImportMeasurement* measurement = nullptr);
Scene with_textures(ImportedModel model);

// import_model in a child process, so that an importer that crashes (assimp 5.2 segfaults or
// asserts on many malformed files) ends the child, not the caller: throws std::runtime_error
// naming the model and the signal. `started` gets the child's PID (to kill it on a time limit),
// then 0 once the child is reaped.
ImportedModel import_model_in_child(const std::string& path, const std::function<void(int pid)>& started);

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
