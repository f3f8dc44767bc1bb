// Example 02: an engine with its own vertex stage (instancing and a per-vertex deformation)
// drawing through RsaaPass's pre-pass callback.
//
// The pre-pass program takes world-space positions (attribute 0) and view/projection only, so
// the engine runs its vertex stage once per frame into a buffer (transform feedback: instance
// transforms and a wave deformation applied on the GPU) and draws that buffer both into its
// G-buffer and in the callback. One draw of the same buffer gives the same primitive ids in
// both, which the pre-pass's shortcut relies on.
// Usage: 02_own_vertex_stage [OUT_DIR]   writes OUT_DIR/02_noaa.ppm and OUT_DIR/02_rsaa.ppm
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/gbuffer.h"
#include "runtime/rsaa_pass.h"

namespace {

// The engine's vertex stage: a flat strip mesh, instanced (per-instance offset, angle, colour),
// bent by a travelling wave. Outputs world positions and albedo for capture.
const char* kDeformVertex = R"(
layout(location = 0) in vec2 a_grid;          // mesh vertex in [0, 1]^2
layout(location = 1) in vec4 a_instance;      // xyz offset, w angle
layout(location = 2) in vec3 a_instance_colour;
uniform float u_time;
out vec3 tf_position;
out vec3 tf_albedo;
void main() {
  vec3 p = vec3(a_grid.x * 2.4 - 1.2, a_grid.y * 0.5 - 0.25, 0.0);
  p.z = 0.25 * sin(3.0 * p.x + u_time);       // the deformation
  p.y += 0.15 * sin(2.0 * p.x - u_time);
  float c = cos(a_instance.w), s = sin(a_instance.w);
  tf_position = vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z) + a_instance.xyz;
  tf_albedo = a_instance_colour;
})";

constexpr int kColumns = 24, kInstances = 4;
constexpr int kVerticesPerInstance = kColumns * 6;

}  // namespace

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : ".";
  const int width = 256, height = 192;
  try {
    engine::HeadlessGl context;

    // Mesh: kColumns quads in a row, two triangles each, in grid coordinates.
    std::vector<float> grid;
    for (int i = 0; i < kColumns; ++i) {
      const float x0 = float(i) / kColumns, x1 = float(i + 1) / kColumns;
      for (float v : {x0, 0.f, x1, 0.f, x1, 1.f, x0, 0.f, x1, 1.f, x0, 1.f}) grid.push_back(v);
    }
    const float instances[kInstances][7] = {{0.0f, 0.55f, -0.6f, 0.15f, 0.8f, 0.2f, 0.2f},
                                            {0.0f, -0.5f, -0.3f, -0.2f, 0.2f, 0.7f, 0.3f},
                                            {-0.3f, 0.0f, 0.1f, 1.2f, 0.2f, 0.3f, 0.9f},
                                            {0.5f, 0.1f, 0.4f, -1.0f, 0.9f, 0.8f, 0.2f}};
    GLuint buffers[3];
    glCreateBuffers(3, buffers);
    const GLuint grid_buffer = buffers[0], instance_buffer = buffers[1], captured = buffers[2];
    glNamedBufferStorage(grid_buffer, GLsizeiptr(grid.size() * sizeof(float)), grid.data(), 0);
    glNamedBufferStorage(instance_buffer, sizeof instances, instances, 0);
    const GLsizeiptr captured_bytes = GLsizeiptr(kInstances) * kVerticesPerInstance * 6 * sizeof(float);
    glNamedBufferStorage(captured, captured_bytes, nullptr, 0);

    // Grid vertices at binding 0, one instance record per instance at binding 1.
    const GLuint source_vao = engine::make_vertex_array({{0, 0, 2, 0}, {1, 1, 4, 0}, {2, 1, 3, 4}});
    glVertexArrayVertexBuffer(source_vao, 0, grid_buffer, 0, 2 * sizeof(float));
    glVertexArrayVertexBuffer(source_vao, 1, instance_buffer, 0, 7 * sizeof(float));
    glVertexArrayBindingDivisor(source_vao, 1, 1);
    // The captured vertices as the G-buffer and pre-pass programs read them: 0 position, 3 albedo.
    const GLuint captured_vao = engine::make_vertex_array({{0, 0, 3, 0}, {3, 0, 3, 3}});
    glVertexArrayVertexBuffer(captured_vao, 0, captured, 0, 6 * sizeof(float));

    // The engine's vertex stage, once per frame, captured interleaved.
    const GLuint deform_program =
        engine::link_program({{GL_VERTEX_SHADER, kDeformVertex}}, [](GLuint program) {
          const char* captured_names[] = {"tf_position", "tf_albedo"};
          glTransformFeedbackVaryings(program, 2, captured_names, GL_INTERLEAVED_ATTRIBS);
        });
    // (A surfaceless context has no default framebuffer: draws need one bound, discard or not.)
    const engine::GBuffer gbuffer(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.framebuffer);
    glUseProgram(deform_program);
    glUniform1f(glGetUniformLocation(deform_program, "u_time"), 0.7f);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured);
    glEnable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(source_vao);
    glBeginTransformFeedback(GL_TRIANGLES);
    glDrawArraysInstanced(GL_TRIANGLES, 0, kVerticesPerInstance, kInstances);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    engine::check_gl("vertex stage");

    const glm::mat4 view = glm::lookAt(glm::vec3(0.3f, 0.4f, 3.2f), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), float(width) / height, 1.0f, 10.0f);
    const auto draw_captured = [&] {
      glBindVertexArray(captured_vao);
      glDrawArrays(GL_TRIANGLES, 0, kInstances * kVerticesPerInstance);
    };

    const GLuint gbuffer_program = engine::make_gbuffer_program();
    const GLfloat background[4] = {0.05f, 0.05f, 0.08f, 1};
    gbuffer.clear(background);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(gbuffer_program);
    engine::set_camera(gbuffer_program, view, projection);
    draw_captured();
    engine::check_gl("G-buffer");

    rsaa::RsaaPass rsaa(rsaa::RsaaSettings{}, width, height);  // the default settings: d3d8x
    const rsaa::RsaaFrame frame{gbuffer.colour, gbuffer.normal, gbuffer.primitive, gbuffer.depth,
                                width,          height,         glm::inverse(projection)};
    rsaa.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
      engine::set_camera(program, view, projection);
      glUniform2f(glGetUniformLocation(program, "u_jitter_ndc"), jitter.x, jitter.y);
      draw_captured();
    });
    const GLuint output = engine::make_texture(GL_RGBA16F, width, height);
    rsaa.resolve(frame, output);

    engine::write_ppm(out_dir + "/02_noaa.ppm", gbuffer.colour, width, height);
    engine::write_ppm(out_dir + "/02_rsaa.ppm", output, width, height);
    engine::check_gl("read-back");
    std::printf("wrote %s/02_rsaa.ppm (%d instances of a deformed strip, RSAA 8x)\n",
                out_dir.c_str(), kInstances);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "02_own_vertex_stage: error: %s\n", e.what());
    return 1;
  }
}
