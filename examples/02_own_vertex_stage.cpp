// Example 02: an engine with its own vertex stage (instancing and a per-vertex deformation) that
// draws RSAA's pre-pass with its own shaders (SMAA-style: the pass's functions included).
//
// One vertex shader serves the G-buffer and the pre-pass. For the pre-pass the engine prepends
// RsaaPass::prepass_glsl() to both stages (the vertex stage after `#define RSAA_INCLUDE_FS 0`),
// calls rsaa_jitter() on its clip position and rsaa_prepass_code() in its fragment stage, and
// draws with render_subsamples_with_own_shaders(). Nothing is baked into a buffer first. The
// G-buffer and the pre-pass number primitives alike (instance * triangles + gl_PrimitiveID + 1):
// gl_PrimitiveID restarts with each instance.
// Usage: 02_own_vertex_stage [OUT_DIR]   writes OUT_DIR/02_noaa.ppm and OUT_DIR/02_rsaa.ppm
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/gbuffer.h"
#include "runtime/rsaa_pass.h"

namespace {

constexpr int kColumns = 24, kInstances = 4;
constexpr int kVerticesPerInstance = kColumns * 6;

// The engine's vertex stage: a flat strip mesh, instanced (per-instance offset, angle, colour),
// bent by a travelling wave. RSAA_PREPASS: the same stage in the pre-pass, jittered by RSAA.
const char* kEngineVertex = R"(
layout(location = 0) in vec2 a_grid;          // mesh vertex in [0, 1]^2
layout(location = 1) in vec4 a_instance;      // xyz offset, w angle
layout(location = 2) in vec3 a_instance_colour;
uniform float u_time;
uniform mat4 u_view, u_projection;
out vec3 v_view_position;
out vec3 v_albedo;
flat out int v_instance;
void main() {
  vec3 p = vec3(a_grid.x * 2.4 - 1.2, a_grid.y * 0.5 - 0.25, 0.0);
  p.z = 0.25 * sin(3.0 * p.x + u_time);       // the deformation
  p.y += 0.15 * sin(2.0 * p.x - u_time);
  float c = cos(a_instance.w), s = sin(a_instance.w);
  vec3 world = vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z) + a_instance.xyz;
  vec4 view = u_view * vec4(world, 1.0);
  v_view_position = view.xyz;
  v_albedo = a_instance_colour;
  v_instance = gl_InstanceID;
#ifdef RSAA_PREPASS
  gl_Position = rsaa_jitter(u_projection * view);
#else
  gl_Position = u_projection * view;
#endif
})";

// The engine's primitive numbering, shared by both fragment stages.
std::string primitive_number_glsl() {
  return "uint engine_primitive(int instance) { return uint(instance) * " +
         std::to_string(kVerticesPerInstance / 3) + "u + uint(gl_PrimitiveID) + 1u; }\n";
}

// The G-buffer: any shading, plus the encoded geometric normal and the primitive number RSAA
// compares (rsaa_common.glsl, put before this text, has rsaa_encode_normal).
const char* kGBufferFragment = R"(
in vec3 v_view_position;
in vec3 v_albedo;
flat in int v_instance;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out uvec2 o_normal;
layout(location = 2) out uint o_primitive;
void main() {
  vec3 n = normalize(cross(dFdx(v_view_position), dFdy(v_view_position)));
  o_colour = vec4(v_albedo * (0.4 + 0.6 * abs(n.z)), 1.0);
  o_normal = rsaa_encode_normal(n);
  o_primitive = engine_primitive(v_instance);
})";

// The pre-pass: the engine's inputs handed to rsaa_prepass_code (rsaa_prepass.glsl, before).
const char* kPrepassFragment = R"(
in vec3 v_view_position;
flat in int v_instance;
layout(location = 0) out uvec4 o_code;
void main() {
  o_code = rsaa_prepass_code(v_view_position, rsaa_face_normal(v_view_position), engine_primitive(v_instance));
})";

void set_frame_uniforms(GLuint program, const glm::mat4& view, const glm::mat4& projection) {
  glUseProgram(program);
  engine::set_camera(program, view, projection);
  glUniform1f(glGetUniformLocation(program, "u_time"), 0.7f);
}

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
    GLuint buffers[2];
    glCreateBuffers(2, buffers);
    glNamedBufferStorage(buffers[0], GLsizeiptr(grid.size() * sizeof(float)), grid.data(), 0);
    glNamedBufferStorage(buffers[1], sizeof instances, instances, 0);
    // Grid vertices at binding 0, one instance record per instance at binding 1.
    const GLuint vao = engine::make_vertex_array({{0, 0, 2, 0}, {1, 1, 4, 0}, {2, 1, 3, 4}});
    glVertexArrayVertexBuffer(vao, 0, buffers[0], 0, 2 * sizeof(float));
    glVertexArrayVertexBuffer(vao, 1, buffers[1], 0, 7 * sizeof(float));
    glVertexArrayBindingDivisor(vao, 1, 1);
    const auto draw_instances = [&] {
      glBindVertexArray(vao);
      glDrawArraysInstanced(GL_TRIANGLES, 0, kVerticesPerInstance, kInstances);
    };

    const glm::mat4 view = glm::lookAt(glm::vec3(0.3f, 0.4f, 3.2f), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), float(width) / height, 1.0f, 10.0f);

    // The engine's 1x frame, drawn by its own stages.
    const std::string rsaa_common = rsaa::rsaa_shader_file("rsaa_common.glsl");
    const GLuint gbuffer_program =
        engine::make_program({{GL_VERTEX_SHADER, kEngineVertex},
                              {GL_FRAGMENT_SHADER, rsaa_common + primitive_number_glsl() + kGBufferFragment}});
    const engine::GBuffer gbuffer(width, height);
    const GLfloat background[4] = {0.05f, 0.05f, 0.08f, 1};
    gbuffer.clear(background);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.framebuffer);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    set_frame_uniforms(gbuffer_program, view, projection);
    draw_instances();
    engine::check_gl("G-buffer");

    // RSAA with the default settings (d3d8x), its pre-pass drawn by the same vertex stage.
    rsaa::RsaaPass rsaa(rsaa::RsaaSettings{}, width, height);
    const std::string prepass = rsaa.prepass_glsl();
    const GLuint prepass_program = engine::make_program(
        {{GL_VERTEX_SHADER, "#define RSAA_INCLUDE_FS 0\n" + prepass + "#define RSAA_PREPASS\n" + kEngineVertex},
         {GL_FRAGMENT_SHADER, prepass + primitive_number_glsl() + kPrepassFragment}});
    const rsaa::RsaaFrame frame{gbuffer.colour, gbuffer.normal, gbuffer.primitive, gbuffer.depth,
                                width,          height,         glm::inverse(projection)};
    rsaa.render_subsamples_with_own_shaders(frame, [&] {
      set_frame_uniforms(prepass_program, view, projection);
      draw_instances();
    });
    const GLuint output = engine::make_texture(GL_RGBA16F, width, height);
    rsaa.resolve(frame, output);

    engine::write_ppm(out_dir + "/02_noaa.ppm", gbuffer.colour, width, height);
    engine::write_ppm(out_dir + "/02_rsaa.ppm", output, width, height);
    engine::check_gl("read-back");
    std::printf("wrote %s/02_rsaa.ppm (%d instances of a deformed strip, RSAA 8x, the engine's own shaders)\n",
                out_dir.c_str(), kInstances);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "02_own_vertex_stage: error: %s\n", e.what());
    return 1;
  }
}
