#include "runtime/rsaa_pass.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "core/rsaa/conventions.h"
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
  std::vector<gl::Texture> codes;  // four subsamples per texel (RGBA), ceil(n / 4) textures
  gl::Texture subsample_depth, table;
  // Borrowed colours (RsaaSettings::multi_surface "borrow", with records): per pixel a byte a
  // subsample, the pixel whose centre shows its surface (shaders/rsaa_prepass_records.glsl).
  gl::Texture sources;
  // The pre-passes that write surface records: the records (RG32UI; with material edges the
  // material packed in) and depths, sample i (multisample) or layer i (RsaaSettings::prepass
  // "records") = subsample i; the record passes turn them into `codes`.
  gl::Texture records, record_depths;
  gl::Framebuffer multisample_target;
  // Union pre-pass (2m subsamples from two m-sample draws): the shifted draw's, sample i =
  // subsample m + i of the pixel that contains the point it sees.
  gl::Texture records2, record_depths2;
  gl::Framebuffer multisample_target2;
  gl::Program record_list_program, record_codes_program;
  GLint record_list_group[3] = {1, 1, 1};
  bool record_images = false;  // the record passes read the records as images
  // The compute resolve reads the codes, normals and primitives as images (RSAA_CODE_IMAGES)
  // where the driver's image and combined resource limits hold them, else as textures.
  bool resolve_reads_images = false;
  // Jittered pre-pass: one per code texture; "records": one per subsample (its layers).
  std::vector<gl::Framebuffer> subsample_targets;
  gl::Buffer uniforms;  // RsaaUniformHead, then an ivec4 per subsample
  // Every texture the pass reads is read through these (the colour bilinear, the others
  // nearest), not through the texture's own parameters nor an engine's sampler objects: a
  // texture's default GL_REPEAT wrap blended the opposite image border into edge pixels, and a
  // texture incomplete under its own filters (glTexImage2D's default mipmap minification, an
  // integer texture filtered linearly, or an engine's sampler object on a unit) reads as zero.
  gl::Sampler bilinear, nearest;
  gl::Program subsample_program, post_program;
  // The culled jittered pre-pass: the marking program and its target (every code texture and
  // the subsample depth-stencil).
  gl::Program cull_program;
  gl::Framebuffer cull_target;
  gl::CachedFramebuffer resolve_target;
  // copy_colour(): the frame's colour and the output, each alone in a framebuffer.
  gl::CachedFramebuffer copy_source, copy_target;
  // The two-pass post-process (RsaaSettings::post "edges"): the edge pass writes depth (the
  // full-screen triangle's) only where a pixel is to be resolved, into a depth-only target.
  gl::Program edge_program;
  gl::Texture edge_depth;
  gl::CachedFramebuffer edge_target;
  // The compute post-process (RsaaSettings::post "compute"): the classify program lists the edge
  // pixels in `edge_list` (rsaa_post_list.glsl), the resolve program runs on the listed pixels.
  gl::Program classify_program, list_size_program, list_resolve_program;
  GLint classify_group[3] = {1, 1, 1};  // the classify program's work group size
  gl::Buffer edge_list;
  // The pre-passes that write records: the list of the pixels their second record pass codes.
  // With the compute post-process the record passes also fill `edge_list` as they finish each
  // pixel's codes, so that the post-process need not read every pixel's codes again.
  gl::Buffer record_list;
  // Resolving in place (output == the frame's colour): the listed pixels' colours are resolved
  // into `scratch` (made at the first such call, in the output's format: RGBA32F values above half
  // float's range, and every format's values, come back as the separate output's), then copied
  // into the colour by `scatter_program`.
  gl::Program scatter_program;
  gl::Texture scratch;
  GLenum scratch_format = 0;
};

namespace {

// A float as a GLSL literal that reads back the same value ("1.5", "1.0", "7.5e-05").
std::string glsl_float(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(value));
  std::string literal = text;
  if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
  return literal;
}

// shaders/rsaa_uniforms.glsl's block, std140: a mat4, two vec2, a float and an int, padding to
// 16 bytes, then one ivec4 per subsample.
struct RsaaUniformHead {
  float inverse_projection[16];
  float viewport[2];
  float jitter_ndc[2];
  float threshold;
  std::int32_t subsample;
  float sample_shift[2];
};
static_assert(sizeof(RsaaUniformHead) == 96, "std140 layout of RsaaUniforms");
// What changes per pre-pass draw: jitter, threshold, subsample, sample shift.
struct RsaaUniformPerDraw {
  float jitter_ndc[2];
  float threshold;
  std::int32_t subsample;
  float sample_shift[2];
};
constexpr GLintptr kJitterOffset = offsetof(RsaaUniformHead, jitter_ndc);
static_assert(offsetof(RsaaUniformHead, sample_shift) - kJitterOffset == offsetof(RsaaUniformPerDraw, sample_shift),
              "the per-draw fields are one update");

// The pass's post-process texture units (rsaa_post.glsl with RSAA_POST_FIRST_UNIT 0).
// Codes take up to four units (16 subsamples, four per texel); the primitive target (material
// edges) comes after the last of them.
constexpr int kColourUnit = 0, kNormalUnit = 1, kDepthUnit = 2, kTableUnit = 3, kFirstCodeUnit = 4,
              kPrimitiveUnit = 8;
// The in-place resolve's scratch image, read by the copy into the colour (rsaa_post_scatter.comp).
constexpr int kScratchUnit = 9;
constexpr int kSourcesUnit = 10;  // rsaa_post.glsl's rsaa_post_sources (borrowed colours)
constexpr int kPostUnits = 11;
// The compute post-process's shader storage binding (the edge list) and image units (output, mask).
constexpr int kEdgeListBinding = 0, kOutputImageUnit = 0, kMaskImageUnit = 1;
// The record passes' lists: the pixels to code at kEdgeListBinding, the post-process's edge list here.
constexpr int kRecordEdgeListBinding = 1;
constexpr GLint kRecordListEdgesLocation = 1;  // rsaa_prepass_records.glsl's rsaa_list_edges
// The compute post-process's image units for what it reads (RSAA_CODE_IMAGES): the code textures
// from kFirstCodeImageUnit on, then the centre normal, then (material edges) the centre primitive.
constexpr int kFirstCodeImageUnit = 2;
// How many of those: the code textures, the normal and, with material edges, the primitive.
int post_read_images(int code_textures, bool material_edges) { return code_textures + (material_edges ? 2 : 1); }
// The record passes of the multisample pre-pass write the codes through the same image units.
constexpr GLint kRecordRowsLocation = 0;
// The record passes' four texture units (records and depths of each draw): 0-3, or after the
// pre-pass's own three when those start below 4.
constexpr int kRecordUnits = 4;
// The record passes' image units for the records, one per draw (rsaa_record_images[2]).
constexpr int kRecordImages = 2;
// The codes pass's image unit for the sources it writes (borrowed colours): one the record passes
// leave free (the post-process's output unit).
constexpr int kSourcesImageUnit = 0;
// The sources' format (rsaa_sources_channels() 32-bit channels).
GLenum sources_format(int sample_count) {
  const GLenum formats[] = {GL_R32UI, GL_RG32UI, 0, GL_RGBA32UI};
  return formats[rsaa_sources_channels(sample_count) - 1];
}
const char* sources_image_format(int sample_count) {
  const char* formats[] = {"r32ui", "rg32ui", "", "rgba32ui"};
  return formats[rsaa_sources_channels(sample_count) - 1];
}
// What the pre-passes that write records keep per subsample and pixel: a surface record (RG32UI)
// and a 32-bit depth.
constexpr double kRecordBytesPerSubsample = 8.0 + 4.0;
int record_first_unit(int prepass_first_unit) { return rsaa_record_first_unit(prepass_first_unit); }
// Whether the record passes' texture units (the pre-pass's three and the records') are below the
// driver's compute limit.
bool record_units_fit(int prepass_first_unit) {
  GLint compute_units = 0;
  glGetIntegerv(GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, &compute_units);
  return std::max(record_first_unit(prepass_first_unit) + kRecordUnits - 1, prepass_first_unit + 2) < compute_units;
}
// The edge list's head (rsaa_post_list.glsl: three group counts and the pixel count), and the
// location of rsaa_post_classify.comp's rows.
constexpr GLint64 kListHeadBytes = 16;
constexpr GLint kClassifyRowsLocation = 0;
constexpr GLint kOutputSrgbLocation = 1;  // rsaa_post_output.glsl's rsaa_output_srgb
static_assert(kFirstCodeUnit + (kMaxTableSamples + 3) / 4 <= kPrimitiveUnit, "code units overlap the primitive's");

// The table the pass uses: the settings' own, or the built-in one of the pattern named.
OffsetTable table_of(const RsaaSettings& settings) {
  if (!settings.table) {
    if (settings.pattern != "d3d4x" && settings.pattern != "d3d8x" && settings.pattern != "gl4x")
      throw std::invalid_argument("RSAA pattern '" + settings.pattern + "' is not one of d3d4x, d3d8x, gl4x " +
                                  "(other patterns: pass their table)");
    OffsetTable table = gl::builtin_offset_table(settings.pattern);
    if (settings.pattern == "gl4x") {  // the driver's positions must be the ones it was trained for
      const SamplePattern driver = query_gl_sample_pattern(4);
      for (int i = 0; i < driver.size(); ++i)
        if (length(driver.positions[i] - table.pattern.positions[i]) > 1e-6)
          throw std::runtime_error("tables/gl4x.json was trained for other sample positions than this driver's "
                                   "(sample " + std::to_string(i) + "); retrain it with rsaa train --pattern gl4x");
    }
    return table;
  }
  const OffsetTable& table = *settings.table;
  if (!settings.pattern.empty() && settings.pattern != table.pattern.name)
    throw std::invalid_argument("the RSAA table is for pattern '" + table.pattern.name + "' (" +
                                std::to_string(table.pattern.size()) + " samples), not '" + settings.pattern + "'");
  if (table.pattern.size() < 1 || table.pattern.size() > kMaxTableSamples ||
      table.offsets.size() != (std::size_t(1) << table.pattern.size()))
    throw std::invalid_argument("the RSAA table for '" + table.pattern.name + "' has " +
                                std::to_string(table.offsets.size()) + " offsets for " +
                                std::to_string(table.pattern.size()) + " samples");
  // A table built in memory has not been through the file reader's checks: finite positions
  // inside the pixel, none coinciding (the pass steps to the outside pixel of each).
  try {
    (void)pattern_from_positions("table", table.pattern.positions);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("the RSAA table for '" + table.pattern.name + "': " + e.what());
  }
  return table;
}

