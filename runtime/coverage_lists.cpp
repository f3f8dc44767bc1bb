#include "runtime/coverage_lists.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/type_ptr.hpp>


#include "runtime/gl_context.h"
#include "runtime/technique_testing.h"
#include "runtime/scene_renderer.h"
#include "runtime/shader_library.h"

namespace rsaa {
namespace {

constexpr std::uint32_t kListEnd = 0xffffffffu;

gl::Texture make_lut_texture(const HalfPlaneLut& lut) {
  std::vector<std::uint32_t> texels;
  texels.reserve(lut.entries().size() * 2);
  for (Mask m : lut.entries()) texels.insert(texels.end(), {std::uint32_t(m), std::uint32_t(m >> 32)});
  gl::Texture t = gl::make_texture_2d(GL_RG32UI, lut.distance_bins(), lut.angle_bins());
  glTextureSubImage2D(t.get(), 0, 0, 0, lut.distance_bins(), lut.angle_bins(), GL_RG_INTEGER, GL_UNSIGNED_INT,
                      texels.data());
  return t;
}

// The inverse of coverage_record.glsl's encode_unit_vector (octahedral, 2 x snorm16).
Normal3 decode_unit_vector(std::uint32_t packed) {
  const glm::vec2 e = glm::unpackSnorm2x16(packed);
  float x = e.x, y = e.y, z = 1.0f - std::abs(x) - std::abs(y);
  if (z < 0.0f) {
    const float ox = (1.0f - std::abs(y)) * (x >= 0.0f ? 1.0f : -1.0f);
    const float oy = (1.0f - std::abs(x)) * (y >= 0.0f ? 1.0f : -1.0f);
    x = ox, y = oy;
  }
  const float len = std::sqrt(x * x + y * y + z * z);
  return {x / len, y / len, z / len};
}

// coverage_record.glsl's decode_slopes: 12-bit mantissas, a shared exponent.
std::pair<float, float> decode_slopes(std::uint32_t code) {
  const int e = int(code >> 24);
  if (e == 0) return {0.0f, 0.0f};
  const auto mantissa = [&](int shift) {
    const int q = int((code >> shift) & 0xfffu);
    return q >= 2048 ? q - 4096 : q;
  };
  return {std::ldexp(float(mantissa(0)), e - 139), std::ldexp(float(mantissa(12)), e - 139)};
}

float bits_to_float(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace

CoverageFragmentLists::CoverageFragmentLists(const SamplePattern& coverage_pattern, int width, int height,
                                             bool shading_inputs)
    : width_(width),
      height_(height),
      shading_inputs_(shading_inputs),
      narrow_(coverage_pattern.size() <= 32),
      record_uints_((narrow_ ? 3 : 4) + (shading_inputs ? 6 : 5)),
      lut_(coverage_pattern),
      program_(gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                                 {GL_GEOMETRY_SHADER, gl::shader_source("coverage_fragments.geom")},
                                 {GL_FRAGMENT_SHADER, gl::shader_source("coverage_fragments.frag")}},
                                record_defines(), "coverage fragment lists")),
      lut_texture_(make_lut_texture(lut_)),
      heads_(gl::make_texture_2d(GL_R32UI, width, height)) {
  GLuint id;
  glCreateBuffers(1, &id);
  counter_ = gl::Buffer(id);
  glNamedBufferStorage(id, 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateFramebuffers(1, &id);
  empty_target_ = gl::Framebuffer(id);
  glNamedFramebufferParameteri(id, GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
  glNamedFramebufferParameteri(id, GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
  const GLuint p = program_.get();
  const Mask full = coverage_pattern.all_similar();
  glProgramUniform2ui(p, glGetUniformLocation(p, "u_full_mask"), GLuint(full), GLuint(full >> 32));
  glProgramUniform1i(p, glGetUniformLocation(p, "u_halfplane_lut"), 1);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_heads"), 0);
  allocate_records(std::size_t(width) * height * kInitialRecordsPerPixel);
  gl::check("coverage fragment lists");
}

std::string CoverageFragmentLists::record_defines() const {
  return std::string(narrow_ ? "#define COVERAGE_NARROW\n" : "") +
         (shading_inputs_ ? "#define COVERAGE_SHADING_INPUTS\n" : "");
}

void CoverageFragmentLists::allocate_records(std::size_t capacity) {
  GLuint id;
  glCreateBuffers(1, &id);
  records_ = gl::Buffer(id);
  glNamedBufferStorage(id, GLsizeiptr(capacity * record_bytes()), nullptr, 0);
  capacity_ = capacity;
}

void CoverageFragmentLists::enable_z_prepass() {
  prepass_depth_ = gl::make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, width_, height_, 4);
  prepass_target_ = gl::make_framebuffer({}, {prepass_depth_.get()});
  max_depth_ = gl::make_texture_2d(GL_R32F, width_, height_);
  max_depth_target_ = gl::make_framebuffer({{max_depth_.get()}});
  max_depth_program_ = make_fullscreen_program("coverage_max_depth.frag", "");
  depth_renderer_.emplace();
  const GLuint p = program_.get();
  glProgramUniform1i(p, glGetUniformLocation(p, "u_max_depth"), 3);
  glProgramUniform1i(p, glGetUniformLocation(p, "u_z_prepass"), 1);
  glProgramUniform1i(max_depth_program_.get(), glGetUniformLocation(max_depth_program_.get(), "u_depth"), 3);
  gl::check("coverage lists: z-prepass setup");
}

void CoverageFragmentLists::z_prepass(const GpuScene& scene, const View& view) {
  const GLfloat far = 1.0f;
  glClearNamedFramebufferfv(prepass_target_.get(), GL_DEPTH, 0, &far);
  glBindFramebuffer(GL_FRAMEBUFFER, prepass_target_.get());
  glEnable(GL_MULTISAMPLE);
  SceneRenderer::draw(scene, view, {0.0f, 0.0f}, depth_renderer_->shade_program());
  glBindFramebuffer(GL_FRAMEBUFFER, max_depth_target_.get());
  glViewport(0, 0, view.width, view.height);
  glDisable(GL_DEPTH_TEST);
  glBindTextureUnit(3, prepass_depth_.get());
  glUseProgram(max_depth_program_.get());
  draw_fullscreen_triangle();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::check("coverage lists: z-prepass");
}

std::size_t CoverageFragmentLists::build(const GpuScene& scene, const View& view) {
  // The buffer follows the frames' fragment counts: grown to 1.25 x the count when a frame
  // overflows it (that frame is drawn again), shrunk to 1.25 x the last count when that used less
  // than half of it (the gap between the two keeps a steady view from reallocating).
  if (built_ && fragments_ * 2 < capacity_) allocate_records(std::max<std::size_t>(fragments_ + fragments_ / 4, 64));
  built_ = true;
  for (int attempt = 0;; ++attempt) {
    const std::uint32_t end = kListEnd;
    glClearTexImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &end);
    const std::uint32_t counter[2] = {0u, std::uint32_t(std::min<std::size_t>(capacity_, kListEnd - 1))};
    glNamedBufferSubData(counter_.get(), 0, sizeof counter, counter);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counter_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, records_.get());
    glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindTextureUnit(1, lut_texture_.get());
    if (z_prepass_enabled()) glBindTextureUnit(3, max_depth_.get());
    glBindFramebuffer(GL_FRAMEBUFFER, empty_target_.get());
    glProgramUniform2f(program_.get(), glGetUniformLocation(program_.get(), "u_viewport"), float(view.width),
                       float(view.height));
    SceneRenderer::draw(scene, view, {0.0f, 0.0f}, program_.get());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t used = 0;
    glGetNamedBufferSubData(counter_.get(), 0, 4, &used);
    fragments_ = used;
    if (used <= capacity_ || attempt == 2) break;
    allocate_records(std::size_t(used) + used / 4);
  }
  gl::check("coverage fragment lists: geometry pass");
  return std::min(fragments_, capacity_);
}

void CoverageFragmentLists::bind_for_resolve(GLuint program) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counter_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, records_.get());
  glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glProgramUniform1i(program, glGetUniformLocation(program, "u_heads"), 0);
}

