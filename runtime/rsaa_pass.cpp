#include "runtime/rsaa_pass.h"

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <type_traits>

#include <glm/gtc/type_ptr.hpp>

#include "core/conventions.h"
#include "runtime/camera.h"
#include "runtime/gl_context.h"
#include "runtime/fullscreen.h"
#include "runtime/gl_objects.h"
#include "runtime/shader_library.h"

namespace rsaa {

static_assert(std::is_same_v<GlName, GLuint>, "rsaa_pass.h names GL objects as unsigned int");

struct RsaaTargets::Objects {
  gl::Texture colour, normal, primitive, depth;
  gl::Framebuffer framebuffer;
};

struct RsaaPass::Objects {
  gl::Texture codes, subsample_depth;
  std::vector<gl::Framebuffer> subsample_targets;
  gl::Program subsample_program, post_program;
  gl::CachedFramebuffer resolve_target;
};

namespace {

SamplePattern pattern_named(const std::string& name) {
  if (name == "gl4x") return query_gl_sample_pattern(4);
  if (name == "d3d4x" || name == "d3d8x") return builtin_pattern(name);
  throw std::invalid_argument("RSAA pattern '" + name + "' is not one of d3d4x, d3d8x, gl4x");
}

// The sample positions baked into a GLSL table (GL window space), back in pixel space.
std::vector<Vec2> table_sample_positions(const std::string& glsl) {
  const std::size_t start = glsl.find("rsaa_sample_positions[");
  const std::string body = glsl.substr(start, glsl.find(';', start) - start);
  static const std::regex pair(R"(vec2\(([-+0-9.eE]+), ([-+0-9.eE]+)\))");
  std::vector<Vec2> out;
  for (auto it = std::sregex_iterator(body.begin(), body.end(), pair); it != std::sregex_iterator(); ++it)
    out.push_back(gl_to_pixel({std::stod((*it)[1]), std::stod((*it)[2])}));
  return out;
}

GLenum code_format(int bits) {
  switch (bits) {
    case 8: return GL_R8UI;
    case 16: return GL_R16UI;
    case 32: return GL_R32UI;
  }
  throw std::invalid_argument("RSAA code bits must be 8, 16 or 32, not " + std::to_string(bits));
}

void set_uniform(GLuint program, const char* name, int value) {
  glProgramUniform1i(program, glGetUniformLocation(program, name), value);
}

void set_frame_uniforms(GLuint program, const RsaaFrame& frame, float threshold) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "u_inverse_projection"), 1,
                            GL_FALSE, glm::value_ptr(frame.inverse_projection));
  glProgramUniform2f(program, glGetUniformLocation(program, "u_viewport"), float(frame.width),
                     float(frame.height));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_threshold"), threshold);
}

// A missing or mismatched texture in the engine's frame is an error naming the field.
void validate_frame(const RsaaFrame& frame, int width, int height) {
  if (frame.width != width || frame.height != height)
    throw std::invalid_argument("RsaaFrame is " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + ", the RsaaPass was made for " +
                                std::to_string(width) + "x" + std::to_string(height));
  gl::require_texture(frame.colour, GL_RGBA16F, width, height, "RsaaFrame::colour");
  gl::require_texture(frame.centre_normal, GL_RG16UI, width, height, "RsaaFrame::centre_normal");
  gl::require_texture(frame.centre_primitive, GL_R32UI, width, height, "RsaaFrame::centre_primitive");
  gl::require_texture(frame.centre_depth, GL_DEPTH_COMPONENT32F, width, height,
                      "RsaaFrame::centre_depth");
}

// The outside pixel of each subsample, converted to window space (+y up).
glm::ivec2 window_step(Vec2 sample) {
  const PixelStep s = outside_pixel_towards(sample);
  const Vec2 gl = pixel_to_gl({double(s.i), double(s.j)});
  return {int(gl.x), int(gl.y)};
}

}  // namespace

RsaaTargets::RsaaTargets(int width, int height)
    : width_(width), height_(height), gl_(std::make_unique<Objects>()) {
  gl_->colour = gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR);
  gl_->normal = gl::make_texture_2d(GL_RG16UI, width, height);
  gl_->primitive = gl::make_texture_2d(GL_R32UI, width, height);
  gl_->depth = gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
  gl_->framebuffer = gl::make_framebuffer(
      {{gl_->colour.get()}, {gl_->normal.get()}, {gl_->primitive.get()}}, {gl_->depth.get()});
}
RsaaTargets::~RsaaTargets() = default;
RsaaTargets::RsaaTargets(RsaaTargets&&) noexcept = default;
RsaaTargets& RsaaTargets::operator=(RsaaTargets&&) noexcept = default;