// The table as a texture: texel (mask % 256, mask / 256) = (dx, dy) in GL window space, the
// mask's representative dissimilar subsample (post-pass authentication), 0.
gl::Texture table_texture(const OffsetTable& table) {
  const int entries = int(table.offsets.size());
  const int width = std::min(entries, 256), height = (entries + 255) / 256;
  std::vector<float> texels(std::size_t(width) * height * 4, 0.0f);
  for (int mask = 0; mask < entries; ++mask) {
    const Vec2 gl = pixel_to_gl(table.offsets[mask]);
    if (!std::isfinite(gl.x) || !std::isfinite(gl.y) || std::abs(gl.x) > 1.0 || std::abs(gl.y) > 1.0)
      throw std::invalid_argument("the RSAA table for '" + table.pattern.name + "' has offset " +
                                  std::to_string(mask) + " outside [-1, 1]");
    float* t = &texels[std::size_t(mask) * 4];
    t[0] = float(gl.x), t[1] = float(gl.y);
    t[2] = float(std::max(0, representative_dissimilar(table.pattern, Mask(mask))));
  }
  gl::Texture texture = gl::make_texture_2d(GL_RGBA32F, width, height);
  gl::upload_texels_2d(texture.get(), width, height, GL_RGBA, GL_FLOAT, texels.data());
  return texture;
}

// Whether the pre-pass can draw into `samples`-sample integer targets: the driver offers that
// many (at least 2) for integer formats, and a multisample texture of that count gets exactly
// that many (a driver may round a count up to one it has: its positions are then another pattern's).
bool driver_offers_samples(int samples) {
  GLint max_samples = 0, max_integer_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &max_integer_samples);
  if (samples < 2 || samples > max_samples || samples > max_integer_samples) return false;
  const gl::Texture texture = gl::make_texture_2d_multisample(GL_RG32UI, 1, 1, samples);
  GLint actual = 0;
  glGetTextureLevelParameteriv(texture.get(), 0, GL_TEXTURE_SAMPLES, &actual);
  return actual == samples;
}

// Whether the driver can run the pre-pass as one multisample draw for `pattern`: it offers that
// many samples for integer targets, and its positions for that count are the pattern's.
bool driver_samples_pattern(const SamplePattern& pattern) {
  const int n = pattern.size();
  if (!driver_offers_samples(n)) return false;
  const SamplePattern driver = query_gl_sample_pattern(n);
  for (int i = 0; i < n; ++i)
    if (length(driver.positions[i] - pattern.positions[i]) > 1e-6) return false;
  return true;
}

// Whether the driver can run the pre-pass as two m-sample draws for a 2m-subsample `pattern`:
// subsamples 0..m-1 are the driver's m positions and m..2m-1 the same shifted by one sub-pixel
// offset, wrapped into the pixel (the union pattern). Sets `shift` (pixel space, +y down) and
// `raster` (per shifted sample i: the raster pixel whose sample i sees subsample m + i of pixel
// P is P + raster[i], window space).
bool driver_samples_union(const SamplePattern& pattern, Vec2& shift, std::vector<glm::ivec2>& raster) {
  const int n = pattern.size(), m = n / 2;
  if (n % 2 != 0 || !driver_offers_samples(m)) return false;
  const SamplePattern driver = query_gl_sample_pattern(m);
  for (int i = 0; i < m; ++i)
    if (length(driver.positions[i] - pattern.positions[i]) > 1e-6) return false;
  const auto wrap = [](double v) { return v - std::floor(v + 0.5); };  // into [-0.5, 0.5)
  const Vec2 d0 = pattern.positions[m] - driver.positions[0];
  shift = {wrap(d0.x), wrap(d0.y)};
  if (!(length(shift) > 1e-6)) return false;
  raster.clear();
  for (int i = 0; i < m; ++i) {
    const Vec2 seen = driver.positions[i] + shift;  // relative to the raster pixel's centre
    const Vec2 u = pattern.positions[m + i];
    if (std::abs(wrap(seen.x) - u.x) > 1e-6 || std::abs(wrap(seen.y) - u.y) > 1e-6) return false;
    // The point seen is at R's centre + seen = P's centre + u: R - P = u - seen (pixel space).
    const Vec2 step = {std::round(u.x - seen.x), std::round(u.y - seen.y)};
    raster.push_back({int(step.x), int(-step.y)});  // R - P in window space (+y up)
  }
  return true;
}

// Whether the driver can run the pre-pass as one m-sample draw at `cells` times the image's size
// (columns, rows) for an n = m x columns x rows subsample `pattern` whose subsample i is the
// driver's sample i % m in cell i / m of the pixel (cell_pattern(): cells numbered row by row from
// the top-left, pixel space), each cell a raster pixel of the draw (a cell pattern, such as
// tables/custom-gl4x-tall.json: 8 subsamples from one 4x draw at twice the height). Sets `cells`
// and `offsets` (per subsample, its cell's raster pixel relative to the pixel's lower-left cell,
// window space). Any cells up to 8 x 8 (what rsaa train --cells makes); a draw beyond the
// driver's framebuffer, viewport, texture or sample limits is not offered, nor a count whose
// positions the driver reports unusably (pattern_from_positions refuses them).
bool driver_samples_cells(const SamplePattern& pattern, int width, int height, glm::ivec2& cells,
                          std::vector<glm::ivec2>& offsets) {
  GLint max_depth_samples = 0, max_size[2] = {}, max_framebuffer[2] = {}, max_texture = 0;
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_depth_samples);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_size);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &max_framebuffer[0]);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &max_framebuffer[1]);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  const int n = pattern.size();
  for (int area = 2; area <= n / 2; ++area)  // the fewest cells first: the most samples a draw
    for (int columns = 1; columns <= std::min(area, 8); ++columns) {
      const glm::ivec2 c(columns, area / columns);
      const int m = n / area;
      if (area % columns != 0 || c.y > 8 || n % area != 0 || m > max_depth_samples) continue;
      const std::int64_t raster_w = std::int64_t(width) * c.x, raster_h = std::int64_t(height) * c.y;
      if (raster_w > std::min({max_size[0], max_framebuffer[0], max_texture}) ||
          raster_h > std::min({max_size[1], max_framebuffer[1], max_texture}) || !driver_offers_samples(m))
        continue;
      SamplePattern expected;
      try {
        expected = cell_pattern(query_gl_sample_pattern(m), c.x, c.y);
      } catch (const std::invalid_argument&) {
        continue;  // positions no table could have: not this pattern's
      }
      std::vector<glm::ivec2> found;
      for (int i = 0; i < n; ++i) {
        if (length(expected.positions[std::size_t(i)] - pattern.positions[std::size_t(i)]) > 1e-6) break;
        const int cell = i / m, column = cell % c.x, row = cell / c.x;  // row 0: the top (pixel space, +y down)
        found.push_back({column, c.y - 1 - row});
      }
      if (int(found.size()) != n) continue;
      cells = c, offsets = found;
      return true;
    }
  return false;
}

GLenum code_format(int bits) {
  switch (bits) {
    case 8: return GL_RGBA8UI;
    case 16: return GL_RGBA16UI;
    case 32: return GL_RGBA32UI;
  }
  throw std::invalid_argument("RSAA code bits must be 8, 16 or 32, not " + std::to_string(bits));
}

bool zero_to_one(const RsaaSettings& s) { return s.depth == "zero-to-one" || s.depth == "reverse-z"; }

// View-space distance in front of the camera (along -z) at window depth `depth` through
// `inverse_projection`.
double view_distance(const glm::mat4& inverse_projection, float depth, bool zero_to_one_depth) {
  const glm::vec4 view = inverse_projection * glm::vec4(0.0f, 0.0f, zero_to_one_depth ? depth : depth * 2.0f - 1.0f, 1.0f);
  return -double(view.z) / double(view.w);
}

// The colour formats the frame's colour and resolve()'s output may have: the engine's HDR or LDR
// target as it is. The pass works in linear light: an sRGB colour is decoded as it is read, an
// sRGB output encoded as it is written (the compute post-process stores into an RGBA8 view of it:
// image units have no sRGB format).
const std::vector<GLenum> kColourFormats = {GL_RGBA16F, GL_RGBA32F, GL_R11F_G11F_B10F, GL_RGB10_A2, GL_RGBA8,
                                            GL_SRGB8_ALPHA8};

// A missing or mismatched texture in the engine's frame is an error naming the field; a depth
// convention other than the settings' too.
void validate_frame(const RsaaFrame& frame, int width, int height, const RsaaSettings& settings) {
  if (frame.width != width || frame.height != height)
    throw std::invalid_argument("RsaaFrame is " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + ", the RsaaPass was made for " +
                                std::to_string(width) + "x" + std::to_string(height));
  gl::require_texture(frame.colour, kColourFormats, width, height, "RsaaFrame::colour");
  gl::require_texture(frame.centre_normal, GL_RG16UI, width, height, "RsaaFrame::centre_normal");
  gl::require_texture(frame.centre_primitive, settings.material_edges ? GL_RG32UI : GL_R32UI, width, height,
                      settings.material_edges ? "RsaaFrame::centre_primitive (material_edges: primitive, material)"
                                              : "RsaaFrame::centre_primitive");
  // The engine's depth buffer as it is: with or without stencil, 32-bit float or 24-bit depth.
  gl::require_texture(frame.centre_depth,
                      {GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8, GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT24}, width,
                      height,
                      "RsaaFrame::centre_depth");
  // Depth is read in the settings' convention (RsaaSettings::depth): the clip control must be its.
  GLint origin = 0, depth_mode = 0;
  glGetIntegerv(GL_CLIP_ORIGIN, &origin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &depth_mode);
  const bool zo = zero_to_one(settings);
  if (origin != GL_LOWER_LEFT || depth_mode != (zo ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE))
    throw std::invalid_argument(std::string("RsaaSettings::depth \"") + settings.depth + "\" needs glClipControl(GL_LOWER_LEFT, " +
                                (zo ? "GL_ZERO_TO_ONE" : "GL_NEGATIVE_ONE_TO_ONE") + "), the GL has " +
                                (origin != GL_LOWER_LEFT ? "GL_UPPER_LEFT" : zo ? "GL_NEGATIVE_ONE_TO_ONE" : "GL_ZERO_TO_ONE") +
                                ": depth reconstruction and the pre-pass depth test follow the setting");
  // Every pixel's position is rebuilt through the inverse projection: a NaN, infinite or singular
  // matrix (or one that sends depths to infinity) would give every similarity as NaN, silently.
  const glm::mat4& inverse = frame.inverse_projection;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(inverse[c][r]))
        throw std::invalid_argument("RsaaFrame::inverse_projection has a non-finite element (column " +
                                    std::to_string(c) + ", row " + std::to_string(r) + ")");
  const double determinant = glm::determinant(glm::dmat4(inverse));
  if (!(std::abs(determinant) > 0.0) || !std::isfinite(determinant))
    throw std::invalid_argument("RsaaFrame::inverse_projection is singular: it is no inverse of a projection");
  // Nearer is smaller depth, but for reverse Z: a camera projection (both depths in front of the
  // camera) must agree.
  const double quarter = view_distance(inverse, 0.25f, zo);
  const double three_quarters = view_distance(inverse, 0.75f, zo);
  if (!std::isfinite(quarter) || !std::isfinite(three_quarters))
    throw std::invalid_argument("RsaaFrame::inverse_projection sends window depth 0.25 or 0.75 to no finite point");
  if (!(quarter > 0.0 && three_quarters > 0.0)) return;
  const bool reversed = quarter > three_quarters;
  if (reversed != (settings.depth == "reverse-z"))
    throw std::invalid_argument(std::string("RsaaFrame::inverse_projection puts depth ") + (reversed ? "1" : "0") +
                                " nearer, but RsaaSettings::depth is \"" + settings.depth + "\"" +
                                (reversed ? " (reverse Z needs \"reverse-z\")" : ""));
}

