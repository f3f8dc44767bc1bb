#include "runtime/scene_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "runtime/gl_context.h"
#include "runtime/shader_library.h"

namespace rsaa {
namespace {

gl::Program make_scene_program(const std::string& defines, const std::string& label) {
  return gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                           {GL_GEOMETRY_SHADER, gl::shader_source("scene.geom")},
                           {GL_FRAGMENT_SHADER, gl::shader_source("scene_shade.frag")}},
                          defines, label);
}

}  // namespace

SceneRenderer::SceneRenderer(bool facet_materials)
    : shade_(make_scene_program("", "scene shading")),
      gbuffer_(make_scene_program(std::string("#define RSAA_GBUFFER\n#define RSAA_SAMPLE_COUNT 1\n") +
                                      (facet_materials ? "#define SCENE_FACET_MATERIALS\n" : ""),
                                  "scene shading + G-buffer")) {
  if (facet_materials)
    glProgramUniform1i(gbuffer_.get(), glGetUniformLocation(gbuffer_.get(), "u_facet_colours"), kFacetColourUnit);
}

void SceneRenderer::draw(const GpuScene& scene, const View& view, glm::vec2 jitter_ndc, GLuint program,
                         GLenum depth_func) {
  glViewport(0, 0, view.width, view.height);
  draw_in_current_viewport(scene, view, jitter_ndc, program, depth_func);
}

void SceneRenderer::draw_in_current_viewport(const GpuScene& scene, const View& view, glm::vec2 jitter_ndc,
                                             GLuint program, GLenum depth_func) {
  glUseProgram(program);
  glUniformMatrix4fv(glGetUniformLocation(program, "u_view"), 1, GL_FALSE, glm::value_ptr(view.view));
  glUniformMatrix4fv(glGetUniformLocation(program, "u_projection"), 1, GL_FALSE,
                     glm::value_ptr(view.projection));
  glUniform2f(glGetUniformLocation(program, "u_jitter_ndc"), jitter_ndc.x, jitter_ndc.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(depth_func);
  scene.draw(program);
  glDisable(GL_DEPTH_TEST);
}

void SceneRenderer::draw_gbuffer(const GpuScene& scene, const View& view, const RsaaTargets& targets,
                                 glm::vec2 jitter_ndc) const {
  const glm::vec3 background = scene.background();
  targets.clear(&background.x);
  targets.bind();
  draw(scene, view, jitter_ndc, gbuffer_.get());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void clear_to_background(GLuint framebuffer, const GpuScene& scene) {
  const glm::vec3 bg = scene.background();
  const GLfloat colour[4] = {bg.r, bg.g, bg.b, 1.0f};
  const GLfloat depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, colour);
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &depth);
}

}  // namespace rsaa