void RsaaTargets::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer.get()); }
GlName RsaaTargets::colour() const { return gl_->colour.get(); }

void RsaaTargets::clear(const float background[3]) const {
  const GLfloat colour[4] = {background[0], background[1], background[2], 1.0f};
  const GLuint zero[4] = {0, 0, 0, 0};
  const GLfloat far_depth = 1.0f;
  const GLuint framebuffer = gl_->framebuffer.get();
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, colour);
  glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 1, zero);
  glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 2, zero);
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far_depth);
}

RsaaFrame RsaaTargets::frame(const glm::mat4& inverse_projection) const {
  return {gl_->colour.get(), gl_->normal.get(), gl_->primitive.get(), gl_->depth.get(),
          width_, height_, inverse_projection};
}

SamplePattern query_gl_sample_pattern(int samples) {
  const gl::Texture texture = gl::make_texture_2d_multisample(GL_RGBA8, 1, 1, samples);
  const gl::Framebuffer fb = gl::make_framebuffer({{texture.get()}});
  glBindFramebuffer(GL_FRAMEBUFFER, fb.get());
  std::vector<Vec2> positions;
  for (int i = 0; i < samples; ++i) {
    GLfloat p[2];
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), p);
    positions.push_back({p[0], p[1]});
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::check("reading the driver's sample positions");
  return pattern_from_gl_positions("gl" + std::to_string(samples) + "x", positions);
}

RsaaPass::RsaaPass(const RsaaSettings& settings, int width, int height)
    : settings_(settings),
      pattern_(pattern_named(settings.pattern)),
      width_(width),
      height_(height),
      gl_(std::make_unique<Objects>()) {
  if (settings.auth < 0 || settings.auth > 2)
    throw std::invalid_argument("RSAA auth must be 0, 1 or 2");
  if (!(settings.threshold >= 0.0f)) throw std::invalid_argument("RSAA threshold must be >= 0");
  const std::string table = gl::table_glsl(pattern_.name);
  const std::vector<Vec2> baked = table_sample_positions(table);
  if (baked.size() != pattern_.positions.size())
    throw std::runtime_error("tables/" + pattern_.name + ".glsl has " + std::to_string(baked.size()) +
                             " samples; the pattern has " + std::to_string(pattern_.size()));
  for (int i = 0; i < pattern_.size(); ++i)
    if (length(baked[i] - pattern_.positions[i]) > 1e-6)
      throw std::runtime_error("tables/" + pattern_.name + ".glsl was trained for other sample " +
                               "positions than this driver's (sample " + std::to_string(i) +
                               "); retrain it with rsaa train --pattern " + pattern_.name);

  const int n = pattern_.size();
  gl_->codes = gl::make_texture_2d_array(code_format(settings.code_bits), width, height, n);
  gl_->subsample_depth = gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
  for (int i = 0; i < n; ++i)
    gl_->subsample_targets.push_back(
        gl::make_framebuffer({{gl_->codes.get(), i}}, {gl_->subsample_depth.get()}));

  std::string defines = "#define RSAA_SAMPLE_COUNT " + std::to_string(n) + "\n" +
                        "#define RSAA_AUTH " + std::to_string(settings.auth) + "\n" +
                        "#define RSAA_CODE_BITS " + std::to_string(settings.code_bits) + "\n";
  if (settings.similarity == "depth") defines += "#define RSAA_SIMILARITY_DEPTH\n";
  else if (settings.similarity == "sadp-plane") defines += "#define RSAA_SIMILARITY_SADP_PLANE\n";
  else if (settings.similarity != "sadp")
    throw std::invalid_argument("RSAA similarity '" + settings.similarity +
                                "' is not one of sadp, depth, sadp-plane");
  gl_->subsample_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                                         {GL_GEOMETRY_SHADER, gl::shader_source("scene.geom")},
                                         {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_subsample.frag")}},
                                        defines, "RSAA pre-pass");
  if (settings.output_mask) defines += "#define RSAA_OUTPUT_MASK\n";
  gl_->post_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                    {GL_FRAGMENT_SHADER, table + gl::shader_source("rsaa_post.frag")}},
                                   defines, "RSAA post-process");
  std::vector<glm::ivec2> steps;
  for (const Vec2& s : pattern_.positions) steps.push_back(window_step(s));
  const GLuint post = gl_->post_program.get();
  glProgramUniform2iv(post, glGetUniformLocation(post, "u_neighbours"), n, glm::value_ptr(steps[0]));
  if (settings.auth == 1) {
    std::vector<GLint> representative(std::size_t(1) << n);
    for (std::size_t mask = 0; mask < representative.size(); ++mask)
      representative[mask] = std::max(0, representative_dissimilar(pattern_, Mask(mask)));
    glProgramUniform1iv(post, glGetUniformLocation(post, "u_representative"),
                        GLsizei(representative.size()), representative.data());
  }
  gl::check("creating the RSAA pass");
}
RsaaPass::~RsaaPass() = default;
RsaaPass::RsaaPass(RsaaPass&&) noexcept = default;
RsaaPass& RsaaPass::operator=(RsaaPass&&) noexcept = default;

