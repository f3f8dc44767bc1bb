// A test suite with one headless GL context for all its tests (made once per suite: llvmpipe
// contexts are slow to create).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "runtime/gl_context.h"
#include "runtime/gl_objects.h"
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
        gpu(scene, /*with_facet_colours=*/false),  // the pass's tests draw without facet materials
        view(make_view(choose_camera(scene, std::nullopt), width, height)),
        targets(width, height, material_edges) {
    renderer.draw_gbuffer(gpu, view, targets);
  }
  RsaaFrame frame() const { return targets.frame(view.inverse_projection()); }
  // The pass's pre-pass with its own program, drawing this scene.
  void render_subsamples(RsaaPass& pass) const {
    pass.render_subsamples(frame(), [&](unsigned program, glm::vec2 jitter) {
      SceneRenderer::draw_in_current_viewport(gpu, view, jitter, program);
    });
  }

  Scene scene;
  GpuScene gpu;
  View view;
  SceneRenderer renderer;
  RsaaTargets targets;
};

// An engine's pre-pass program built from `prepass_glsl` (RsaaPass::prepass_glsl()): its own
// vertex stage (the scene's attribute 0 and camera, no geometry stage) with rsaa_jitter(), and
// a fragment stage calling rsaa_prepass_code() with the face normal from derivatives (and, with
// material edges, the draw's material).
inline gl::Program engine_prepass_program(const std::string& prepass_glsl) {
  const std::string vertex = "#define RSAA_INCLUDE_FS 0\n" + prepass_glsl + R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_view, u_projection;
out vec3 v_view_position;
void main() {
  vec4 view = u_view * vec4(a_position, 1.0);
  v_view_position = view.xyz;
  gl_Position = rsaa_jitter(u_projection * view);
})";
  const std::string fragment = prepass_glsl + R"(
in vec3 v_view_position;
uniform uint u_primitive_base, u_material;
layout(location = 0) out uvec4 o_code;
void main() {
  uint primitive = u_primitive_base + uint(gl_PrimitiveID) + 1u;
#ifdef RSAA_MATERIAL_EDGES
  o_code = rsaa_prepass_code(v_view_position, rsaa_face_normal(v_view_position), primitive, u_material);
#else
  o_code = rsaa_prepass_code(v_view_position, rsaa_face_normal(v_view_position), primitive);
#endif
})";
  return gl::make_program({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, "", "engine pre-pass");
}

}  // namespace rsaa::test
