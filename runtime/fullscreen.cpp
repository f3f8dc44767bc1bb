#include "runtime/fullscreen.h"

#include "runtime/shader_library.h"

namespace rsaa {

gl::Program make_fullscreen_program(const std::string& fragment_name, const std::string& defines) {
  return gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                           {GL_FRAGMENT_SHADER, gl::shader_source(fragment_name)}},
                          defines, fragment_name);
}

void draw_fullscreen_triangle() {
  GLuint id;  // core profile needs a bound VAO even without attributes
  glCreateVertexArrays(1, &id);
  const gl::VertexArray empty(id);
  glBindVertexArray(id);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace rsaa