void RsaaPass::render_subsamples(const RsaaFrame& frame, const DrawGeometry& draw_geometry) {
  validate_frame(frame, width_, height_);
  const gl::SavedState saved(4);
  gl::set_pass_state(true);  // before the clears: they obey the engine's scissor and masks
  const GLuint program = gl_->subsample_program.get();
  set_frame_uniforms(program, frame, settings_.threshold);
  set_uniform(program, "u_centre_normal", 1);
  set_uniform(program, "u_centre_primitive", 2);
  set_uniform(program, "u_centre_depth", 3);
  glBindTextureUnit(1, frame.centre_normal);
  glBindTextureUnit(2, frame.centre_primitive);
  glBindTextureUnit(3, frame.centre_depth);
  const GLint neighbour = glGetUniformLocation(program, "u_neighbour");
  for (int i = 0; i < pattern_.size(); ++i) {
    const GLuint fb = gl_->subsample_targets[i].get();
    const GLuint zero[4] = {0, 0, 0, 0};
    const GLfloat far_depth = 1.0f;
    glClearNamedFramebufferuiv(fb, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    const glm::ivec2 step = window_step(pattern_.positions[i]);
    glProgramUniform2i(program, neighbour, step.x, step.y);
    const Vec2 s = pattern_.positions[i];
    gl::set_pass_state(true);  // again: the previous callback may have changed it
    glViewport(0, 0, frame.width, frame.height);
    glUseProgram(program);
    draw_geometry(program, jitter_ndc_for_sample(s.x, s.y, frame.width, frame.height));
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) != program)
      throw std::logic_error("RSAA pre-pass: the draw callback drew with program " +
                             std::to_string(current) + ", not the pre-pass program " +
                             std::to_string(program) + " it was given");
  }
  gl::check("RSAA pre-pass");
}

void RsaaPass::resolve(const RsaaFrame& frame, GLuint output, GLuint mask_output) {
  validate_frame(frame, width_, height_);
  gl::require_texture(output, GL_RGBA16F, width_, height_, "RsaaPass::resolve output");
  if (settings_.output_mask && mask_output)
    gl::require_texture(mask_output, GL_R32UI, width_, height_, "RsaaPass::resolve mask_output");
  const gl::SavedState saved(4);
  gl::set_pass_state(false);
  std::vector<gl::Attachment> targets = {{output}};
  if (settings_.output_mask) {
    if (!mask_output) throw std::invalid_argument("RSAA resolve: output_mask set but no mask texture");
    targets.push_back({mask_output});
  }
  const GLuint fb = gl_->resolve_target.get(targets);
  const GLuint program = gl_->post_program.get();
  set_frame_uniforms(program, frame, settings_.threshold);
  set_uniform(program, "u_colour", 0);
  set_uniform(program, "u_centre_normal", 1);
  set_uniform(program, "u_centre_depth", 2);
  set_uniform(program, "u_codes", 3);
  glBindTextureUnit(0, frame.colour);
  glBindTextureUnit(1, frame.centre_normal);
  glBindTextureUnit(2, frame.centre_depth);
  glBindTextureUnit(3, gl_->codes.get());
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, frame.width, frame.height);
  glUseProgram(program);
  draw_fullscreen_triangle();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::check("RSAA post-process");
}

}  // namespace rsaa
