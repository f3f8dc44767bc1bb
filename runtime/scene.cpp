#include "runtime/scene.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <future>
#include <limits>
#include <memory>
#include <thread>

namespace rsaa {

glm::vec3 Scene::bounds_min() const {
  glm::vec3 lo(std::numeric_limits<float>::max());
  for (std::uint32_t i : indices) lo = glm::min(lo, vertices[i].position);
  return lo;
}

glm::vec3 Scene::bounds_max() const {
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (std::uint32_t i : indices) hi = glm::max(hi, vertices[i].position);
  return hi;
}

Scene load_scene(const std::string& spec) {
  const std::string prefix = "builtin:";
  if (spec.rfind(prefix, 0) == 0) return builtin_scene(spec.substr(prefix.size()));
  return load_model(spec);
}

Scene load_scene_within(const std::string& spec, double seconds) {
  auto task = std::make_shared<std::packaged_task<Scene()>>([spec] { return load_scene(spec); });
  std::future<Scene> result = task->get_future();
  std::thread([task] { (*task)(); }).detach();
  if (result.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready)
    throw std::runtime_error("'" + spec + "': loading did not finish within " +
                             std::to_string(int(seconds)) + " s (a malformed file can make the "
                             "model importer loop forever)");
  return result.get();
}

Scene scaled_scene(Scene scene, float factor) {
  if (!(factor > 0.0f) || !std::isfinite(factor)) throw std::invalid_argument("scene scale must be a finite number > 0");
  for (SceneVertex& v : scene.vertices) v.position *= factor;
  if (scene.camera) {
    scene.camera->eye *= factor, scene.camera->target *= factor;
    scene.camera->near_plane *= factor, scene.camera->far_plane *= factor;
  }
  return scene;
}

std::string scene_short_name(const std::string& spec) {
  const std::string name = spec.substr(spec.find_last_of("/:") + 1);
  return name.substr(0, name.find('.'));
}

Camera choose_camera(const Scene& scene, const std::optional<Camera>& requested) {
  if (requested) return *requested;
  if (scene.camera) return *scene.camera;
  return frame_bounds(scene.bounds_min(), scene.bounds_max());
}

}  // namespace rsaa
