// agaa --samples 4|8|16 [--agaa-aggregates 1-4] [--agaa-k-pixels 4 | --agaa-k 0.1]: Aggregate
// G-Buffer Anti-Aliasing (seed 001) with c aggregates (2 by default). (1) Visibility pre-pass: per sample depth, facet normal and primitive id, from
// hardware 4x MSAA or 8 or 16 jittered single-sample passes (the d3d8x or d3d16x positions). (2) Aggregate
// definition: a fullscreen pass clusters each pixel's samples (core/reference/agaa.h). (3) Aggregate
// G-buffer: the scene drawn again with conservative expansion; each fragment blends its shading
// inputs, weighted by its visible samples per aggregate, into that aggregate's two targets.
// (4) Shading once per aggregate (Toksvig-filtered specular) and resolve.
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/reference/agaa.h"
#include "core/rsaa/conventions.h"
#include "runtime/camera.h"
#include "runtime/shader_library.h"
#include "runtime/technique_testing.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Agaa : public Technique {
 public:
  Agaa(int samples, AgaaSettings settings, float k_pixels, int width, int height)
      : samples_(samples),
        settings_(settings),
        k_pixels_(k_pixels),
        pattern_(samples == 4   ? query_gl_sample_pattern(4)
                 : samples == 8 ? builtin_pattern("d3d8x")
                                : builtin_pattern("d3d16x")),
        meta_(gl::make_texture_2d(GL_RG32UI, width, height)),
        define_(make_fullscreen_program("agaa_define.frag", defines())),
        accumulate_(gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                                      {GL_GEOMETRY_SHADER, gl::shader_source("coverage_fragments.geom")},
                                      {GL_FRAGMENT_SHADER, gl::shader_source("agaa_accumulate.frag")}},
                                     defines(), "agaa accumulation")),
        resolve_(make_fullscreen_program("agaa_resolve.frag", "")) {
    if (samples == 4) {
      depth_ = gl::make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, width, height, 4);
      normal_ = gl::make_texture_2d_multisample(GL_RG16UI, width, height, 4);
      primitive_ = gl::make_texture_2d_multisample(GL_R32UI, width, height, 4);
      prepass_.push_back(gl::make_framebuffer({{0}, {normal_.get()}, {primitive_.get()}}, {depth_.get()}));
    } else {
      depth_ = gl::make_texture_2d_array(GL_DEPTH_COMPONENT32F, width, height, samples);
      normal_ = gl::make_texture_2d_array(GL_RG16UI, width, height, samples);
      primitive_ = gl::make_texture_2d_array(GL_R32UI, width, height, samples);
      for (int s = 0; s < samples; ++s)
        prepass_.push_back(
            gl::make_framebuffer({{0}, {normal_.get(), s}, {primitive_.get(), s}}, {depth_.get(), s}));
    }
    define_target_ = gl::make_framebuffer({{meta_.get()}});
    std::vector<gl::Attachment> targets;
    for (int i = 0; i < 2 * settings.aggregates; ++i) {
      aggregate_.push_back(gl::make_texture_2d(GL_RGBA32F, width, height));
      targets.push_back({aggregate_.back().get()});
    }
    accumulate_target_ = gl::make_framebuffer(targets);

    std::vector<float> offsets;  // window space: pixel-space y flipped
    for (const Vec2& s : pattern_.positions) offsets.insert(offsets.end(), {float(s.x), float(-s.y)});
    for (GLuint p : {define_.get(), accumulate_.get()}) {
      glProgramUniform1i(p, glGetUniformLocation(p, "u_samples"), samples);
      glProgramUniform1i(p, glGetUniformLocation(p, "u_sample_depth"), 1);
      glProgramUniform1i(p, glGetUniformLocation(p, "u_sample_normal"), 2);
      glProgramUniform1i(p, glGetUniformLocation(p, "u_sample_primitive"), 3);
    }
    GLuint p = define_.get();
    glProgramUniform2fv(p, glGetUniformLocation(p, "u_sample_offsets"), samples, offsets.data());
    glProgramUniform1f(p, glGetUniformLocation(p, "u_k"), settings.k);
    glProgramUniform1f(p, glGetUniformLocation(p, "u_min_separation"), settings.min_separation);
    glProgramUniform1i(accumulate_.get(), glGetUniformLocation(accumulate_.get(), "u_meta"), 4);
    p = resolve_.get();
    glProgramUniform1i(p, glGetUniformLocation(p, "u_aggregates"), settings.aggregates);
    glProgramUniform1i(define_.get(), glGetUniformLocation(define_.get(), "u_aggregates"), settings.aggregates);
    for (int a = 0; a < 4; ++a) {  // unused samplers of the array still need distinct units
      const int unit = 5 + 2 * std::min(a, settings.aggregates - 1);
      glProgramUniform1i(p, glGetUniformLocation(p, ("u_albedo[" + std::to_string(a) + "]").c_str()), unit);
      glProgramUniform1i(p, glGetUniformLocation(p, ("u_geometry[" + std::to_string(a) + "]").c_str()), unit + 1);
    }
    gl::check("agaa setup");
  }

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    const glm::mat4 inverse_projection = glm::inverse(view.projection);
    timer_.begin("pre-pass");
    const GLuint zero[4] = {0, 0, 0, 0};
    const GLfloat far = 1.0f;
    for (int s = 0; s < int(prepass_.size()); ++s) {
      const GLuint fb = prepass_[s].get();
      glClearNamedFramebufferuiv(fb, GL_COLOR, 1, zero);
      glClearNamedFramebufferuiv(fb, GL_COLOR, 2, zero);
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far);
      glBindFramebuffer(GL_FRAMEBUFFER, fb);
      const Vec2 at = pattern_.positions[s];
      const glm::vec2 jitter = samples_ == 4 ? glm::vec2(0.0f) : jitter_ndc_for_sample(at.x, at.y, view.width, view.height);
      if (samples_ == 4) glEnable(GL_MULTISAMPLE);
      SceneRenderer::draw(scene, view, jitter, renderer_.gbuffer_program());
    }
    timer_.end();

    timer_.begin("aggregates");
    bind_samples();
    GLuint p = define_.get();
    settings_.k_per_depth = k_pixels_ > 0.0f ? agaa_k_per_depth(k_pixels_, view.projection[1][1], view.height) : 0.0f;
    glProgramUniform1f(p, glGetUniformLocation(p, "u_k_per_depth"), settings_.k_per_depth);
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_inverse_projection"), 1, GL_FALSE,
                              glm::value_ptr(inverse_projection));
    glProgramUniform2f(p, glGetUniformLocation(p, "u_viewport"), float(view.width), float(view.height));
    glBindFramebuffer(GL_FRAMEBUFFER, define_target_.get());
    glViewport(0, 0, view.width, view.height);
    glUseProgram(p);
    draw_fullscreen_triangle();
    timer_.end();

    timer_.begin("main");
    const GLfloat none[4] = {0, 0, 0, 0};
    for (int i = 0; i < int(aggregate_.size()); ++i) glClearNamedFramebufferfv(accumulate_target_.get(), GL_COLOR, i, none);
    glBindTextureUnit(4, meta_.get());
    glProgramUniform2f(accumulate_.get(), glGetUniformLocation(accumulate_.get(), "u_viewport"), float(view.width),
                       float(view.height));
    glBindFramebuffer(GL_FRAMEBUFFER, accumulate_target_.get());
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, accumulate_.get());
    glDisable(GL_BLEND);
    timer_.end();

    timer_.begin("resolve");
    p = resolve_.get();
    for (int i = 0; i < int(aggregate_.size()); ++i) glBindTextureUnit(5 + i, aggregate_[i].get());
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_inverse_projection"), 1, GL_FALSE,
                              glm::value_ptr(inverse_projection));
    glProgramUniform2f(p, glGetUniformLocation(p, "u_viewport"), float(view.width), float(view.height));
    const glm::vec3 bg = scene.background();
    glProgramUniform3f(p, glGetUniformLocation(p, "u_background"), bg.r, bg.g, bg.b);
    glProgramUniform1i(p, glGetUniformLocation(p, "u_filtered_diffuse"), settings_.filtered_diffuse);
    glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}));
    glUseProgram(p);
    draw_fullscreen_triangle();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timer_.end();
    gl::check("agaa");
  }

  // Per sample: depth 4 + normal 4 + primitive id 4; per aggregate 2 x RGBA32F; metadata 8.
  double bytes_per_pixel() const override { return 12.0 * samples_ + 32.0 * settings_.aggregates + 8.0; }

  AgaaFrameData read_back(const View& view) const {
    if (samples_ == 4) throw std::logic_error("agaa: multisampled buffers cannot be read back");
    const int w = view.width, h = view.height, n = samples_;
    const std::size_t pixels = std::size_t(w) * h;
    std::vector<float> depth(pixels * n);
    std::vector<std::uint16_t> normal(pixels * n * 2);
    std::vector<std::uint32_t> primitive(pixels * n), meta(pixels * 2);
    glGetTextureImage(depth_.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * 4), depth.data());
    glGetTextureImage(normal_.get(), 0, GL_RG_INTEGER, GL_UNSIGNED_SHORT, GLsizei(normal.size() * 2), normal.data());
    glGetTextureImage(primitive_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(primitive.size() * 4),
                      primitive.data());
    glGetTextureImage(meta_.get(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, GLsizei(meta.size() * 4), meta.data());
    const int c = settings_.aggregates;
    std::vector<std::vector<float>> sums(2 * c, std::vector<float>(pixels * 4));
    for (int i = 0; i < 2 * c; ++i)
      glGetTextureImage(aggregate_[i].get(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels * 16), sums[i].data());
    gl::check("agaa read back");

    const glm::mat4 inverse_projection = glm::inverse(view.projection);
    // rsaa_common.glsl's rsaa_view_position.
    const auto view_position = [&](float wx, float wy, float d) {
      const glm::vec4 v = inverse_projection * glm::vec4(wx / w * 2 - 1, wy / h * 2 - 1, d * 2 - 1, 1);
      return Normal3{v.x / v.w, v.y / v.w, v.z / v.w};
    };
    AgaaFrameData out;
    out.width = w, out.height = h, out.samples = n;
    out.settings = settings_;
    out.samples_of_pixels.resize(pixels * n);
    out.meta.resize(pixels);
    out.aggregates.resize(pixels * c);
    out.pixel_rays.resize(pixels);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t gl_pixel = std::size_t(y) * w + x, pixel = std::size_t(h - 1 - y) * w + x;
        const float cx = x + 0.5f, cy = y + 0.5f;
        for (int s = 0; s < n; ++s) {
          const std::size_t i = std::size_t(s) * pixels + gl_pixel;
          AgaaSample& sample = out.samples_of_pixels[pixel * n + s];
          sample.valid = primitive[i] != 0;
          sample.position = view_position(cx + float(pattern_.positions[s].x), cy - float(pattern_.positions[s].y), depth[i]);
          // rsaa_decode_normal
          const float nx = normal[2 * i] / 16383.0f - 2.0f, ny = normal[2 * i + 1] / 16383.0f - 2.0f;
          sample.normal = {nx, ny, std::sqrt(std::max(0.0f, 1.0f - nx * nx - ny * ny))};
        }
        out.meta[pixel] = meta[2 * gl_pixel] | std::uint64_t(meta[2 * gl_pixel + 1]) << 32;
        for (int a = 0; a < c; ++a) {
          const float* albedo = &sums[2 * a][gl_pixel * 4];
          const float* geometry = &sums[2 * a + 1][gl_pixel * 4];
          out.aggregates[pixel * c + a] = {{albedo[0], albedo[1], albedo[2]}, {geometry[0], geometry[1], geometry[2]},
                                           geometry[3], albedo[3]};
        }
        out.pixel_rays[pixel] = view_position(cx, cy, 0.5f);
      }
    return out;
  }

 private:
  std::string defines() const { return samples_ == 4 ? "#define AGAA_MULTISAMPLE\n" : ""; }
  void bind_samples() const {
    glBindTextureUnit(1, depth_.get());
    glBindTextureUnit(2, normal_.get());
    glBindTextureUnit(3, primitive_.get());
  }

  int samples_;
  AgaaSettings settings_;
  float k_pixels_;
  SamplePattern pattern_;
  SceneRenderer renderer_;
  gl::Texture depth_, normal_, primitive_, meta_;
  std::vector<gl::Texture> aggregate_;
  std::vector<gl::Framebuffer> prepass_;
  gl::Framebuffer define_target_, accumulate_target_;
  gl::Program define_, accumulate_, resolve_;
  gl::CachedFramebuffer output_target_;
};

}  // namespace

