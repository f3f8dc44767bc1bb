// Example 03: only an rsaa offset table, no rsaa library. The engine classifies subsamples its
// own way (object ids, not the paper's SADP) and resolves with the generated GLSL table
// (share/rsaa/tables/d3d8x.glsl: rsaa_sample_positions[] and rsaa_offsets[], GL window space).
//
// 1. 1x pass: colour + object id. 2. Subsample pass: the geometry once per table sample
// position (instanced, one layer each, jittered so the sample lands on the pixel centre),
// object id only. 3. Post-process: mask bit i = subsample i sees the centre's object; one
// bilinear fetch of the colour at pixel centre + rsaa_offsets[mask].
// Usage: 03_tables_only [OUT_DIR]   writes OUT_DIR/03_noaa.ppm and OUT_DIR/03_rsaa.ppm
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "common/engine.h"

namespace {

const char* kSceneVertex = R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform bool u_subsamples;  // false: the 1x pass; true: instance i = table sample i
out vec3 v_albedo;
flat out uint v_object;
flat out int v_layer;
void main() {
  v_object = uint(gl_VertexID / 3) + 1u;
  v_albedo = vec3(0.2 + 0.3 * float(v_object), 0.6, 1.0 - 0.3 * float(v_object));
  gl_Position = u_view_projection * vec4(a_position, 1.0);
  v_layer = 0;
  if (u_subsamples) {
    // Translate the image so that this subsample (window space) lands on the pixel centre.
    gl_Position.xy -= 2.0 * rsaa_sample_positions[gl_InstanceID] / u_viewport * gl_Position.w;
    v_layer = gl_InstanceID;
  }
})";

// Routes each instance to its own layer of the subsample target.
const char* kSceneGeometry = R"(
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 v_albedo[];
flat in uint v_object[];
flat in int v_layer[];
out vec3 g_albedo;
flat out uint g_object;
void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    gl_Layer = v_layer[0];
    g_albedo = v_albedo[i];
    g_object = v_object[i];
    EmitVertex();
  }
})";

const char* kSceneFragment = R"(
in vec3 g_albedo;
flat in uint g_object;
layout(location = 0) out uint o_object;
layout(location = 1) out vec4 o_colour;
void main() {
  o_object = g_object;
  o_colour = vec4(g_albedo, 1.0);
})";

const char* kFullscreenVertex = R"(
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";

