// A test suite with one headless GL context for all its tests (made once per suite: llvmpipe
// contexts are slow to create).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "runtime/gl_context.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene.h"
#include "runtime/scene_renderer.h"

namespace rsaa::test {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context() = std::make_unique<gl::HeadlessContext>(); }
  static void TearDownTestSuite() { context().reset(); }

 private:
  static std::unique_ptr<gl::HeadlessContext>& context() {
    static std::unique_ptr<gl::HeadlessContext> c;
    return c;
  }
};

// `settings` with the paper's classification and resolve (no split cap, one fetch everywhere)
// instead of this project's defaults: for tests of the paper's algorithm and its CPU reference.
inline RsaaSettings paper_resolve(RsaaSettings settings = {}) {
  settings.auth = 0;  // the CPU reference has no authentication
  settings.split_cap = 0.0f;
  settings.multi_surface = "fetch";
  settings.split_check = "off";
  settings.fetch_check = "off";
  return settings;
}

// A scene at its own camera drawn into the 1x targets RSAA reads (needs a current context).
struct SceneFrame {
  SceneFrame(const std::string& scene_name, int width, int height, bool material_edges = false)
      : scene(load_scene(scene_name)),
        gpu(scene),
        view(make_view(choose_camera(scene, std::nullopt), width, height)),
        targets(width, height, material_edges) {
    renderer.draw_gbuffer(gpu, view, targets);
  }
  RsaaFrame frame() const { return targets.frame(view.inverse_projection()); }
  // The pass's pre-pass with its own program, drawing this scene.
  void render_subsamples(RsaaPass& pass) const {
    pass.render_subsamples(frame(), [&](unsigned program, glm::vec2 jitter) {
      SceneRenderer::draw(gpu, view, jitter, program);
    });
  }

  Scene scene;
  GpuScene gpu;
  View view;
  SceneRenderer renderer;
  RsaaTargets targets;
};

}  // namespace rsaa::test