std::unique_ptr<Technique> make_agaa(int samples, AgaaSettings settings, float k_pixels, int width, int height) {
  return std::make_unique<Agaa>(samples, settings, k_pixels, width, height);
}

AgaaFrameData read_back_agaa(Technique& agaa, const View& view) {
  auto* t = dynamic_cast<Agaa*>(&agaa);
  if (!t) throw std::invalid_argument("read_back_agaa: not an agaa technique");
  return t->read_back(view);
}

TechniqueKind agaa_technique() {
  return {"agaa", "Aggregate G-buffer Anti-Aliasing: 4 (hardware), 8 or 16 (jittered) visibility samples, c aggregates",
          [](const TechniqueOptions& o) {
            const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
            const int n = samples_or(o, 8);
            if (n != 4 && n != 8 && n != 16)
              bad("agaa --samples must be 4 (hardware), 8 or 16 (jittered), not " + std::to_string(n));
            if (!(o.agaa_k >= 0.0) || !std::isfinite(o.agaa_k)) bad("agaa --agaa-k must be a finite length >= 0");
            if (o.agaa_diffuse != "filtered" && o.agaa_diffuse != "plain") bad("agaa --agaa-diffuse must be filtered or plain");
            if (o.agaa_aggregates < 1 || o.agaa_aggregates > 4) bad("agaa --agaa-aggregates must be 1, 2, 3 or 4");
            if (!(o.agaa_k_pixels > 0.0) || !std::isfinite(o.agaa_k_pixels))
              bad("agaa --agaa-k-pixels must be finite and > 0");
          },
          [](const TechniqueOptions& o) {
            std::ostringstream label;
            label << "agaa " << samples_or(o, 8) << "x";
            if (o.agaa_k > 0.0) label << " k" << o.agaa_k;
            else if (o.agaa_k_pixels != TechniqueOptions{}.agaa_k_pixels) label << " k" << o.agaa_k_pixels << "px";
            if (o.agaa_aggregates != TechniqueOptions{}.agaa_aggregates) label << " c" << o.agaa_aggregates;
            if (o.agaa_diffuse != TechniqueOptions{}.agaa_diffuse) label << " " << o.agaa_diffuse;
            return label.str();
          },
          [](const TechniqueOptions& o, int width, int height) {
            AgaaSettings s;
            s.k = float(o.agaa_k);
            s.aggregates = o.agaa_aggregates;
            s.filtered_diffuse = o.agaa_diffuse == "filtered";
            return make_agaa(samples_or(o, 8), s, float(o.agaa_k > 0.0 ? 0.0 : o.agaa_k_pixels), width, height);
          }};
}

}  // namespace rsaa
