#include "runtime/scene.h"

#include <pthread.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

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

namespace {

// What the loader thread hands back; shared, since a thread that times out outlives the call.
struct LoadState {
  std::string spec;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<Scene> scene;
  std::exception_ptr error;
};

void* run_loader(void* argument) {
  const std::shared_ptr<LoadState> state = *static_cast<std::shared_ptr<LoadState>*>(argument);
  delete static_cast<std::shared_ptr<LoadState>*>(argument);
  std::optional<Scene> scene;
  std::exception_ptr error;
  try {
    scene = load_scene(state->spec);
  } catch (...) {
    error = std::current_exception();
  }
  const std::lock_guard<std::mutex> lock(state->mutex);
  state->scene = std::move(scene);
  state->error = error;
  state->done = true;
  state->finished.notify_all();
  return nullptr;
}

}  // namespace

Scene load_scene_within(const std::string& spec, double seconds) {
  auto state = std::make_shared<LoadState>();
  state->spec = spec;
  // pthread, not std::thread: only pthread attributes set the stack size.
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, kLoaderStackBytes);
  auto* argument = new std::shared_ptr<LoadState>(state);
  pthread_t thread;
  const int error = pthread_create(&thread, &attributes, run_loader, argument);
  pthread_attr_destroy(&attributes);
  if (error != 0) {
    delete argument;
    throw std::runtime_error("'" + spec + "': cannot start the loader thread (" +
                             std::strerror(error) + "; a process or memory limit?)");
  }
  pthread_detach(thread);
  std::unique_lock<std::mutex> lock(state->mutex);
  if (!state->finished.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return state->done; }))
    throw std::runtime_error("'" + spec + "': loading did not finish within " +
                             std::to_string(int(seconds)) + " s (a malformed file can make the "
                             "model importer loop forever)");
  if (state->error) std::rethrow_exception(state->error);
  return std::move(*state->scene);
}

void check_frameable(const Scene& scene, const std::string& what) {
  const glm::dvec3 lo = scene.bounds_min(), hi = scene.bounds_max();
  double largest = 0.0, extent = 0.0;
  for (int k = 0; k < 3; ++k) {
    largest = std::max({largest, std::abs(lo[k]), std::abs(hi[k])});
    extent = std::max(extent, hi[k] - lo[k]);
  }
  char text[160];
  if (!(largest <= kMaxSceneCoordinate)) {
    std::snprintf(text, sizeof text, "coordinates reach %g; a float camera frames at most %g", largest,
                  kMaxSceneCoordinate);
  } else if (!(extent >= kMinSceneExtent)) {
    std::snprintf(text, sizeof text, "extent %g is below %g, too small to frame in float", extent,
                  kMinSceneExtent);
  } else if (extent < largest * kMinExtentToPosition) {
    std::snprintf(text, sizeof text, "extent %g at %g from the origin spans too few float steps (at least %g of the distance)",
                  extent, largest, kMinExtentToPosition);
  } else {
    return;
  }
  throw std::runtime_error(what + ": " + text);
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