// A moved-from RsaaPass or RsaaTargets has no GL objects: a call on it is a clear error.
void require_not_moved_from(const void* objects, const char* call) {
  if (!objects) throw std::logic_error(std::string(call) + ": this object was moved from");
}

// An image size the driver can hold in a texture and draw into whole, else std::invalid_argument
// naming `who` and the limit (it was a GL error from inside; a minimised window's 0 x 0 is one).
void require_image_size(const char* who, int width, int height) {
  GLint texture = 0, framebuffer[2] = {}, viewport[2] = {};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &framebuffer[0]);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &framebuffer[1]);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  const int max_width = std::min({texture, framebuffer[0], viewport[0]});
  const int max_height = std::min({texture, framebuffer[1], viewport[1]});
  if (width < 1 || height < 1 || width > max_width || height > max_height)
    throw std::invalid_argument(std::string(who) + ": a " + std::to_string(width) + "x" + std::to_string(height) +
                                " image; this driver takes 1x1 to " + std::to_string(max_width) + "x" +
                                std::to_string(max_height) +
                                " (GL_MAX_TEXTURE_SIZE, GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT, GL_MAX_VIEWPORT_DIMS)");
}

// The outside pixel of each subsample, converted to window space (+y up).
glm::ivec2 window_step(Vec2 sample) {
  const PixelStep s = outside_pixel_towards(sample);
  const Vec2 gl = pixel_to_gl({double(s.i), double(s.j)});
  return {int(gl.x), int(gl.y)};
}

}  // namespace

RsaaTargets::RsaaTargets(int width, int height, bool material_edges)
    : width_(width), height_(height), gl_(std::make_unique<Objects>()) {
  gl::check_none_pending("RsaaTargets::RsaaTargets");
  gl::require_gl45("RsaaTargets::RsaaTargets");
  require_image_size("RsaaTargets", width, height);
  gl_->colour = gl::make_texture_2d(GL_RGBA16F, width, height, GL_LINEAR);
  gl_->normal = gl::make_texture_2d(GL_RG16UI, width, height);
  gl_->primitive = gl::make_texture_2d(material_edges ? GL_RG32UI : GL_R32UI, width, height);
  gl_->depth = gl::make_texture_2d(GL_DEPTH_COMPONENT32F, width, height);
  gl_->framebuffer = gl::make_framebuffer(
      {{gl_->colour.get()}, {gl_->normal.get()}, {gl_->primitive.get()}}, {gl_->depth.get()});
}
RsaaTargets::~RsaaTargets() = default;
RsaaTargets::RsaaTargets(RsaaTargets&&) noexcept = default;
RsaaTargets& RsaaTargets::operator=(RsaaTargets&&) noexcept = default;

void RsaaTargets::bind() const {
  require_not_moved_from(gl_.get(), "RsaaTargets::bind");
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer.get());
}
GlName RsaaTargets::colour() const {
  require_not_moved_from(gl_.get(), "RsaaTargets::colour");
  return colour_ ? colour_ : gl_->colour.get();
}

void RsaaTargets::use_colour(GlName colour) {
  require_not_moved_from(gl_.get(), "RsaaTargets::use_colour");
  // Attached every call: a deleted texture stays attached to a framebuffer not bound, and its name
  // may come back as another texture.
  if (colour) gl::require_texture(colour, kColourFormats, width_, height_, "RsaaTargets::use_colour");
  colour_ = colour;
  glNamedFramebufferTexture(gl_->framebuffer.get(), GL_COLOR_ATTACHMENT0, this->colour(), 0);
}

void RsaaTargets::clear(const float background[3], float far_depth) const {
  require_not_moved_from(gl_.get(), "RsaaTargets::clear");
  // Clears obey the scissor test and the colour and depth masks: the engine's (a depth mask left
  // off after its transparent draws, a scissor left on) left pixels of the last frame.
  const gl::SavedState saved({});
  gl::set_pass_state(false);
  glEnable(GL_FRAMEBUFFER_SRGB);  // linear RGB, encoded into an sRGB colour (use_colour())
  const GLfloat colour[4] = {background[0], background[1], background[2], 1.0f};
  const GLuint zero[4] = {0, 0, 0, 0};
  const GLuint framebuffer = gl_->framebuffer.get();
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, colour);
  glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 1, zero);
  glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 2, zero);
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far_depth);
}

RsaaFrame RsaaTargets::frame(const glm::mat4& inverse_projection) const {
  require_not_moved_from(gl_.get(), "RsaaTargets::frame");
  return {colour(), gl_->normal.get(), gl_->primitive.get(), gl_->depth.get(), width_, height_, inverse_projection};
}

SamplePattern query_gl_sample_pattern(int samples) {
  gl::check_none_pending("query_gl_sample_pattern");  // (and a current context: else "at most 0 samples")
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const auto renderer = [] {
    const GLubyte* name = glGetString(GL_RENDERER);
    return std::string(name ? reinterpret_cast<const char*>(name) : "unknown");
  };
  if (samples < 1 || samples > max_samples)
    throw std::invalid_argument("the GL driver (" + renderer() + ") offers at most " + std::to_string(max_samples) +
                                " samples per pixel (GL_MAX_SAMPLES): no " + std::to_string(samples) +
                                "-sample pattern to read");
  const gl::Texture texture = gl::make_texture_2d_multisample(GL_RGBA8, 1, 1, samples);
  GLint actual = 0;  // a driver may round a count up to one it has
  glGetTextureLevelParameteriv(texture.get(), 0, GL_TEXTURE_SAMPLES, &actual);
  if (actual != samples)
    throw std::invalid_argument("the GL driver (" + renderer() + ") gives " + std::to_string(actual) + " samples for " +
                                std::to_string(samples) + ": it has no " + std::to_string(samples) + "-sample pattern");
  const gl::Framebuffer fb = gl::make_framebuffer({{texture.get()}});
  // The positions are the draw framebuffer's: bound meanwhile, the engine's bound again after
  // (RsaaPass's constructor calls this; it left the engine drawing into the default framebuffer).
  GLint engine_framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &engine_framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb.get());
  std::vector<Vec2> positions;
  for (int i = 0; i < samples; ++i) {
    GLfloat p[2];
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), p);
    positions.push_back({p[0], p[1]});
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(engine_framebuffer));
  gl::check("reading the driver's sample positions");
  return pattern_from_gl_positions("gl" + std::to_string(samples) + "x", positions);
}

std::string rsaa_shader_defines(const RsaaSettings& settings, int sample_count, bool multisample_prepass,
                                bool union_pattern, glm::ivec2 cells) {
  if (sample_count < 1 || sample_count > kMaxTableSamples)
    throw std::invalid_argument("rsaa_shader_defines: sample_count " + std::to_string(sample_count) +
                                " is not 1 to " + std::to_string(kMaxTableSamples));
  code_format(settings.code_bits);  // throws unless 8, 16 or 32
  if (multisample_prepass && union_pattern && sample_count % 2 != 0)
    throw std::invalid_argument("rsaa_shader_defines: a union pattern's two draws need an even sample_count, not " +
                                std::to_string(sample_count));
  if (multisample_prepass && !union_pattern && cells != glm::ivec2(1, 1) &&
      (cells.x < 1 || cells.y < 1 || cells.x > sample_count || cells.y > sample_count ||
       sample_count % (cells.x * cells.y) != 0))
    throw std::invalid_argument("rsaa_shader_defines: cells " + std::to_string(cells.x) + "x" +
                                std::to_string(cells.y) + " do not divide sample_count " + std::to_string(sample_count) +
                                " into whole draws (each at least 1x1)");
  std::string defines = "#define RSAA_SAMPLE_COUNT " + std::to_string(sample_count) + "\n" +
                        "#define RSAA_AUTH " + std::to_string(settings.auth) + "\n" +
                        "#define RSAA_CODE_BITS " + std::to_string(settings.code_bits) + "\n" +
                        "#define RSAA_PREPASS_FIRST_UNIT " + std::to_string(settings.prepass_first_unit) + "\n" +
                        "#define RSAA_UNIFORM_BINDING " + std::to_string(settings.uniform_binding) + "\n";
  if (multisample_prepass) defines += "#define RSAA_PREPASS_MSAA\n";
  else if (settings.prepass == "records") defines += "#define RSAA_PREPASS_RECORDS\n";
  if (multisample_prepass && union_pattern)
    defines += "#define RSAA_PREPASS_MSAA_UNION\n#define RSAA_MS_SAMPLES " + std::to_string(sample_count / 2) + "\n";
  else if (multisample_prepass && cells != glm::ivec2(1, 1))
    defines += "#define RSAA_PREPASS_MSAA_CELLS ivec2(" + std::to_string(cells.x) + ", " + std::to_string(cells.y) +
               ")\n#define RSAA_MS_SAMPLES " + std::to_string(sample_count / (cells.x * cells.y)) + "\n";
  if (settings.similarity == "depth") defines += "#define RSAA_SIMILARITY_DEPTH\n";
  else if (settings.similarity == "sadp-plane") defines += "#define RSAA_SIMILARITY_SADP_PLANE\n";
  else if (settings.similarity != "sadp")
    throw std::invalid_argument("RSAA similarity '" + settings.similarity +
                                "' is not one of sadp, depth, sadp-plane");
  if (!(settings.split_cap == 0.0f || (settings.split_cap >= 1.0f && std::isfinite(settings.split_cap))))
    throw std::invalid_argument("RSAA split_cap must be 0 (the paper's split) or a finite number >= 1");
  if (settings.multi_surface != "fetch" && settings.multi_surface != "neighbours" && settings.multi_surface != "borrow")
    throw std::invalid_argument("RSAA multi_surface must be fetch, neighbours or borrow, not '" + settings.multi_surface +
                                "'");
  if (!(settings.borrow_weight >= 0.0f && settings.borrow_weight <= 1.0f))
    throw std::invalid_argument("RSAA borrow_weight must be a number in [0, 1]");
  if (settings.split_check != "off" && settings.split_check != "neighbours")
    throw std::invalid_argument("RSAA split_check must be off or neighbours, not '" + settings.split_check + "'");
  if (settings.fetch_check != "off" && settings.fetch_check != "neighbours")
    throw std::invalid_argument("RSAA fetch_check must be off or neighbours, not '" + settings.fetch_check + "'");
  if (settings.depth != "gl" && settings.depth != "zero-to-one" && settings.depth != "reverse-z")
    throw std::invalid_argument("RSAA depth must be gl, zero-to-one or reverse-z, not '" + settings.depth + "'");
  if (zero_to_one(settings)) defines += "#define RSAA_DEPTH_ZERO_TO_ONE\n";
  if (settings.split_cap > 0.0f) defines += "#define RSAA_SPLIT_CAP " + glsl_float(settings.split_cap) + "\n";
  if (settings.multi_surface != "fetch") defines += "#define RSAA_MULTI_SURFACE_NEIGHBOURS\n";
  // Borrowed colours need the subsamples' surfaces, which only the pre-passes writing records keep:
  // with the jittered pre-pass "borrow" resolves as "neighbours".
  if (settings.multi_surface == "borrow" && (multisample_prepass || settings.prepass == "records"))
    defines += std::string("#define RSAA_MULTI_SURFACE_BORROW\n#define RSAA_SOURCES_FORMAT ") +
               sources_image_format(sample_count) + "\n#define RSAA_BORROW_WEIGHT " +
               glsl_float(settings.borrow_weight) + "\n";
  if (settings.split_check == "neighbours") defines += "#define RSAA_SPLIT_CHECK_NEIGHBOURS\n";
  if (settings.fetch_check == "neighbours") defines += "#define RSAA_FETCH_CHECK_NEIGHBOURS\n";
  if (settings.material_edges) defines += "#define RSAA_MATERIAL_EDGES\n";
  if (settings.output_mask) defines += "#define RSAA_OUTPUT_MASK\n";
  return defines;
}

