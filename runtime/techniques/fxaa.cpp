// fxaa: the 1x frame with its luma beside it (FXAA 3.11 wants luma from the pass before it),
// then the FXAA-style post-process (shaders/fxaa.frag): the single-sample post-process baseline
// beside RSAA.
#include <algorithm>
#include <cmath>

#include "runtime/shader_library.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Fxaa : public Technique {
 public:
  Fxaa(int width, int height, bool edge_pass)
      : edge_pass_(edge_pass),
        colour_(gl::make_texture_2d(GL_RGBA16F, width, height)),
        luma_(gl::make_texture_2d(GL_R16F, width, height)),
        depth_(gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height)),
        frame_(gl::make_framebuffer({{colour_.get()}, {luma_.get()}}, {depth_.get()})),
        shade_(gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                                 {GL_GEOMETRY_SHADER, gl::shader_source("scene.geom")},
                                 {GL_FRAGMENT_SHADER, gl::shader_source("scene_shade.frag")}},
                                "#define FXAA_LUMA\n", "scene shading + FXAA luma")),
        post_(make_fullscreen_program("fxaa.frag", "")),
        edges_(make_fullscreen_program("fxaa_edges.frag", "")) {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    timer_.begin("main");
    clear_to_background(frame_.get(), scene);
    const glm::vec3 bg = scene.background();  // fxaa_luma of the background
    const GLfloat bg_luma = std::sqrt(0.299f * std::max(0.0f, bg.r) + 0.587f * std::max(0.0f, bg.g) +
                                      0.114f * std::max(0.0f, bg.b));
    glClearNamedFramebufferfv(frame_.get(), GL_COLOR, 1, &bg_luma);
    glBindFramebuffer(GL_FRAMEBUFFER, frame_.get());
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, shade_.get());
    timer_.end();
    timer_.begin("post-process");
    for (const GLuint program : {post_.get(), edges_.get()}) {
      glProgramUniform1i(program, glGetUniformLocation(program, "u_colour"), 0);
      glProgramUniform1i(program, glGetUniformLocation(program, "u_luma"), 1);
      glProgramUniform2f(program, glGetUniformLocation(program, "u_viewport"), float(view.width),
                         float(view.height));
    }
    glBindTextureUnit(0, colour_.get());
    glBindTextureUnit(1, luma_.get());
    if (edge_pass_) {
      // The kept pixels as they are: a copy of the image; then the edge pass writes depth (the
      // full-screen triangle's, into the main pass's depth buffer, no longer needed) where FXAA
      // may change a pixel, and fxaa.frag runs there only (GL_GEQUAL passes the triangle's depth).
      glCopyImageSubData(colour_.get(), GL_TEXTURE_2D, 0, 0, 0, 0, output, GL_TEXTURE_2D, 0, 0, 0, 0, view.width,
                         view.height, 1);
      const GLuint edge_fb = edge_target_.get({}, {depth_.get()});
      glBindFramebuffer(GL_FRAMEBUFFER, edge_fb);
      glViewport(0, 0, view.width, view.height);
      const GLfloat far_depth = 1.0f;
      glDepthMask(GL_TRUE);
      glClearNamedFramebufferfv(edge_fb, GL_DEPTH, 0, &far_depth);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_ALWAYS);
      glUseProgram(edges_.get());
      draw_fullscreen_triangle();
      glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}, {depth_.get()}));
      glDepthFunc(GL_GEQUAL);
      glDepthMask(GL_FALSE);
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}));
      glViewport(0, 0, view.width, view.height);
    }
    glUseProgram(post_.get());
    draw_fullscreen_triangle();
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
    gl::check("FXAA");
  }

  double bytes_per_pixel() const override { return 8 + 2 + 4 + 8; }  // colour, luma, depth, output

 private:
  bool edge_pass_;
  gl::Texture colour_, luma_, depth_;
  gl::Framebuffer frame_;
  gl::Program shade_, post_, edges_;
  gl::CachedFramebuffer output_target_, edge_target_;
};

}  // namespace

std::unique_ptr<Technique> make_fxaa(int width, int height, bool edge_pass) {
  return std::make_unique<Fxaa>(width, height, edge_pass);
}

TechniqueKind fxaa_technique() {
  return {"fxaa", "an FXAA-style post-process of the 1x frame",
          [](const TechniqueOptions& o) { reject_samples(o); },
          [](const TechniqueOptions&) { return std::string("fxaa"); },
          [](const TechniqueOptions&, int width, int height) { return make_fxaa(width, height); }};
}

}  // namespace rsaa
