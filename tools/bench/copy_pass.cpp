#include "tools/bench/copy_pass.h"

#include "runtime/gl_context.h"
#include "runtime/pass_timer.h"
#include "runtime/scene_renderer.h"
#include "runtime/shader_library.h"

namespace rsaa::bench {
namespace {

// Kept here, not in shaders/: it is a measuring stick of the bench, not part of any technique.
constexpr const char* kCopyFragment = R"(
uniform sampler2D u_source;
layout(location = 0) out vec4 o_colour;
void main() { o_colour = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0); }
)";

}  // namespace

CopyPass::CopyPass(int width, int height)
    : width_(width),
      height_(height),
      target_(gl::make_texture_2d(GL_RGBA8, width, height)),
      framebuffer_(gl::make_framebuffer({{target_.get()}})),
      program_(gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                 {GL_FRAGMENT_SHADER, kCopyFragment}},
                                "", "bench copy pass")) {
  glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_source"), 0);
}

double CopyPass::time_ms(GLuint source) {
  PassTimer timer;
  timer.begin("copy");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, width_, height_);
  glBindTextureUnit(0, source);
  glUseProgram(program_.get());
  draw_fullscreen_triangle();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  timer.end();
  gl::check("bench copy pass");
  return timer.collect().front().wall_milliseconds;
}

}  // namespace rsaa::bench