std::string rsaa_shader_file(const std::string& name) { return gl::shader_source(name); }

int rsaa_sources_channels(int sample_count) { return sample_count <= 4 ? 1 : sample_count <= 8 ? 2 : 4; }

int rsaa_record_first_unit(int prepass_first_unit) {
  constexpr int kRecordUnits = 4;  // records and depths of each of a union pattern's two draws
  return prepass_first_unit >= kRecordUnits ? 0 : prepass_first_unit + 3;
}

std::string rsaa_record_pass_defines(const SamplePattern& pattern, int first_record_unit, int first_code_image,
                                     int list_binding, int sources_image) {
  std::string windows;
  for (const Vec2& position : pattern.positions) {  // window space, from the pixel's lower-left corner
    const Vec2 gl = pixel_to_gl(position);
    char entry[96];
    std::snprintf(entry, sizeof entry, "%svec2(%.9g, %.9g)", windows.empty() ? "" : ", ", 0.5 + gl.x, 0.5 + gl.y);
    windows += entry;
  }
  return "#define RSAA_LIST_BINDING " + std::to_string(list_binding) + "\n#define RSAA_RECORD_FIRST_UNIT " +
         std::to_string(first_record_unit) + "\n#define RSAA_RECORD_CODE_IMAGES " + std::to_string(first_code_image) +
         "\n#define RSAA_SUBSAMPLE_WINDOWS vec2[](" + windows + ")\n#define RSAA_RECORD_SOURCES_IMAGE " +
         std::to_string(sources_image) + "\n";
}

RsaaPass::RsaaPass(const RsaaSettings& settings, int width, int height)
    : settings_(settings), width_(width), height_(height), gl_(std::make_unique<Objects>()) {
  gl::check_none_pending("RsaaPass::RsaaPass");
  gl::require_gl45("RsaaPass::RsaaPass");
  require_image_size("RsaaPass", width, height);
  if (settings.auth < 0 || settings.auth > 2)
    throw std::invalid_argument("RSAA auth must be 0, 1 or 2");
  if (!(settings.threshold >= 0.0f)) throw std::invalid_argument("RSAA threshold must be >= 0");
  GLint units = 0, bindings = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
  glGetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &bindings);
  if (settings.prepass_first_unit < 0 || settings.prepass_first_unit > units - 3)  // (no overflow near INT_MAX)
    throw std::invalid_argument("RSAA prepass_first_unit " + std::to_string(settings.prepass_first_unit) +
                                ": the pre-pass needs units " + std::to_string(settings.prepass_first_unit) +
                                " to +2, this driver has " + std::to_string(units) + " fragment texture units");
  if (settings.facet_materials) {
    GLint geometry_units = 0;
    glGetIntegerv(GL_MAX_GEOMETRY_TEXTURE_IMAGE_UNITS, &geometry_units);
    const int unit = settings.facet_colours_unit;
    // Two samplers of different types on one unit make a draw fail (GL_INVALID_OPERATION), which
    // some drivers do not report: refused here instead.
    if (unit < 0 || unit >= geometry_units || (unit >= settings.prepass_first_unit && unit <= settings.prepass_first_unit + 2))
      throw std::invalid_argument("RSAA facet_colours_unit " + std::to_string(unit) +
                                  ": must be below this driver's " + std::to_string(geometry_units) +
                                  " geometry texture units and not one of the pre-pass's units " +
                                  std::to_string(settings.prepass_first_unit) + " to +2");
  }
  if (settings.uniform_binding < 0 || settings.uniform_binding >= bindings)
    throw std::invalid_argument("RSAA uniform_binding " + std::to_string(settings.uniform_binding) +
                                " is not below this driver's " + std::to_string(bindings) + " uniform buffer bindings");
  const OffsetTable table = table_of(settings);
  pattern_ = table.pattern;
  gl_->table = table_texture(table);
  gl_->bilinear = gl::make_sampler(GL_LINEAR);
  gl_->nearest = gl::make_sampler(GL_NEAREST);

  const int n = pattern_.size();
  if (settings.post != "edges" && settings.post != "single" && settings.post != "compute")
    throw std::invalid_argument("RSAA post '" + settings.post + "' is not one of edges, compute, single");
  if (settings.prepass != "auto" && settings.prepass != "jittered" && settings.prepass != "msaa" &&
      settings.prepass != "records")
    throw std::invalid_argument("RSAA prepass '" + settings.prepass + "' is not one of auto, jittered, msaa, records");
  if (settings.prepass_cull != "off" && settings.prepass_cull != "neighbours")
    throw std::invalid_argument("RSAA prepass_cull '" + settings.prepass_cull + "' is not one of off, neighbours");
  cull_ = settings.prepass_cull == "neighbours";
  if (cull_ && (settings.prepass == "msaa" || settings.prepass == "records"))
    throw std::invalid_argument("RSAA prepass_cull neighbours needs the jittered pre-pass, not '" + settings.prepass + "'");
  if (settings.facet_materials && !settings.material_edges)
    throw std::invalid_argument("RSAA facet_materials needs material_edges: facets differ by their materials");
  layered_ = settings.prepass == "records";
  // "auto": the multisample pre-pass where the driver samples the pattern (and its pixel list can
  // address the image), else the jittered draws writing records where these fit the budget, else
  // the jittered pre-pass.
  const bool auto_may_list = settings.prepass == "auto" && !cull_ && width <= 65536 && height <= 65536;
  const bool may_multisample = settings.prepass == "msaa" || auto_may_list;
  multisample_ = may_multisample && driver_samples_pattern(pattern_);
  std::vector<glm::ivec2> union_raster, cell_offsets;
  // A cell pattern's draw (and a union's two) keeps the records of every subsample, as "records"
  // does: "auto" takes it within the same budget (16 subsamples at 1920x1080 keep 380 MiB).
  const bool records_fit =
      double(width) * height * n * kRecordBytesPerSubsample <= double(settings.auto_records_max_bytes);
  glm::ivec2 cells{1, 1};
  if (may_multisample && !multisample_ && driver_samples_cells(pattern_, width, height, cells, cell_offsets) &&
      (settings.prepass == "msaa" || records_fit))
    multisample_ = true, cells_ = cells;
  else
    cell_offsets.clear();
  if (may_multisample && !multisample_) {
    // A union's two draws keep every subsample's record too: the same budget under "auto".
    multisample_ = union_ = driver_samples_union(pattern_, union_shift_, union_raster) &&
                            (settings.prepass == "msaa" || records_fit);
    if (!multisample_ && settings.prepass == "msaa")
      throw std::invalid_argument("RSAA prepass msaa: this driver has no " + std::to_string(n) +
                                  "-sample integer target at the positions of pattern '" + pattern_.name + "'" +
                                  (n % 2 == 0 && n >= 4 ? ", nor fewer-sample draws at a multiple of the image's "
                                                          "size, or two whose union they are"
                                                        : ""));
  }
  if (auto_may_list && !multisample_ && record_units_fit(settings.prepass_first_unit) && records_fit) {
    layered_ = true;
    settings_.prepass = "records";  // the shaders' defines (rsaa_shader_defines) follow it
  }
  for (int k = 0; k < (n + 3) / 4; ++k) gl_->codes.push_back(gl::make_texture_2d(code_format(settings.code_bits), width, height));
  if (borrows()) {
    gl_->sources = gl::make_texture_2d(sources_format(n), width, height);
    const GLuint none[4] = {0, 0, 0, 0};  // (the codes pass writes every pixel the post-process reads)
    glClearTexImage(gl_->sources.get(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, none);
  }
  if (multisample_) {
    const int m = raster_samples();
    const glm::ivec2 raster = raster_size();
    const auto make_draw_target = [&](gl::Texture& records, gl::Texture& depth) {
      records = gl::make_texture_2d_multisample(GL_RG32UI, raster.x, raster.y, m);
      depth = gl::make_texture_2d_multisample(GL_DEPTH_COMPONENT32F, raster.x, raster.y, m);
      return gl::make_framebuffer({{records.get()}}, {depth.get()});
    };
    gl_->multisample_target = make_draw_target(gl_->records, gl_->record_depths);
    if (union_) gl_->multisample_target2 = make_draw_target(gl_->records2, gl_->record_depths2);
  } else if (layered_) {
    gl_->records = gl::make_texture_2d_array(GL_RG32UI, width, height, n);
    gl_->record_depths = gl::make_texture_2d_array(GL_DEPTH_COMPONENT32F, width, height, n);
    for (int i = 0; i < n; ++i)
      gl_->subsample_targets.push_back(gl::make_framebuffer({{gl_->records.get(), i}}, {gl_->record_depths.get(), i}));
  } else {
    gl_->subsample_depth = gl::make_texture_2d(cull_ ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F, width, height);
    const gl::Attachment depth{gl_->subsample_depth.get()};
    std::vector<gl::Attachment> all_codes;
    for (const gl::Texture& codes : gl_->codes) {
      gl_->subsample_targets.push_back(gl::make_framebuffer({{codes.get()}}, depth));
      all_codes.push_back({codes.get()});
    }
    if (cull_) gl_->cull_target = gl::make_framebuffer(all_codes, depth);
  }

  // The uniform block: the frame's fields are written per call, the neighbours once.
  std::vector<std::int32_t> block(sizeof(RsaaUniformHead) / 4 + 4 * std::size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    std::int32_t* entry = &block[sizeof(RsaaUniformHead) / 4 + 4 * std::size_t(i)];
    const glm::ivec2 step = window_step(pattern_.positions[i]);
    entry[0] = step.x, entry[1] = step.y;
    if (union_ && i >= n / 2) entry[2] = union_raster[i - n / 2].x, entry[3] = union_raster[i - n / 2].y;
    if (!cell_offsets.empty()) entry[2] = cell_offsets[std::size_t(i)].x, entry[3] = cell_offsets[std::size_t(i)].y;
  }
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  gl_->uniforms = gl::Buffer(buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(block.size() * 4), block.data(), GL_DYNAMIC_STORAGE_BIT);

  const std::string defines = rsaa_shader_defines(settings_, n, multisample_, union_, cells_);
  gl_->subsample_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("scene.vert")},
                                             {GL_GEOMETRY_SHADER, gl::shader_source("scene.geom")},
                                             {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_subsample.frag")}},
                                            defines + (settings.facet_materials ? "#define SCENE_FACET_MATERIALS\n" : ""),
                                            "RSAA pre-pass");
  if (settings.facet_materials)
    glProgramUniform1i(gl_->subsample_program.get(),
                       glGetUniformLocation(gl_->subsample_program.get(), "u_facet_colours"), settings.facet_colours_unit);
  if (cull_)
    gl_->cull_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                          {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_prepass_cull.frag")}},
                                         defines, "RSAA pre-pass culling");
  if (settings.post != "compute")
    gl_->post_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                          {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_post.frag")}},
                                         defines + "#define RSAA_POST_FIRST_UNIT " + std::to_string(kColourUnit) + "\n",
                                         "RSAA post-process");
  if (settings.post == "edges") {
    gl_->edge_program = gl::make_program({{GL_VERTEX_SHADER, gl::shader_source("fullscreen.vert")},
                                          {GL_FRAGMENT_SHADER, gl::shader_source("rsaa_post_edges.frag")}},
                                         defines + "#define RSAA_POST_FIRST_UNIT " + std::to_string(kColourUnit) + "\n",
                                         "RSAA post-process edge pass");
    gl_->edge_depth = gl::make_texture_2d(GL_DEPTH_COMPONENT16, width, height);
  }
  // The compute post-process and the record passes of the pre-passes that write surface records
  // list pixels (a list buffer each). The list packs a pixel's x and y into 16 bits each.
  if ((settings.post == "compute" || writes_records()) && (width > 65536 || height > 65536))
    throw std::invalid_argument("RSAA " + (writes_records() ? "prepass " + settings.prepass : std::string("post compute")) +
                                ": the pixel list packs coordinates into 16 bits; a " + std::to_string(width) + "x" +
                                std::to_string(height) + " image needs " +
                                (writes_records() ? "the jittered pre-pass" : "post edges"));
  const std::string list_defines = "#define RSAA_LIST_BINDING " + std::to_string(kEdgeListBinding) + "\n";
  if (settings.post == "compute" || writes_records()) {
    gl_->list_size_program = gl::make_program({{GL_COMPUTE_SHADER, gl::shader_source("rsaa_post_list_size.comp")}},
                                              defines + list_defines, "RSAA pixel list size");
    // Every pixel of the image, or as many rows as the driver's storage block holds (8192 x 4096
    // on llvmpipe's 128 MiB was refused: the passes then list and resolve in rounds of rows).
    GLint64 max_block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
    make_lists(std::min(GLint64(width) * height, (max_block - kListHeadBytes) / 4));
  }
  if (writes_records()) {
    if (!record_units_fit(settings.prepass_first_unit)) {
      GLint compute_units = 0;
      glGetIntegerv(GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, &compute_units);
      throw std::invalid_argument("RSAA prepass " + settings.prepass + ": its compute passes need texture units " +
                                  std::to_string(settings.prepass_first_unit) + " to +2 and " +
                                  std::to_string(record_first_unit(settings.prepass_first_unit)) + " to +" +
                                  std::to_string(kRecordUnits - 1) + ", this driver has " +
                                  std::to_string(compute_units) + " compute texture units (lower prepass_first_unit)");
    }
    // The records as images where the image units suffice and, for multisample records, the
    // driver loads multisample images of that many samples.
    GLint image_samples = 0, image_units = 0;
    glGetIntegerv(GL_MAX_IMAGE_SAMPLES, &image_samples);
    glGetIntegerv(GL_MAX_COMPUTE_IMAGE_UNIFORMS, &image_units);
    make_record_programs((layered_ || image_samples >= raster_samples()) &&
                         kFirstCodeImageUnit + int(gl_->codes.size()) + kRecordImages <= image_units);
  }
  if (settings.post == "compute") {
    const std::string post_defines = defines + "#define RSAA_POST_FIRST_UNIT " + std::to_string(kColourUnit) + "\n" +
                                     list_defines;
    // The listing pass and the resolve read the integer targets as images: codes, normal,
    // primitive from kFirstCodeImageUnit (2 + 4 + 2 units at 16 subsamples, GL's least maximum 8),
    // the resolve where its images and the list's storage block fit the driver's limits (GL's
    // least combined maximum is 8 too: with 16 subsamples, the mask and material edges the
    // resolve would need 9), else through textures, as before session 29.
    const std::string image_defines = "#define RSAA_CODE_IMAGES " + std::to_string(kFirstCodeImageUnit) + "\n";
    GLint image_uniforms = 0, combined = 0;
    glGetIntegerv(GL_MAX_COMPUTE_IMAGE_UNIFORMS, &image_uniforms);
    glGetIntegerv(GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES, &combined);
    const int resolve_images = kFirstCodeImageUnit + post_read_images(int(gl_->codes.size()), settings.material_edges);
    gl_->resolve_reads_images = resolve_images <= image_uniforms && resolve_images + 1 <= combined;
    gl_->classify_program = gl::make_program(
        {{GL_COMPUTE_SHADER, gl::shader_source("rsaa_post_classify.comp")}},
        post_defines + image_defines, "RSAA post-process edge list");
    glGetProgramiv(gl_->classify_program.get(), GL_COMPUTE_WORK_GROUP_SIZE, gl_->classify_group);
    gl_->scatter_program = gl::make_program({{GL_COMPUTE_SHADER, gl::shader_source("rsaa_post_scatter.comp")}},
                                            post_defines + "#define RSAA_SCRATCH_UNIT " + std::to_string(kScratchUnit) + "\n",
                                            "RSAA post-process in place");
    gl_->list_resolve_program = gl::make_program({{GL_COMPUTE_SHADER, gl::shader_source("rsaa_post_resolve.comp")}},
                                                 post_defines + (gl_->resolve_reads_images ? image_defines : ""),
                                                 "RSAA post-process resolve of the edge list");
  }
  gl::check("creating the RSAA pass");
}
double RsaaPass::bytes_per_pixel(bool resolves_in_place) const {
  const int n = pattern_.size();
  const double code_bytes = settings_.code_bits / 8.0;
  double bytes = 0.0;
  bytes += (n + 3) / 4 * 4 * code_bytes;  // RGBA code texels
  if (writes_records())
    bytes += n * kRecordBytesPerSubsample;  // (both draws of a union)
  else
    bytes += cull_ ? 8.0 : 4.0;  // the draws' depth (+ stencil)
  if (borrows()) bytes += 4.0 * rsaa_sources_channels(n);  // the sources
  if (settings_.post == "edges") bytes += 2.0;  // the 16-bit depth the edge pass marks
  const int lists = (settings_.post == "compute" ? 1 : 0) + (writes_records() ? 1 : 0);  // (edges, pixels to code)
  bytes += lists * double(kListHeadBytes + 4 * list_capacity_) / (double(width_) * height_);
  // The scratch, in the colour's format: 8 bytes for RGBA16F (4 for 32-bit formats, 16 for RGBA32F).
  if (settings_.post == "compute" && resolves_in_place) bytes += 8.0;
  return bytes;
}