double CoverageFragmentLists::bytes_per_pixel() const {
  // The z-prepass keeps a 4x depth buffer (32-bit) and the max-depth image besides.
  const double prepass = z_prepass_enabled() ? 4 * 4 + 4 : 0;
  return 4.0 + prepass + double(capacity_) * record_bytes() / (double(width_) * height_);
}

std::vector<std::vector<CoverageFragment>> CoverageFragmentLists::read_back() const {
  std::vector<std::uint32_t> heads(std::size_t(width_) * height_);
  glGetTextureImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(heads.size() * 4), heads.data());
  const std::size_t stored = std::min(fragments_, capacity_);
  const std::size_t uints = std::size_t(record_uints_);
  std::vector<std::uint32_t> records(stored * uints);
  if (stored) glGetNamedBufferSubData(records_.get(), 0, GLsizeiptr(records.size() * 4), records.data());
  std::vector<std::vector<CoverageFragment>> pixels(heads.size());
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      // GL rows are bottom first; ours top first.
      auto& list = pixels[std::size_t(height_ - 1 - y) * width_ + x];
      for (std::uint32_t i = heads[std::size_t(y) * width_ + x]; i != kListEnd && i < stored;
           i = records[i * uints]) {
        const std::uint32_t* r = &records[i * uints];
        CoverageFragment f;
        f.order = r[1];
        f.coverage = Mask(r[2]) | (narrow_ ? 0 : Mask(r[3]) << 32);
        const std::uint32_t* d = r + (narrow_ ? 3 : 4);  // coverage_record.glsl's RECORD_DEPTH
        const auto [ddx, ddy] = decode_slopes(d[1]);
        f.depth = {bits_to_float(d[0]), ddx, ddy};
        f.normal = decode_unit_vector(d[2]);
        if (shading_inputs_) {
          const glm::vec2 rg = glm::unpackHalf2x16(d[3]), b = glm::unpackHalf2x16(d[4]);
          f.albedo = {rg.x, rg.y, b.x};
          f.shading_normal = decode_unit_vector(d[5]);
        } else {
          const glm::vec2 rg = glm::unpackHalf2x16(d[3]), b = glm::unpackHalf2x16(d[4]);
          f.colour = {rg.x, rg.y, b.x};
        }
        list.push_back(f);
      }
      std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
    }
  gl::check("coverage fragment lists: read back");
  return pixels;
}

