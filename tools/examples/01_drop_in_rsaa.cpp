// Example 01: RSAA dropped into an "engine" that owns its geometry, shaders and targets.
//
// The engine draws two overlapping triangles into its own 1x G-buffer (colour, compressed
// geometric normal, primitive id, depth), then hands the targets to rsaa::RsaaPass, drawing its
// geometry once per subsample through a callback, and resolves into its own output texture.
// Usage: 01_drop_in_rsaa [OUT.png]   (default: drop_in_rsaa.png)
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/image_io.h"
#include "runtime/gl_context.h"
#include "runtime/render.h"
#include "runtime/rsaa_pass.h"
#include "runtime/shader_library.h"

namespace {

// The engine's G-buffer shader: any shading, plus the two values RSAA needs. It includes the
// shared RSAA GLSL for rsaa_encode_normal().
const char* kVertex = R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_view, u_projection;
uniform vec2 u_jitter_ndc;
out VertexData { vec3 view_position; vec3 view_normal; vec2 uv; vec3 albedo; float filter_alpha; } v_out;
void main() {
  vec4 view = u_view * vec4(a_position, 1.0);
  v_out.view_position = view.xyz;
  v_out.view_normal = vec3(0, 0, 1);
  v_out.uv = vec2(0);
  v_out.albedo = vec3(a_position.z > 0.0 ? 0.9 : 0.1, 0.3, a_position.z > 0.0 ? 0.1 : 0.8);
  v_out.filter_alpha = 1.0;
  gl_Position = u_projection * view + vec4(u_jitter_ndc, 0, 0) * (u_projection * view).w;
})";

const char* kFragment = R"(
in FragmentData { vec3 view_position; vec3 view_normal; vec2 uv; vec3 albedo; float filter_alpha; flat vec3 face_normal; } f_in;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out uvec2 o_normal;
layout(location = 2) out uint o_primitive;
void main() {
  o_colour = vec4(f_in.albedo, 1.0);
  o_normal = rsaa_encode_normal(f_in.face_normal);
  o_primitive = uint(gl_PrimitiveID) + 1u;
})";

}  // namespace

int main(int argc, char** argv) {
  using namespace rsaa;
  const std::string out = argc > 1 ? argv[1] : "drop_in_rsaa.png";
  const int width = 256, height = 192;
  try {
    gl::HeadlessContext context;

    // The engine's geometry: two triangles at different depths, positions only.
    const std::vector<float> positions = {-1.5f, -1.0f, -0.5f, 1.5f, -0.6f, -0.5f, 0.1f, 1.2f, -0.5f,
                                          -0.8f, 0.9f,  0.3f,  1.0f, 0.2f,  0.3f,  -0.2f, -1.1f, 0.3f};
    GLuint buffer, vao;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(positions.size() * sizeof(float)), positions.data(), 0);
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, 3 * sizeof(float));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 0, 0);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), float(width) / height, 1.0f, 10.0f);
    const auto draw_geometry = [&](GLuint program, glm::vec2 jitter) {
      glUseProgram(program);
      glUniformMatrix4fv(glGetUniformLocation(program, "u_view"), 1, GL_FALSE, glm::value_ptr(view));
      glUniformMatrix4fv(glGetUniformLocation(program, "u_projection"), 1, GL_FALSE, glm::value_ptr(projection));
      glUniform2f(glGetUniformLocation(program, "u_jitter_ndc"), jitter.x, jitter.y);
      glViewport(0, 0, width, height);
      glEnable(GL_DEPTH_TEST);
      glBindVertexArray(vao);
      glDrawArrays(GL_TRIANGLES, 0, 6);
      glDisable(GL_DEPTH_TEST);
    };

    // The engine's 1x G-buffer in the formats RsaaPass documents.
    const gl::Texture colour = gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR);
    const gl::Texture normal = gl::make_texture_2d(GL_RG16UI, width, height);
    const gl::Texture primitive = gl::make_texture_2d(GL_R32UI, width, height);
    const gl::Texture depth = gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
    const gl::Framebuffer gbuffer =
        gl::make_framebuffer({{colour.get()}, {normal.get()}, {primitive.get()}}, {depth.get()});
    const gl::Program engine_program = gl::make_program(
        {{GL_VERTEX_SHADER, kVertex},
         {GL_GEOMETRY_SHADER, gl::shader_source("scene.geom")},
         {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_common.glsl") + kFragment}},
        "", "engine G-buffer");
    const GLfloat background[4] = {0.9f, 0.9f, 0.9f, 1}, far_depth = 1;
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(gbuffer.get(), GL_COLOR, 0, background);
    glClearNamedFramebufferuiv(gbuffer.get(), GL_COLOR, 1, zero);
    glClearNamedFramebufferuiv(gbuffer.get(), GL_COLOR, 2, zero);
    glClearNamedFramebufferfv(gbuffer.get(), GL_DEPTH, 0, &far_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.get());
    draw_geometry(engine_program.get(), {0, 0});

    // RSAA: 8 subsamples, SADP, post-pass authentication.
    RsaaSettings settings;
    settings.auth = 1;
    RsaaPass rsaa(settings, width, height);
    const RsaaFrame frame{colour.get(), normal.get(), primitive.get(), depth.get(),
                          width, height, glm::inverse(projection)};
    rsaa.render_subsamples(frame, draw_geometry);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
    rsaa.resolve(frame, output.get());

    write_image(out, read_back_image(output.get(), width, height));
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &buffer);
    std::printf("wrote %s (%dx%d, RSAA 8x SADP auth 1 on the engine's own G-buffer)\n", out.c_str(),
                width, height);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "01_drop_in_rsaa: error: %s\n", e.what());
    return 1;
  }
}
