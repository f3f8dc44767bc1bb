// The engine's 1x G-buffer in the formats rsaa_pass.h documents, and its G-buffer program: a
// plain vertex stage (world positions in, no model matrix: the engines here bake theirs), a
// geometry stage for the face normal RSAA compares, and a fragment stage writing colour, the
// encoded normal and the primitive id.
#pragma once

#include "common/engine.h"

#include <glm/gtc/type_ptr.hpp>

namespace engine {

struct GBuffer {
  GLuint colour, normal, primitive, depth, framebuffer;

  GBuffer(int width, int height)
      : colour(make_texture(GL_RGBA16F, width, height, GL_LINEAR)),
        normal(make_texture(GL_RG16UI, width, height)),
        primitive(make_texture(GL_R32UI, width, height)),
        depth(make_texture(GL_DEPTH_COMPONENT32F, width, height)) {
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT1, normal, 0);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT2, primitive, 0);
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
    const GLenum attachments[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(framebuffer, 3, attachments);
  }

  void clear(const GLfloat background[4]) const {
    const GLfloat far_depth = 1;
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, background);
    glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 1, zero);  // 0 = background for RSAA
    glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 2, zero);
    glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far_depth);
  }
};

inline const char* kGBufferVertex = R"(
layout(location = 0) in vec3 a_position;
layout(location = 3) in vec3 a_albedo;
uniform mat4 u_view, u_projection;
out vec3 v_view_position;
out vec3 v_albedo;
void main() {
  vec4 view = u_view * vec4(a_position, 1.0);
  v_view_position = view.xyz;
  v_albedo = a_albedo;
  gl_Position = u_projection * view;
})";

// RSAA compares geometric (face) normals: computed per triangle, as the pre-pass does.
inline const char* kGBufferGeometry = R"(
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 v_view_position[];
in vec3 v_albedo[];
out vec3 g_albedo;
flat out vec3 g_face_normal;
void main() {
  vec3 n = normalize(cross(v_view_position[1] - v_view_position[0],
                           v_view_position[2] - v_view_position[0]));
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    gl_PrimitiveID = gl_PrimitiveIDIn;
    g_albedo = v_albedo[i];
    g_face_normal = n;
    EmitVertex();
  }
})";

// Any shading, plus the two values RSAA needs; rsaa_encode_normal comes from the installed
// rsaa_common.glsl, which is put before this text.
inline const char* kGBufferFragment = R"(
in vec3 g_albedo;
flat in vec3 g_face_normal;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out uvec2 o_normal;
layout(location = 2) out uint o_primitive;
void main() {
  o_colour = vec4(g_albedo * (0.4 + 0.6 * abs(g_face_normal.z)), 1.0);
  o_normal = rsaa_encode_normal(g_face_normal);
  o_primitive = uint(gl_PrimitiveID) + 1u;
})";

inline GLuint make_gbuffer_program() {
  const std::string rsaa_common = read_text_file(std::string(RSAA_SHADER_DIR) + "/rsaa_common.glsl");
  return make_program({{GL_VERTEX_SHADER, kGBufferVertex},
                       {GL_GEOMETRY_SHADER, kGBufferGeometry},
                       {GL_FRAGMENT_SHADER, rsaa_common + kGBufferFragment}});
}

// Camera uniforms by the names both the G-buffer program and the RSAA pre-pass use.
inline void set_camera(GLuint program, const glm::mat4& view, const glm::mat4& projection) {
  glUniformMatrix4fv(glGetUniformLocation(program, "u_view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(glGetUniformLocation(program, "u_projection"), 1, GL_FALSE,
                     glm::value_ptr(projection));
}

}  // namespace engine