RsaaPass::~RsaaPass() = default;
RsaaPass::RsaaPass(RsaaPass&&) noexcept = default;
RsaaPass& RsaaPass::operator=(RsaaPass&&) noexcept = default;

std::string RsaaPass::prepass_description() const {
  const int n = pattern_.size();
  const std::string draws = std::to_string(n) + (n == 1 ? " jittered draw" : " jittered draws");
  if (layered_) return "records, " + draws + " writing surface records";
  if (!multisample_)
    return "jittered, " + draws + (cull_ ? " behind the neighbourhood culling" : "") +
           (settings_.multi_surface == "borrow" ? " (no borrowed colours: it keeps no subsample's surface)" : "");
  const std::string samples = std::to_string(raster_samples()) + "-sample draw";
  if (union_) return "msaa, two " + samples + "s (a union pattern)";
  if (cells_ == glm::ivec2(1, 1)) return "msaa, one " + samples;
  return "msaa, one " + samples + " at " + std::to_string(cells_.x) + "x" + std::to_string(cells_.y) + " cells (" +
         std::to_string(raster_size().x) + "x" + std::to_string(raster_size().y) + ")";
}

std::string RsaaPass::prepass_glsl() const {
  require_not_moved_from(gl_.get(), "RsaaPass::prepass_glsl");
  return "// RSAA pre-pass for pattern " + pattern_.name + " (generated by RsaaPass::prepass_glsl)\n" +
         rsaa_prepass_text(rsaa_shader_defines(settings_, pattern_.size(), multisample_, union_, cells_));
}

std::vector<GlName> RsaaPass::code_textures() const {
  require_not_moved_from(gl_.get(), "RsaaPass::code_textures");
  std::vector<GlName> names;
  for (const gl::Texture& t : gl_->codes) names.push_back(t.get());
  return names;
}

void RsaaPass::write_frame_uniforms(const RsaaFrame& frame) const {
  RsaaUniformHead head{};
  std::copy_n(glm::value_ptr(frame.inverse_projection), 16, head.inverse_projection);
  head.viewport[0] = float(frame.width), head.viewport[1] = float(frame.height);
  head.threshold = settings_.threshold;
  head.subsample = -1;
  glNamedBufferSubData(gl_->uniforms.get(), 0, sizeof head, &head);
  glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(settings_.uniform_binding), gl_->uniforms.get());
}

// The record passes' programs, reading the records as images or (a driver without multisample
// image loads of that many samples) as textures.
void RsaaPass::make_record_programs(bool record_images) {
  std::string defines = rsaa_shader_defines(settings_, pattern_.size(), multisample_, union_, cells_) +
                        rsaa_record_pass_defines(pattern_, record_first_unit(settings_.prepass_first_unit),
                                                 kFirstCodeImageUnit, kEdgeListBinding, kSourcesImageUnit);
  if (settings_.post == "compute") defines += "#define RSAA_EDGE_LIST_BINDING " + std::to_string(kRecordEdgeListBinding) + "\n";
  gl_->record_images = record_images;
  if (record_images)
    defines += "#define RSAA_RECORD_IMAGES " + std::to_string(kFirstCodeImageUnit + int(gl_->codes.size())) + "\n";
  gl_->record_list_program = gl::make_program({{GL_COMPUTE_SHADER, gl::shader_source("rsaa_prepass_list.comp")}},
                                              defines, "RSAA pre-pass record list");
  glGetProgramiv(gl_->record_list_program.get(), GL_COMPUTE_WORK_GROUP_SIZE, gl_->record_list_group);
  gl_->record_codes_program = gl::make_program({{GL_COMPUTE_SHADER, gl::shader_source("rsaa_prepass_codes.comp")}},
                                               defines, "RSAA pre-pass record codes");
}