namespace {
std::string resolve_defines(const std::string& resolve_define, bool shade_surfaces) {
  return "#define " + resolve_define + "\n" + (shade_surfaces ? "#define DCAA_SHADE_SURFACES\n" : "");
}
}  // namespace

CoverageListTechnique::CoverageListTechnique(const SamplePattern& coverage_pattern, const std::string& resolve_define,
                                             int width, int height, bool z_prepass, bool shade_surfaces)
    : lists_(coverage_pattern, width, height, shade_surfaces),
      resolve_(make_fullscreen_program("coverage_resolve.frag",
                                       resolve_defines(resolve_define, shade_surfaces) + lists_.record_defines())),
      continue_(make_fullscreen_program("coverage_resolve.frag", resolve_defines(resolve_define, shade_surfaces) +
                                                                     lists_.record_defines() +
                                                                     "#define COVERAGE_CONTINUE\n")),
      pending_index_(gl::make_texture_2d(GL_R32UI, width, height)) {
  if (z_prepass) lists_.enable_z_prepass();
  GLuint id;
  glCreateBuffers(1, &id);
  pending_counter_ = gl::Buffer(id);
  glNamedBufferStorage(id, 12, nullptr, GL_DYNAMIC_STORAGE_BIT);
  for (GLuint p : resolve_programs()) glProgramUniform1i(p, glGetUniformLocation(p, "u_pending_index"), 1);
  allocate_pending(std::max(64, width * height / 256));
  gl::check("coverage technique: pending entries");
}

void CoverageListTechnique::allocate_pending(std::size_t capacity) {
  GLuint id;
  glCreateBuffers(1, &id);
  pending_entries_ = gl::Buffer(id);
  glNamedBufferStorage(id, GLsizeiptr(capacity * kPendingUints * 4), nullptr, 0);
  pending_capacity_ = capacity;
}