const char* kResolveFragment = R"(
uniform sampler2D u_colour;           // linear filtering: the one bilinear fetch
uniform usampler2D u_centre_object;
uniform usampler2DArray u_subsample_objects;
layout(location = 0) out vec4 o_colour;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint centre = texelFetch(u_centre_object, pixel, 0).x;
  uint mask = 0u;
  for (int i = 0; i < RSAA_TABLE_SAMPLE_COUNT; ++i)
    if (texelFetch(u_subsample_objects, ivec3(pixel, i), 0).x == centre) mask |= 1u << i;
  vec2 at = gl_FragCoord.xy + rsaa_offsets[mask];
  o_colour = textureLod(u_colour, at / vec2(textureSize(u_colour, 0)), 0.0);
})";

}  // namespace

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : ".";
  const int width = 256, height = 192;
  try {
    engine::HeadlessGl context;
    const std::string table = engine::read_text_file(std::string(RSAA_TABLE_DIR) + "/d3d8x.glsl");
    const int samples = 8;

    const std::vector<float> positions = {-1.5f, -1.0f, -0.5f, 1.5f, -0.6f, -0.5f, 0.1f, 1.2f, -0.5f,
                                          -0.8f, 0.9f,  0.3f,  1.0f, 0.2f,  0.3f,  -0.2f, -1.1f, 0.3f};
    GLuint buffer;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(positions.size() * sizeof(float)), positions.data(), 0);
    const GLuint vao = engine::make_vertex_array({{0, 0, 3, 0}});
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, 3 * sizeof(float));
    const glm::mat4 view_projection =
        glm::perspective(glm::radians(45.0f), float(width) / height, 1.0f, 10.0f) *
        glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0));

    // Targets: 1x object id + colour + depth; per subsample an object-id layer + depth layer.
    const GLuint centre_object = engine::make_texture(GL_R32UI, width, height);
    const GLuint colour = engine::make_texture(GL_RGBA16F, width, height, GL_LINEAR);
    const GLuint centre_depth = engine::make_texture(GL_DEPTH_COMPONENT32F, width, height);
    GLuint subsample_objects, subsample_depth;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &subsample_objects);
    glTextureStorage3D(subsample_objects, 1, GL_R32UI, width, height, samples);
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &subsample_depth);
    glTextureStorage3D(subsample_depth, 1, GL_DEPTH_COMPONENT32F, width, height, samples);
    GLuint framebuffers[2];
    glCreateFramebuffers(2, framebuffers);
    const GLuint centre_fb = framebuffers[0], subsample_fb = framebuffers[1];
    glNamedFramebufferTexture(centre_fb, GL_COLOR_ATTACHMENT0, centre_object, 0);
    glNamedFramebufferTexture(centre_fb, GL_COLOR_ATTACHMENT1, colour, 0);
    glNamedFramebufferTexture(centre_fb, GL_DEPTH_ATTACHMENT, centre_depth, 0);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(centre_fb, 2, both);
    glNamedFramebufferTexture(subsample_fb, GL_COLOR_ATTACHMENT0, subsample_objects, 0);  // layered
    glNamedFramebufferTexture(subsample_fb, GL_DEPTH_ATTACHMENT, subsample_depth, 0);
    for (const GLuint fb : framebuffers)
      if (glCheckNamedFramebufferStatus(fb, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("incomplete framebuffer");

    // The table is included before the engine's code that uses it, SMAA-style.
    const GLuint scene_program = engine::make_program({{GL_VERTEX_SHADER, table + kSceneVertex},
                                                       {GL_GEOMETRY_SHADER, kSceneGeometry},
                                                       {GL_FRAGMENT_SHADER, kSceneFragment}});
    const GLuint resolve_program = engine::make_program(
        {{GL_VERTEX_SHADER, kFullscreenVertex}, {GL_FRAGMENT_SHADER, table + kResolveFragment}});

    const GLuint no_object[4] = {0, 0, 0, 0};
    const GLfloat background[4] = {0.9f, 0.9f, 0.9f, 1}, far_depth = 1;
    glClearNamedFramebufferuiv(centre_fb, GL_COLOR, 0, no_object);
    glClearNamedFramebufferfv(centre_fb, GL_COLOR, 1, background);
    glClearNamedFramebufferfv(centre_fb, GL_DEPTH, 0, &far_depth);
    glClearNamedFramebufferuiv(subsample_fb, GL_COLOR, 0, no_object);
    glClearNamedFramebufferfv(subsample_fb, GL_DEPTH, 0, &far_depth);

    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(scene_program);
    glUniformMatrix4fv(glGetUniformLocation(scene_program, "u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    glUniform2f(glGetUniformLocation(scene_program, "u_viewport"), float(width), float(height));
    glBindVertexArray(vao);
    glBindFramebuffer(GL_FRAMEBUFFER, centre_fb);
    glUniform1i(glGetUniformLocation(scene_program, "u_subsamples"), 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindFramebuffer(GL_FRAMEBUFFER, subsample_fb);
    glUniform1i(glGetUniformLocation(scene_program, "u_subsamples"), 1);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, samples);
    glDisable(GL_DEPTH_TEST);

    const GLuint output = engine::make_texture(GL_RGBA16F, width, height);
    GLuint output_fb;
    glCreateFramebuffers(1, &output_fb);
    glNamedFramebufferTexture(output_fb, GL_COLOR_ATTACHMENT0, output, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, output_fb);
    glUseProgram(resolve_program);
    glUniform1i(glGetUniformLocation(resolve_program, "u_colour"), 0);
    glUniform1i(glGetUniformLocation(resolve_program, "u_centre_object"), 1);
    glUniform1i(glGetUniformLocation(resolve_program, "u_subsample_objects"), 2);
    glBindTextureUnit(0, colour);
    glBindTextureUnit(1, centre_object);
    glBindTextureUnit(2, subsample_objects);
    glDrawArrays(GL_TRIANGLES, 0, 3);  // the VAO bound above is ignored: no attributes read
    engine::check_gl("tables-only RSAA");

    engine::write_ppm(out_dir + "/03_noaa.ppm", colour, width, height);
    engine::write_ppm(out_dir + "/03_rsaa.ppm", output, width, height);
    std::printf("wrote %s/03_rsaa.ppm (object-id classification, offsets from d3d8x.glsl)\n",
                out_dir.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "03_tables_only: error: %s\n", e.what());
    return 1;
  }
}