// The multisample pre-pass's record passes (shaders/rsaa_prepass_records.glsl): the codes of every
// pixel from the records and depths of its draws, the similarities computed for the listed pixels
// only (a sample on another triangle than the centre's). Called by run_prepass() with the frame's
// centre textures and the uniform block bound.
void RsaaPass::codes_from_records() {
  const int record_unit = record_first_unit(settings_.prepass_first_unit);
  const int code_images = int(gl_->codes.size());
  // The records and depths of each draw (two units, four for a union pattern's two draws).
  const int record_units = union_ ? kRecordUnits : 2;
  std::vector<int> image_units, units;
  for (int k = 0; k < code_images + (gl_->record_images ? kRecordImages : 0); ++k) image_units.push_back(kFirstCodeImageUnit + k);
  if (borrows()) image_units.push_back(kSourcesImageUnit);
  for (int k = 0; k < record_units; ++k) units.push_back(record_unit + k);
  const gl::SavedState saved(units);
  const gl::SavedComputeState saved_compute({kEdgeListBinding, kRecordEdgeListBinding}, image_units);
  const GLuint records[kRecordUnits] = {gl_->records.get(), gl_->record_depths.get(), gl_->records2.get(),
                                        gl_->record_depths2.get()};
  glBindTextures(GLuint(record_unit), record_units, records);
  const GLboolean layered = layered_ ? GL_TRUE : GL_FALSE;  // array textures: every layer
  const std::vector<GLuint> samplers(kRecordUnits, gl_->nearest.get());
  glBindSamplers(GLuint(record_unit), record_units, samplers.data());
  for (int k = 0; k < code_images; ++k)
    glBindImageTexture(GLuint(kFirstCodeImageUnit + k), gl_->codes[std::size_t(k)].get(), 0, GL_FALSE, 0,
                       GL_WRITE_ONLY, code_format(settings_.code_bits));
  if (gl_->record_images)
    for (int d = 0; d < (union_ ? 2 : 1); ++d)
      glBindImageTexture(GLuint(kFirstCodeImageUnit + code_images + d), records[2 * d], 0, layered, 0, GL_READ_ONLY,
                         GL_RG32UI);
  if (borrows())
    glBindImageTexture(kSourcesImageUnit, gl_->sources.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, sources_format(pattern_.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeListBinding, gl_->record_list.get());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, gl_->record_list.get());
  // Rounds of rows when the list cannot hold every pixel, as the compute post-process does. In one
  // round the record passes list the post-process's edges too (in rounds, the post-process lists
  // them round by round).
  const int rows = int(std::min<std::int64_t>(height_, list_capacity_ / width_));
  edges_listed_ = settings_.post == "compute" && rows == height_;
  if (settings_.post == "compute") {
    glProgramUniform1i(gl_->record_list_program.get(), kRecordListEdgesLocation, edges_listed_ ? 1 : 0);
    glProgramUniform1i(gl_->record_codes_program.get(), kRecordListEdgesLocation, edges_listed_ ? 1 : 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRecordEdgeListBinding, gl_->edge_list.get());
    if (edges_listed_) {
      const GLuint empty_list[4] = {0, 1, 1, 0};  // rsaa_post_list.glsl's head
      glNamedBufferSubData(gl_->edge_list.get(), 0, sizeof empty_list, empty_list);
    }
  }
  for (int first = 0; first < height_; first += rows) {
    const int end = std::min(first + rows, height_);
    const GLuint empty_list[4] = {0, 1, 1, 0};
    glNamedBufferSubData(gl_->record_list.get(), 0, sizeof empty_list, empty_list);
    glUseProgram(gl_->record_list_program.get());
    glUniform2i(kRecordRowsLocation, first, end);
    const GLint* group = gl_->record_list_group;
    glDispatchCompute(GLuint((width_ + group[0] - 1) / group[0]), GLuint((end - first + group[1] - 1) / group[1]), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(gl_->list_size_program.get());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    glUseProgram(gl_->record_codes_program.get());
    glDispatchComputeIndirect(0);
    // The next round rewrites the list this one read; the codes pass stored over the list pass's.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  // The post-process (or the engine's) reads the codes next, as images or textures, and the edge list.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void RsaaPass::run_prepass(const RsaaFrame& frame, const std::function<void(int subsample, glm::vec2 jitter_ndc)>& draw) {
  gl::check_none_pending("RsaaPass::render_subsamples");
  validate_frame(frame, width_, height_, settings_);
  codes_ready_ = false;  // until every draw is done (a callback may throw)
  edges_listed_ = false;
  prepass_frame_[0] = frame.centre_normal, prepass_frame_[1] = frame.centre_primitive;
  prepass_frame_[2] = frame.centre_depth;
  const int first = settings_.prepass_first_unit;
  const gl::SavedState saved({first, first + 1, first + 2}, {settings_.uniform_binding});
  gl::set_pass_state(true);  // before the clears: they obey the engine's scissor and masks
  write_frame_uniforms(frame);
  const GLuint textures[3] = {frame.centre_normal, frame.centre_primitive, frame.centre_depth};
  glBindTextures(GLuint(first), 3, textures);
  const GLuint samplers[3] = {gl_->nearest.get(), gl_->nearest.get(), gl_->nearest.get()};
  glBindSamplers(GLuint(first), 3, samplers);
  const GLuint zero[4] = {0, 0, 0, 0};
  const bool reverse_z = settings_.depth == "reverse-z";
  const GLfloat far_depth = reverse_z ? 0.0f : 1.0f;
  // The pass's depth state for a draw: the nearest surface wins.
  const auto set_depth_state = [&] {
    gl::set_pass_state(true);
    if (reverse_z) glDepthFunc(GL_GREATER);
  };
  // Each draw goes into the framebuffer and viewport the pass has just set: a callback that binds
  // or sets its own draws elsewhere, and the codes would be the last frame's, silently.
  const auto checked_draw = [&](int subsample, glm::vec2 jitter) {
    GLint framebuffer = 0, set[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, set);
    draw(subsample, jitter);
    GLint after = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &after);
    glGetIntegerv(GL_VIEWPORT, viewport);
    if (after != framebuffer)
      throw std::logic_error("RSAA pre-pass: the draw callback bound framebuffer " + std::to_string(after) +
                             "; it must draw into the one the pass bound (" + std::to_string(framebuffer) + ")");
    if (!std::equal(viewport, viewport + 4, set))
      throw std::logic_error("RSAA pre-pass: the draw callback set the viewport to " + std::to_string(viewport[0]) +
                             "," + std::to_string(viewport[1]) + " " + std::to_string(viewport[2]) + "x" +
                             std::to_string(viewport[3]) + "; the pass draws the frame's 0,0 " +
                             std::to_string(set[2]) + "x" + std::to_string(set[3]) +
                             (set[2] != frame.width || set[3] != frame.height ? " (its cells: a multiple of the image)" : ""));
  };
  const auto write_per_draw = [&](glm::vec2 jitter, int subsample, Vec2 sample_shift) {
    const RsaaUniformPerDraw per_draw = {
        {jitter.x, jitter.y}, settings_.threshold, subsample, {float(sample_shift.x), float(sample_shift.y)}};
    glNamedBufferSubData(gl_->uniforms.get(), kJitterOffset, sizeof per_draw, &per_draw);
  };
  if (multisample_) {  // one draw (two for a union), the fragment shader run once per pixel
    for (int d = 0; d < (union_ ? 2 : 1); ++d) {
      // Records to 0 (no surface: rsaa_prepass.glsl); the materials are read only where a record is.
      const GLuint fb = (d == 0 ? gl_->multisample_target : gl_->multisample_target2).get();
      set_depth_state();  // before the clears too: the previous callback may have masked depth
      glClearNamedFramebufferuiv(fb, GL_COLOR, 0, zero);
      glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
      glBindFramebuffer(GL_FRAMEBUFFER, fb);
      glViewport(0, 0, raster_size().x, raster_size().y);  // a cell pattern's draw: a multiple of the image
      // A record is the triangle's, whichever sample: shading once per pixel writes it to every
      // covered sample (the depth buffer holds each sample's own depth).
      glDisable(GL_SAMPLE_SHADING);
      // The shifted draw: the image moves by -shift, so that raster sample i sees the point at
      // its position + shift.
      const Vec2 shift = d == 0 ? Vec2{0.0, 0.0} : union_shift_;
      const glm::vec2 jitter = d == 0 ? glm::vec2(0.0f) : jitter_ndc_for_sample(shift.x, shift.y, frame.width, frame.height);
      write_per_draw(jitter, d == 0 ? 0 : pattern_.size() / 2, pixel_to_gl(shift));
      checked_draw(-1, jitter);
    }
    codes_from_records();
    gl::check("RSAA pre-pass (multisample)");
    codes_ready_ = true;
    return;
  }
  if (layered_) {  // a jittered draw per subsample, each writing surface records into its own layers
    // The whole arrays at once (glClearTexImage ignores the scissor and masks). Clearing each layer
    // through its framebuffer before its draw, which llvmpipe bins with the draw, saves 0.5-3 ms
    // on the default scene at 1280x720 but costs the spider 2-8 ms (session 28; every tile cleared
    // per draw, most of them empty).
    glClearTexImage(gl_->records.get(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, nullptr);  // 0: no surface
    glClearTexImage(gl_->record_depths.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far_depth);
    for (int i = 0; i < pattern_.size(); ++i) {
      glBindFramebuffer(GL_FRAMEBUFFER, gl_->subsample_targets[std::size_t(i)].get());
      set_depth_state();  // again: the previous callback may have changed it
      glViewport(0, 0, frame.width, frame.height);
      const Vec2 s = pattern_.positions[i];
      const glm::vec2 jitter = jitter_ndc_for_sample(s.x, s.y, frame.width, frame.height);
      write_per_draw(jitter, i, {0.0, 0.0});
      checked_draw(i, jitter);
    }
    codes_from_records();
    gl::check("RSAA pre-pass (records)");
    codes_ready_ = true;
    return;
  }
  if (cull_) {
    // Codes 1 and stencil 0 everywhere, then codes 0 and stencil 1 where a pixel needs the draws.
    const GLuint fb = gl_->cull_target.get();
    const GLuint one[4] = {1, 1, 1, 1};
    for (GLint k = 0; k < GLint(gl_->codes.size()); ++k) glClearNamedFramebufferuiv(fb, GL_COLOR, k, one);
    const GLint no_stencil = 0;
    glClearNamedFramebufferiv(fb, GL_STENCIL, 0, &no_stencil);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glViewport(0, 0, frame.width, frame.height);
    gl::set_pass_state(false);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFFu);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glUseProgram(gl_->cull_program.get());
    draw_fullscreen_triangle();

  } else {
    for (const gl::Framebuffer& fb : gl_->subsample_targets) glClearNamedFramebufferuiv(fb.get(), GL_COLOR, 0, zero);
  }
  for (int i = 0; i < pattern_.size(); ++i) {
    // Subsample i goes to channel i % 4 of code texture i / 4; the depth buffer is its own.
    const GLuint fb = gl_->subsample_targets[i / 4].get();
    set_depth_state();  // again, before the clear: the previous callback may have changed it
    glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glViewport(0, 0, frame.width, frame.height);
    const Vec2 s = pattern_.positions[i];
    const glm::vec2 jitter = jitter_ndc_for_sample(s.x, s.y, frame.width, frame.height);
    write_per_draw(jitter, i, {0.0, 0.0});
    if (cull_) {  // only where the marking pass set stencil 1; an early test skips the rest
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 1, 0xFFu);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      glStencilMask(0u);
    }
    glColorMaski(0, i % 4 == 0, i % 4 == 1, i % 4 == 2, i % 4 == 3);
    checked_draw(i, jitter);
  }
  gl::check("RSAA pre-pass");
  codes_ready_ = true;
}

void RsaaPass::render_subsamples(const RsaaFrame& frame, const DrawGeometry& draw_geometry) {
  require_not_moved_from(gl_.get(), "RsaaPass::render_subsamples");
  const GLuint program = gl_->subsample_program.get();
  run_prepass(frame, [&](int, glm::vec2 jitter_ndc) {
    glUseProgram(program);
    draw_geometry(program, jitter_ndc);
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) != program)
      throw std::logic_error("RSAA pre-pass: the draw callback drew with program " + std::to_string(current) +
                             ", not the pre-pass program " + std::to_string(program) + " it was given");
    require_prepass_bindings_kept(frame);
  });
}

