// Example 01: RSAA dropped into an "engine" that owns its context, GL loader, geometry, shaders
// and targets (common/: plain EGL and the Khronos headers, no epoxy, no rsaa GL wrapper).
//
// The engine draws two overlapping triangles into its own 1x G-buffer (colour, compressed
// geometric normal, primitive id, depth), hands the four textures to rsaa::RsaaPass, draws its
// geometry once per subsample through the pass's callback, and resolves into its own texture.
// Usage: 01_drop_in_rsaa [OUT_DIR]   writes OUT_DIR/01_noaa.ppm and OUT_DIR/01_rsaa.ppm
#include <glm/gtc/matrix_transform.hpp>

#include "common/gbuffer.h"
#include "runtime/rsaa_pass.h"

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : ".";
  const int width = 256, height = 192;
  try {
    engine::HeadlessGl context;

    // The engine's geometry: two triangles at different depths; positions (0), albedo (3).
    const std::vector<float> vertices = {
        -1.5f, -1.0f, -0.5f, 0.1f, 0.3f, 0.8f,  1.5f, -0.6f, -0.5f, 0.1f, 0.3f, 0.8f,
        0.1f,  1.2f,  -0.5f, 0.1f, 0.3f, 0.8f,  -0.8f, 0.9f, 0.3f,  0.9f, 0.3f, 0.1f,
        1.0f,  0.2f,  0.3f,  0.9f, 0.3f, 0.1f,  -0.2f, -1.1f, 0.3f, 0.9f, 0.3f, 0.1f};
    GLuint buffer;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), 0);
    const GLuint vao = engine::make_vertex_array({{0, 0, 3, 0}, {3, 0, 3, 3}});
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, 6 * sizeof(float));
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), float(width) / height, 1.0f, 10.0f);

    // The engine's 1x frame.
    const engine::GBuffer gbuffer(width, height);
    const GLuint gbuffer_program = engine::make_gbuffer_program();
    const GLfloat background[4] = {0.9f, 0.9f, 0.9f, 1};
    gbuffer.clear(background);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.framebuffer);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(gbuffer_program);
    engine::set_camera(gbuffer_program, view, projection);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    engine::check_gl("G-buffer");

    // RSAA: 8 subsamples, the default similarity, post-pass authentication. The callback draws
    // the same geometry with the pre-pass program it is given (uniforms as rsaa_pass.h lists).
    rsaa::RsaaSettings settings;
    settings.auth = 1;
    rsaa::RsaaPass rsaa(settings, width, height);
    const rsaa::RsaaFrame frame{gbuffer.colour, gbuffer.normal, gbuffer.primitive, gbuffer.depth,
                                width,          height,         glm::inverse(projection)};
    rsaa.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
      engine::set_camera(program, view, projection);
      glUniform2f(glGetUniformLocation(program, "u_jitter_ndc"), jitter.x, jitter.y);
      glBindVertexArray(vao);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    });
    const GLuint output = engine::make_texture(GL_RGBA16F, width, height);
    rsaa.resolve(frame, output);

    // The pass restored the engine's state: its G-buffer framebuffer and program are still bound.
    GLint bound_framebuffer = 0, bound_program = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound_framebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &bound_program);
    if (GLuint(bound_framebuffer) != gbuffer.framebuffer || GLuint(bound_program) != gbuffer_program)
      throw std::runtime_error("the RSAA pass did not restore the engine's GL state");

    engine::write_ppm(out_dir + "/01_noaa.ppm", gbuffer.colour, width, height);
    engine::write_ppm(out_dir + "/01_rsaa.ppm", output, width, height);
    engine::check_gl("read-back");
    std::printf("wrote %s/01_rsaa.ppm (%dx%d, RSAA 8x auth 1 on the engine's G-buffer)\n",
                out_dir.c_str(), width, height);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "01_drop_in_rsaa: error: %s\n", e.what());
    return 1;
  }
}