double CoverageListTechnique::bytes_per_pixel() const {
  const glm::ivec2 size = lists_.size();
  return lists_.bytes_per_pixel() + 4.0 + double(pending_capacity_) * kPendingUints * 4 / (double(size.x) * size.y);
}

void CoverageListTechnique::render(const GpuScene& scene, const View& view, GLuint output) {
  if (lists_.z_prepass_enabled()) {
    timer_.begin("z-prepass");
    lists_.z_prepass(scene, view);
    timer_.end();
  }
  timer_.begin("main");
  lists_.build(scene, view);
  timer_.end();
  timer_.begin("resolve");
  const GLuint program = resolve_.get();
  const glm::vec3 bg = scene.background();
  const glm::mat4 inverse_projection = glm::inverse(view.projection);
  for (GLuint p : resolve_programs()) {
    lists_.bind_for_resolve(p);
    glProgramUniform3f(p, glGetUniformLocation(p, "u_background"), bg.r, bg.g, bg.b);
    if (lists_.shading_inputs()) {
      glProgramUniformMatrix4fv(p, glGetUniformLocation(p, "u_inverse_projection"), 1, GL_FALSE,
                                glm::value_ptr(inverse_projection));
      glProgramUniform2f(p, glGetUniformLocation(p, "u_viewport"), float(view.width), float(view.height));
    }
  }
  const std::uint32_t none = 0;
  glClearTexImage(pending_index_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glBindFramebuffer(GL_FRAMEBUFFER, output_target_.get({{output}}));
  glViewport(0, 0, view.width, view.height);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, pending_counter_.get());
  // First pass: the short lists; the long ones become pending entries (grown and drawn again
  // if they overflowed).
  std::uint32_t counter[3] = {0u, 0u, 0u};
  for (int attempt = 0;; ++attempt) {
    counter[0] = 0u;
    counter[1] = std::uint32_t(std::min<std::size_t>(pending_capacity_, 0xffffffffu));
    glNamedBufferSubData(pending_counter_.get(), 0, sizeof counter, counter);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, pending_entries_.get());
    glBindImageTexture(1, pending_index_.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glUseProgram(program);
    draw_fullscreen_triangle();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(pending_counter_.get(), 0, 4, &counter[0]);
    if (counter[0] <= pending_capacity_ || attempt == 1) break;
    allocate_pending(std::size_t(counter[0]) + counter[0] / 4);
  }
  pending_ = std::min<std::size_t>(counter[0], pending_capacity_);
  timer_.end();
  timer_.begin("resolve long lists");
  // Continuation passes until every entry is done (each walks a bounded part of its list).
  continuation_passes_ = 0;
  if (pending_) {
    glBindImageTexture(1, pending_index_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glUseProgram(continue_.get());
    for (std::uint32_t active = 1; active; ++continuation_passes_) {
      active = 0;
      glNamedBufferSubData(pending_counter_.get(), 8, 4, &active);
      draw_fullscreen_triangle();
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
      glGetNamedBufferSubData(pending_counter_.get(), 8, 4, &active);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  timer_.end();
  gl::check("coverage lists: resolve");
}

DcaaSurfaceShader dcaa_surface_shader(const View& view, const std::vector<PointLight>& point_lights, int x, int y) {
  const glm::mat4 inverse_projection = glm::inverse(view.projection);
  const float wx = float(x) + 0.5f, wy = float(view.height - 1 - y) + 0.5f;  // GL window space
  return [=, &point_lights](const DcaaSurface& s) {
    const glm::vec4 v = inverse_projection * glm::vec4(wx / float(view.width) * 2.0f - 1.0f,
                                                       wy / float(view.height) * 2.0f - 1.0f,
                                                       s.depth.at_centre * 2.0f - 1.0f, 1.0f);
    return shade_surface(s.albedo, s.shading_normal, {v.x / v.w, v.y / v.w, v.z / v.w}, kSceneSpecularExponent,
                         kSceneSpecularScale, 1.0f, point_lights);
  };
}

CoverageFragmentLists* coverage_lists_of(Technique& technique) {
  auto* coverage = dynamic_cast<CoverageListTechnique*>(&technique);
  return coverage ? coverage->coverage_lists() : nullptr;
}

}  // namespace rsaa