void RsaaPass::render_subsamples_with_own_shaders(const RsaaFrame& frame, const std::function<void()>& draw) {
  require_not_moved_from(gl_.get(), "RsaaPass::render_subsamples_with_own_shaders");
  run_prepass(frame, [&](int, glm::vec2) {
    draw();
    // What the engine's draw must leave alone, checked after the fact: a clear error, never
    // codes computed from another texture.
    GLint current = 0, pipeline = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glGetIntegerv(GL_PROGRAM_PIPELINE_BINDING, &pipeline);
    if (current == 0 && pipeline != 0)
      throw std::logic_error("RSAA pre-pass: the engine's draw used program pipeline " + std::to_string(pipeline) +
                             "; the pass checks one program that includes RsaaPass::prepass_glsl() in its stages "
                             "(glUseProgram), not a pipeline of separable programs");
    if (current == 0 ||
        glGetProgramResourceIndex(GLuint(current), GL_UNIFORM_BLOCK, "RsaaUniforms") == GL_INVALID_INDEX)
      throw std::logic_error("RSAA pre-pass: the engine's program " + std::to_string(current) +
                             " has no RsaaUniforms block: its stages must include RsaaPass::prepass_glsl() "
                             "and call rsaa_jitter() and rsaa_prepass_code()");
    if (glGetUniformLocation(GLuint(current), prepass_signature().c_str()) < 0)
      throw std::logic_error("RSAA pre-pass: the engine's program " + std::to_string(current) +
                             " was not built from this pass's RsaaPass::prepass_glsl() (another pass's, or "
                             "one for other settings or another driver: its codes would not be this pass's), "
                             "or its fragment stage does not write rsaa_prepass_code()");
    GLint block_binding = -1;
    glGetActiveUniformBlockiv(GLuint(current),
                              glGetProgramResourceIndex(GLuint(current), GL_UNIFORM_BLOCK, "RsaaUniforms"),
                              GL_UNIFORM_BLOCK_BINDING, &block_binding);
    if (block_binding != settings_.uniform_binding)
      throw std::logic_error("RSAA pre-pass: the engine's program reads RsaaUniforms at binding " +
                             std::to_string(block_binding) + ", not " + std::to_string(settings_.uniform_binding) +
                             " (RsaaSettings::uniform_binding; do not call glUniformBlockBinding on it)");
    require_prepass_bindings_kept(frame);
  });
}

// The pre-pass's uniform buffer, its three texture units and their samplers, as run_prepass()
// bound them: a draw that rebound one computed codes from another texture.
void RsaaPass::require_prepass_bindings_kept(const RsaaFrame& frame) const {
  const int first = settings_.prepass_first_unit;
  const GLuint expected_textures[3] = {frame.centre_normal, frame.centre_primitive, frame.centre_depth};
  GLint bound = 0;
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, GLuint(settings_.uniform_binding), &bound);
  if (GLuint(bound) != gl_->uniforms.get())
    throw std::logic_error("RSAA pre-pass: the engine's draw rebound uniform buffer binding " +
                           std::to_string(settings_.uniform_binding) + " (RsaaSettings::uniform_binding)");
  for (int k = 0; k < 3; ++k) {
    GLint texture = 0;
    glGetIntegeri_v(GL_TEXTURE_BINDING_2D, GLuint(first + k), &texture);
    if (GLuint(texture) != expected_textures[k])
      throw std::logic_error("RSAA pre-pass: the engine's draw rebound texture unit " + std::to_string(first + k) +
                             " (RsaaSettings::prepass_first_unit + " + std::to_string(k) + ")");
    GLint sampler = 0;  // another sampler object (a linear one) makes the integer textures read as zero
    glGetIntegeri_v(GL_SAMPLER_BINDING, GLuint(first + k), &sampler);
    if (GLuint(sampler) != gl_->nearest.get())
      throw std::logic_error("RSAA pre-pass: the engine's draw bound sampler object " + std::to_string(sampler) +
                             " to texture unit " + std::to_string(first + k) + " (RsaaSettings::prepass_first_unit + " +
                             std::to_string(k) + ")");
  }
}

std::string rsaa_prepass_signature(const std::string& defines) {
  // Only what the pre-pass's text reads: a program stays good for passes that differ in their
  // post-process alone (the mask output, the split cap, the checks; authentication but for 2).
  static const char* const kPrePassDefines[] = {
      "RSAA_SAMPLE_COUNT",     "RSAA_CODE_BITS",         "RSAA_PREPASS_FIRST_UNIT", "RSAA_UNIFORM_BINDING",
      "RSAA_PREPASS_MSAA",     "RSAA_PREPASS_RECORDS",   "RSAA_PREPASS_MSAA_UNION", "RSAA_MS_SAMPLES",
      "RSAA_PREPASS_MSAA_CELLS",
      "RSAA_SIMILARITY_DEPTH", "RSAA_SIMILARITY_SADP_PLANE", "RSAA_DEPTH_ZERO_TO_ONE", "RSAA_MATERIAL_EDGES"};
  std::string read;
  std::istringstream lines(defines);
  for (std::string line; std::getline(lines, line);) {
    if (line == "#define RSAA_AUTH 2") read += line + "\n";  // pre-pass authentication
    for (const char* name : kPrePassDefines) {
      const std::string prefix = std::string("#define ") + name;
      if (line.rfind(prefix, 0) == 0 && (line.size() == prefix.size() || line[prefix.size()] == ' ')) read += line + "\n";
    }
  }
  std::uint32_t hash = 2166136261u;  // FNV-1a
  for (const char c : read) hash = (hash ^ std::uint8_t(c)) * 16777619u;
  char name[40];
  std::snprintf(name, sizeof name, "rsaa_prepass_signature_%08x", unsigned(hash));
  return name;
}

std::string rsaa_prepass_text(const std::string& defines) {
  return defines + "#define RSAA_PREPASS_SIGNATURE " + rsaa_prepass_signature(defines) + "\n" +
         rsaa_shader_file("rsaa_prepass.glsl");
}

const std::string& RsaaPass::prepass_signature() const {
  if (prepass_signature_.empty())  // once: the engine's program is checked after every draw
    prepass_signature_ = rsaa_prepass_signature(rsaa_shader_defines(settings_, pattern_.size(), multisample_, union_, cells_));
  return prepass_signature_;
}

void RsaaPass::resolve(const RsaaFrame& frame, GLuint output, GLuint mask_output) {
  require_not_moved_from(gl_.get(), "RsaaPass::resolve");
  gl::check_none_pending("RsaaPass::resolve");
  validate_frame(frame, width_, height_, settings_);
  gl::require_texture(output, kColourFormats, width_, height_, "RsaaPass::resolve output");
  if (settings_.post == "compute" && gl::internal_format_of(output) == GL_SRGB8_ALPHA8) {
    GLint immutable = GL_FALSE;
    glGetTextureParameteriv(output, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    if (!immutable)
      throw std::invalid_argument("RsaaPass::resolve output: texture " + std::to_string(output) +
                                  " is GL_SRGB8_ALPHA8 with mutable storage; the compute post-process stores into "
                                  "an RGBA8 view of an sRGB output, which needs storage made by glTexStorage2D "
                                  "(or RsaaSettings::post \"edges\" or \"single\")");
  }
  if (settings_.output_mask && mask_output)
    gl::require_texture(mask_output, GL_R32UI, width_, height_, "RsaaPass::resolve mask_output");
  if (output == frame.colour && settings_.post != "compute")
    throw std::invalid_argument("RsaaPass::resolve: the output is the frame's colour texture; resolving in place needs "
                                "RsaaSettings::post \"compute\", not \"" + settings_.post +
                                "\" (which reads the colour while it writes it)");
  // Codes never written are undefined (zeros on llvmpipe: a third of a frame's pixels resampled).
  if (!codes_ready_)
    throw std::logic_error("RsaaPass::resolve before render_subsamples (or after one that did not finish): "
                           "the pass has no similarity codes for this frame");
  // Two views pre-passed, then resolved, get the second's codes for both.
  if (prepass_frame_[0] != frame.centre_normal || prepass_frame_[1] != frame.centre_primitive ||
      prepass_frame_[2] != frame.centre_depth)
    throw std::logic_error("RsaaPass::resolve: the frame's centre_normal, centre_primitive or centre_depth is not the "
                           "last render_subsamples' frame's: the codes are another frame's (resolve each frame after "
                           "its own pre-pass)");
  std::vector<int> units;
  for (int unit = 0; unit < kPostUnits; ++unit) units.push_back(unit);
  const gl::SavedState saved(units, {settings_.uniform_binding});
  gl::set_pass_state(false);
  // The pass works in linear light: an sRGB output is encoded as the draws and blits write it (an
  // sRGB colour is decoded as it is read); other formats are written as they are.
  glEnable(GL_FRAMEBUFFER_SRGB);
  std::vector<gl::Attachment> targets = {{output}};
  if (settings_.output_mask) {
    if (!mask_output) throw std::invalid_argument("RSAA resolve: output_mask set but no mask texture");
    targets.push_back({mask_output});
  }
  write_frame_uniforms(frame);
  std::vector<GLuint> samplers(kPostUnits, gl_->nearest.get());  // (an engine's sampler objects are restored)
  samplers[kColourUnit] = gl_->bilinear.get();
  glBindSamplers(0, kPostUnits, samplers.data());
  glBindTextureUnit(kColourUnit, frame.colour);
  glBindTextureUnit(kNormalUnit, frame.centre_normal);
  glBindTextureUnit(kDepthUnit, frame.centre_depth);
  glBindTextureUnit(kTableUnit, gl_->table.get());
  for (std::size_t k = 0; k < gl_->codes.size(); ++k) glBindTextureUnit(GLuint(kFirstCodeUnit + k), gl_->codes[k].get());
  if (settings_.material_edges) glBindTextureUnit(kPrimitiveUnit, frame.centre_primitive);
  if (borrows()) glBindTextureUnit(kSourcesUnit, gl_->sources.get());
  if (settings_.post == "compute") {
    resolve_edge_list(frame, output, mask_output);
    gl::check("RSAA post-process");
    return;
  }
  const bool edges = settings_.post == "edges";
  const GLuint fb = gl_->resolve_target.get(targets, {edges ? gl_->edge_depth.get() : 0u});
  const GLuint edge_fb = edges ? gl_->edge_target.get({}, {gl_->edge_depth.get()}) : 0u;
  glViewport(0, 0, frame.width, frame.height);
  if (edges) {
    // Every pixel's colour as it is (and the all-similar mask): the resolve pass overwrites the
    // edge pixels. An image copy, and an edge pass that writes depth only: on llvmpipe an edge
    // pass that also fetched and wrote every colour cost more (README, *Cheaper post-processes*).
    copy_colour(frame.colour, output);
    if (settings_.output_mask) clear_to_all_similar(mask_output);
    // Edge pass: depth 1 everywhere, then the full-screen triangle's depth (0.5, or 0 under
    // glClipControl GL_ZERO_TO_ONE) where the mask is not all-similar (the others discard).
    glBindFramebuffer(GL_FRAMEBUFFER, edge_fb);
    const GLfloat far_depth = 1.0f;
    glClearNamedFramebufferfv(edge_fb, GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glUseProgram(gl_->edge_program.get());
    draw_fullscreen_triangle();
    // Resolve pass: GL_GEQUAL passes the triangle's depth where the edge pass wrote it only.
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glUseProgram(gl_->post_program.get());
  draw_fullscreen_triangle();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::check("RSAA post-process");
}

// The mask output of a pass that resolves only the edge pixels: every other pixel all-similar.
void RsaaPass::clear_to_all_similar(GLuint mask_output) const {
  const GLuint all_similar = GLuint((std::uint64_t(1) << pattern_.size()) - 1);
  glClearTexImage(mask_output, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &all_similar);
}

// One image into another as it is (the frame's colour into the output), by a framebuffer blit at
// scale 1 (exact): unlike glCopyImageSubData it takes textures that are not mipmap-complete (a
// glTexImage2D output with the default minification filter).
void RsaaPass::copy_colour(GLuint from, GLuint to) {
  const GLuint source = gl_->copy_source.get({{from}}, {});
  const GLuint target = gl_->copy_target.get({{to}}, {});
  glBlitNamedFramebuffer(source, target, 0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void RsaaPass::make_lists(std::int64_t capacity) {
  // At least a row: a round lists whole rows.
  list_capacity_ = std::max<std::int64_t>(capacity, width_);
  edges_listed_ = false;
  const auto make_list = [&] {
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(kListHeadBytes + 4 * list_capacity_), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return gl::Buffer(buffer);
  };
  gl_->edge_list = settings_.post == "compute" ? make_list() : gl::Buffer();
  gl_->record_list = writes_records() ? make_list() : gl::Buffer();
}

std::vector<std::uint32_t> RsaaPass::edge_list_pixels() const {
  if (gl_->edge_list.get() == 0) return {};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint count = 0;
  glGetNamedBufferSubData(gl_->edge_list.get(), 12, 4, &count);
  std::vector<std::uint32_t> pixels(std::min<std::int64_t>(count, list_capacity_));
  glGetNamedBufferSubData(gl_->edge_list.get(), kListHeadBytes, GLsizeiptr(4 * pixels.size()), pixels.data());
  return pixels;
}

namespace {
// Image loads and stores of an incomplete texture are invalid (GL 4.5 section 8.26; loads give
// 0), and completeness is then the texture's own state: one made with glTexImage2D keeps the
// default mipmap minifying filter (with one level, incomplete), and an integer texture with a
// linear filter is incomplete too. Mesa reads and stores all the same; a stricter driver would
// drop the resolved pixels or read every engine normal as the background. While the pass uses an
// engine texture as an image, its filters are ones it is complete with; put back after.
class CompleteForImageAccess {
 public:
  // `integer`: an integer format (both filters must be nearest).
  CompleteForImageAccess(GLuint texture, bool integer) : texture_(texture) {
    if (texture_ == 0) return;
    glGetTextureParameteriv(texture_, GL_TEXTURE_MIN_FILTER, &min_filter_);
    glGetTextureParameteriv(texture_, GL_TEXTURE_MAG_FILTER, &mag_filter_);
    change_min_ = integer ? min_filter_ != GL_NEAREST : min_filter_ != GL_NEAREST && min_filter_ != GL_LINEAR;
    change_mag_ = integer && mag_filter_ != GL_NEAREST;
    if (change_min_) glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    if (change_mag_) glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  ~CompleteForImageAccess() {
    if (change_min_) glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, min_filter_);
    if (change_mag_) glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, mag_filter_);
  }
  CompleteForImageAccess(const CompleteForImageAccess&) = delete;
  CompleteForImageAccess& operator=(const CompleteForImageAccess&) = delete;

 private:
  GLuint texture_;
  GLint min_filter_ = GL_NEAREST, mag_filter_ = GL_NEAREST;
  bool change_min_ = false, change_mag_ = false;
};

// Where the compute post-process stores into a texture: the texture in its own format or, for an
// sRGB one (image units have no sRGB format), an RGBA8 view of its storage (immutable: resolve()
// checked), which the shaders store encoded colours into (rsaa_post_output.glsl). A view per
// call: an engine may delete a texture and make another under its name.
class OutputImage {
 public:
  // 0: none (bind() must not be called).
  explicit OutputImage(GLuint texture) : image_(texture) {
    if (texture == 0) return;
    format_ = gl::internal_format_of(texture);
    if (format_ != GL_SRGB8_ALPHA8) return;
    GLuint view = 0;
    glGenTextures(1, &view);
    glTextureView(view, GL_TEXTURE_2D, texture, GL_RGBA8, 0, 1, 0, 1);
    view_ = gl::Texture(view);
    image_ = view, format_ = GL_RGBA8, encode_srgb_ = true;
  }
  // Binds the image to `unit` for writing and tells `program` whether to encode linear colours
  // (for an sRGB texture, when `linear_colours`; else the values are stored as they come).
  void bind(GLuint unit, GLuint program, bool linear_colours) const {
    glBindImageTexture(unit, image_, 0, GL_FALSE, 0, GL_WRITE_ONLY, format_);
    glProgramUniform1i(program, kOutputSrgbLocation, encode_srgb_ && linear_colours ? 1 : 0);
  }
  // The texture the image unit writes: the texture or its RGBA8 view.
  GLuint image() const { return image_; }

 private:
  GLuint image_;
  GLenum format_ = 0;
  bool encode_srgb_ = false;
  gl::Texture view_;
};
}  // namespace

// The compute post-process (RsaaSettings::post "compute"): the colour image copied as it is, a
// list of the pixels whose mask is not all-similar (rsaa_post_classify.comp), its dispatch size
// (rsaa_post_list_size.comp), then the resolve on the listed pixels only (rsaa_post_resolve.comp,
// glDispatchComputeIndirect). In place (output == frame.colour) without the copy: the listed
// pixels are resolved into a scratch image and then copied into the colour
// (rsaa_post_scatter.comp). On a driver that runs a SIMD batch's branches both ways (llvmpipe)
// the edge pass and depth test of "edges" still run the resolve for whole batches around each
// edge pixel; here every lane holds one (README, *Cheaper post-processes*).
void RsaaPass::resolve_edge_list(const RsaaFrame& frame, GLuint output, GLuint mask_output) {
  const CompleteForImageAccess complete_output(output, false);
  const CompleteForImageAccess complete_mask(settings_.output_mask ? mask_output : 0, true);
  // The listing pass and the resolve read the codes and the engine's centre normal as images, the
  // resolve (where it reads images) the centre primitive too (RSAA_CODE_IMAGES).
  const bool primitive_image = settings_.material_edges && gl_->resolve_reads_images;
  const CompleteForImageAccess complete_normal(frame.centre_normal, true);
  const CompleteForImageAccess complete_primitive(primitive_image ? frame.centre_primitive : 0, true);
  const int code_images = int(gl_->codes.size());
  std::vector<int> image_units = {kOutputImageUnit, kMaskImageUnit};
  for (int k = 0; k < post_read_images(code_images, primitive_image); ++k) image_units.push_back(kFirstCodeImageUnit + k);
  const gl::SavedComputeState saved({kEdgeListBinding}, image_units);
  // The rows listed per round: all of them unless the list cannot hold every pixel (then the
  // list is filled and resolved again for each band of rows).
  const int rows = int(std::min<std::int64_t>(height_, list_capacity_ / width_));
  const bool one_round = rows == height_;
  const bool in_place = output == frame.colour;
  const GLenum output_format = gl::internal_format_of(output);
  if (in_place && gl_->scratch_format != output_format) {
    gl_->scratch = gl::make_texture_2d(output_format, width_, height_);
    gl_->scratch_format = output_format;
  }
  // In place in one round, the image already holds every edge-free pixel's colour: no copy; the
  // listed pixels are resolved into the scratch image, then copied over. In several rounds a
  // round's copy would overwrite 1x colours the next round's resolve reads: the image is resolved
  // into the scratch image as into a separate output, then copied back whole.
  const bool scatter = in_place && one_round;
  const GLuint resolved = in_place ? gl_->scratch.get() : output;
  const OutputImage resolved_image(resolved);
  const OutputImage output_image(scatter ? output : 0);
  if (scatter) {  // the scratch as it is stored (an sRGB one's encoded bytes, through its view)
    glBindTextureUnit(kScratchUnit, resolved_image.image());
    glBindSampler(kScratchUnit, gl_->nearest.get());
  }
  if (!in_place)
    copy_colour(frame.colour, output);
  else if (!one_round)
    copy_colour(frame.colour, resolved);
  if (settings_.output_mask) clear_to_all_similar(mask_output);
  for (int k = 0; k < code_images; ++k)
    glBindImageTexture(GLuint(kFirstCodeImageUnit + k), gl_->codes[std::size_t(k)].get(), 0, GL_FALSE, 0,
                       GL_READ_ONLY, code_format(settings_.code_bits));
  glBindImageTexture(GLuint(kFirstCodeImageUnit + code_images), frame.centre_normal, 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_RG16UI);
  if (primitive_image)
    glBindImageTexture(GLuint(kFirstCodeImageUnit + code_images + 1), frame.centre_primitive, 0, GL_FALSE, 0,
                       GL_READ_ONLY, GL_RG32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeListBinding, gl_->edge_list.get());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, gl_->edge_list.get());
  for (int first = 0; first < height_; first += rows) {
    const int end = std::min(first + rows, height_);
    // The pre-pass's record passes listed the edges already (one round), or the listing pass
    // does, from the codes.
    if (!edges_listed_) {
      // The list's head (rsaa_post_list.glsl): 0 x 1 x 1 groups, 0 pixels.
      const GLuint empty_list[4] = {0, 1, 1, 0};
      glNamedBufferSubData(gl_->edge_list.get(), 0, sizeof empty_list, empty_list);
      glUseProgram(gl_->classify_program.get());
      glUniform2i(kClassifyRowsLocation, first, end);
      const GLint* group = gl_->classify_group;
      glDispatchCompute(GLuint((width_ + group[0] - 1) / group[0]), GLuint((end - first + group[1] - 1) / group[1]), 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glUseProgram(gl_->list_size_program.get());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    resolved_image.bind(kOutputImageUnit, gl_->list_resolve_program.get(), true);
    if (settings_.output_mask)
      glBindImageTexture(kMaskImageUnit, mask_output, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glUseProgram(gl_->list_resolve_program.get());
    glDispatchComputeIndirect(0);
    if (scatter) {
      // Every listed pixel resolved from the 1x colours before any of them is overwritten.
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);  // (the copy fetches)
      // A copy of what the scratch stores, in the same format: encoded already for an sRGB output.
      output_image.bind(kOutputImageUnit, gl_->scatter_program.get(), false);
      glUseProgram(gl_->scatter_program.get());
      glDispatchComputeIndirect(0);
    }
    // The next round rewrites the list this one read (and its head, by a buffer update).
    if (end < height_)
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  }
  if (in_place && !one_round) {
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);  // the blit reads what the resolve stored
    copy_colour(resolved, output);
  }
  // The engine reads the output next, by any path (texture, framebuffer, copy, image).
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

}  // namespace rsaa
