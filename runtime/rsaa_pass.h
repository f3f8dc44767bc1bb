// The RSAA pass as an engine drops it in: per-subsample similarity pre-pass + post-process, for
// any of the 12 variants of the paper. The public header of rsaa::pass.
//
// GL LOADER. This header includes no GL header: GL object names are plain `unsigned int` (what
// every GL header typedefs GLuint to), so it compiles beside epoxy, glad, GLEW or the Khronos
// headers alike. The library calls GL through libepoxy internally; epoxy resolves entry points
// for whichever context is current (EGL or GLX), so it coexists with the engine's own loader.
// Every call, the destructors included, needs the OpenGL 4.5 core context the object was made
// in to be current on the calling thread.
//
// THE FRAME. The engine renders its 1x frame into four textures of the pass's width x height:
//   colour            the engine's colour target as it is: GL_RGBA16F, GL_RGBA32F or
//                     GL_R11F_G11F_B10F (linear light), GL_SRGB8_ALPHA8 (decoded as it is read,
//                     encoded as it is written: the pass blends linear light), or GL_RGB10_A2 or
//                     GL_RGBA8 (the fetch blends the stored values: linear light, as for the
//                     float formats, unless the engine accepts blending encoded ones). An sRGB
//                     output of the compute post-process needs immutable storage
//                     (glTexStorage2D): the pass stores into an RGBA8 view of it
//   centre_normal     GL_RG16UI: rsaa_encode_normal(geometric normal, view space); 0 = background
//   centre_primitive  GL_R32UI: primitive id + 1 of the triangle seen (0 = background); the
//                     pre-pass compares it with u_primitive_base + gl_PrimitiveID + 1. With
//                     RsaaSettings::material_edges GL_RG32UI, the second channel the material of
//                     the triangle's draw (any value the engine chooses per material; the
//                     pre-pass compares it with u_material / its `material` argument). The
//                     G-buffer's output there must then be a uvec2: a uint output leaves the
//                     second channel undefined, which no check here can see (every triangle
//                     edge would look like a material edge)
//   centre_depth      the depth of the same draw: GL_DEPTH_COMPONENT32F (RsaaTargets' own), or
//                     the engine's depth buffer as it is, GL_DEPTH32F_STENCIL8,
//                     GL_DEPTH24_STENCIL8 or GL_DEPTH_COMPONENT24 (read as depth:
//                     GL_DEPTH_STENCIL_TEXTURE_MODE must stay GL_DEPTH_COMPONENT)
// rsaa_encode_normal() is in shaders/rsaa_common.glsl (installed in share/rsaa/shaders);
// RsaaTargets allocates the four for an engine that has none of its own. render_subsamples()
// and resolve() check the four (name, format, size) and throw
// std::invalid_argument naming the field, so a forgotten or wrong binding is an error, not a
// wrong image. The pass reads the four through its own sampler objects (the colour bilinear and
// clamped to the edge, the others nearest): their own wrap modes, minification filters, depth
// comparison and completeness under them (a glTexImage2D texture with the default mipmap filter)
// do not matter; a swizzle other than the identity is refused, on these and on the outputs
// (texture reads would apply it, image loads, stores and copies not).
//
// DEPTH CONVENTION (RsaaSettings::depth). "gl", OpenGL's default: glClipControl(GL_LOWER_LEFT,
// GL_NEGATIVE_ONE_TO_ONE), nearer is less, inverse_projection maps NDC (z = 2 depth - 1) to view
// space. "zero-to-one": glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), nearer is less, NDC z =
// depth. "reverse-z": GL_ZERO_TO_ONE with nearer greater (depth cleared to 0, GL_GREATER), NDC z =
// depth; the pre-pass then clears its depth to 0 and tests with GL_GREATER. Depth range [0, 1]
// always. A clip control other than the setting's, or an inverse_projection that is not finite,
// is singular, sends a depth to no finite point or whose depth order is not the setting's, is
// refused (std::invalid_argument).
//
// THE PRE-PASS, WITH THE ENGINE'S OWN SHADERS (render_subsamples_with_own_shaders). The engine
// compiles a program whose stages begin with `#version 450 core` (or later), then prepass_glsl()
// (for the vertex stage after `#define RSAA_INCLUDE_FS 0`), and which call
//   vertex stage    gl_Position = rsaa_jitter(clip_position);
//   fragment stage  layout(location = 0) out uvec4 o_code;
//                   o_code = rsaa_prepass_code(view_position, view_face_normal, primitive);
//                   (with material_edges: rsaa_prepass_code(..., primitive, material))
// (shaders/rsaa_prepass.glsl documents them; rsaa_face_normal(view_position) gives the face
// normal from derivatives.) The callback binds that program and its vertex arrays and draws the
// frame's geometry; it is called once per subsample (jittered pre-pass and "records") or once
// (multisample; twice for a union pattern), so draw the whole frame in every call, into the
// viewport the pass set (a cell pattern's multisample draw is a multiple of the image). With the
// multisample or "records" pre-pass and material_edges the record keeps the primitive's low 24
// bits and the material's low 8 (materials numbered below 256 compare exactly;
// docs/conventions.md). Before each call the pass binds its framebuffer, the viewport, the
// pre-pass state below, the uniform block at settings.uniform_binding and three textures (and its
// nearest sampler objects) at units settings.prepass_first_unit to +2; the callback may use any other unit and binding, and may
// set culling for its geometry, but must draw with the colour mask, depth test, function and
// writes and blending the pass set (the codes depend on them; state it changes after drawing is
// its own business, so the pass cannot check these: a callback that sets its own colour mask
// before drawing writes every subsample's code into all four channels of the jittered
// pre-pass's targets). It must not move or destroy the pass that calls it. After each call the
// pass checks that the current program declares the
// block at that binding (no glUniformBlockBinding elsewhere) and was built from the
// prepass_glsl() of a pass with this pass's pre-pass settings (its text declares a uniform named
// after the settings the pre-pass reads: sample count, code bits, units, similarity, depth
// convention, material edges, pre-pass kind, pre-pass authentication; a program cached across a
// change of these, or taken from another such pass, would write other codes), that no pipeline of separable programs drew, that its units and buffer are untouched
// and that the framebuffer and viewport are still the pass's, and throws std::logic_error naming
// what is not.
//
// THE PRE-PASS, WITH THE PASS'S PROGRAM (render_subsamples). The pass calls
// `draw_geometry(program, jitter_ndc)` with its own program current (render_subsamples() throws
// std::logic_error if another program is current when it returns, or the units, buffer,
// framebuffer or viewport were changed, as above), after the same set-up. The
// callback draws the same geometry as the 1x frame with `program`, after setting on it:
//   vertex attributes  0 position (vec3, world space: the pre-pass applies no model matrix,
//                      so instanced, skinned or morphed geometry is baked into a buffer first;
//                      engines with such geometry use the way above), 1 normal, 2 uv, 3 albedo
//                      (only 0 matters to the pre-pass, and 1 with facet_materials; the
//                      others may stay disabled)
//   u_view, u_projection (mat4)   the frame's camera, unjittered
//   u_jitter_ndc (vec2)           = jitter_ndc: the image translation that puts this subsample
//                                   on the pixel centre
//   u_primitive_base (uint)       first primitive id of this draw call as written into
//                                 centre_primitive (0 for one draw per frame; default 0)
//   u_material (uint)             with material_edges: the draw's material as written into
//                                 centre_primitive's second channel (default 0; with
//                                 facet_materials, facets write their facet's)
//   u_facet_colours (usamplerBuffer) with facet_materials: per triangle of the draws (indexed by
//                                 u_primitive_base + gl_PrimitiveIDIn), 0 or 0x80 | colour
//                                 (runtime/smoothing_groups.h), at settings.facet_colours_unit
//
// The pre-pass state: depth test on (GL_LESS, depth writes on), blending, scissor test, culling,
// logic op and rasterizer discard off, filled polygons, colour mask: the subsample's channel
// (jittered) or all (multisample, "records"), GL_MULTISAMPLE on and sample shading off (the
// multisample pre-pass shades once per pixel), sample mask, coverage value and alpha to coverage
// off, and stencil test off, or, with prepass_cull "neighbours", on (GL_EQUAL 1, no stencil
// writes).
//
// GL STATE. Every call restores what it changes: framebuffer bindings, the viewports, depth
// ranges and scissor tests of every viewport index, current program, depth test/function/mask,
// stencil test/functions/operations/masks, blending and colour masks of every draw buffer, culling, polygon mode, rasterizer discard,
// sample shading, GL_MULTISAMPLE, sample mask and coverage, alpha to coverage/one, logic op, the
// generic uniform buffer binding, the vertex array, the textures and sampler objects bound to units 0-9 and to
// the pre-pass's three units, the uniform buffer binding, and for the compute post-process the
// shader storage buffer at binding 0 (and the generic one), the image units it binds (0-7 at most:
// outputs, codes, records) and the indirect-dispatch buffer, and for the record passes of the
// multisample and "records" pre-passes those, the storage buffer at binding 1 and their texture units too (every texture target of each
// unit saved: 2D, cube map, 3D and the rest); the engine's scissor, masks,
// culling and samplers do not reach the pass. (A program the engine deleted while current cannot
// be restored: none is current after.)
// A GL error already set when a call begins is the engine's: the call throws std::runtime_error
// (gl::GlError) saying so, before it does anything.
// Textures and programs they create belong to the RsaaPass object. A call that draws, resolves or
// hands out GL names on a moved-from RsaaPass or RsaaTargets throws std::logic_error.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/rsaa/sample_pattern.h"

namespace rsaa {
// core/rsaa/offset_table.h (which brings nlohmann/json) is for the code that builds a table;
// an engine that only names one includes no JSON library through this header.
struct OffsetTable;
}  // namespace rsaa

namespace rsaa {

// A GL object name (GLuint) without including a GL header.
using GlName = unsigned int;

struct RsaaSettings {
  // The offset table. Null: the built-in table of `pattern`. Otherwise any table (a retrained,
  // custom-pattern or scene-specific one, read with rsaa::read_offset_table() or built in memory;
  // both in core/rsaa/offset_table.h, which the engine includes for them):
  // the pre-pass then samples the table's own positions, and `pattern`, when not empty, must name
  // the table's pattern (a mismatch is refused naming both).
  std::shared_ptr<const OffsetTable> table;
  std::string pattern = "d3d8x";  // d3d8x | d3d4x | gl4x (the driver's 4x pattern)
  // sadp: the paper's SADP; depth: the paper's depth alternative (relative depth difference);
  // sadp-plane (ours): SADP or the gap between the surfaces' planes along the view ray, whichever
  // is larger, so that silhouettes over surfaces seen at grazing angles are found.
  std::string similarity = "sadp-plane";
  // 0 none, 1 post-pass (halve offsets; the default: no bench scene loses more than 0.01 dB, the
  // fence gains 0.7), 2 pre-pass (reclassify)
  int auth = 1;
  float threshold = 0.4f;         // SADP units (sadp, sadp-plane), or percent of depth (depth)
  int code_bits = 8;              // 8 | 16 | 32: storage per subsample similarity
  // Ours, beyond the paper, the defaults since they won on every bench scene (README "Pixels of
  // three or more surfaces"); 0 / "fetch" keep the paper's algorithm exactly:
  // split_cap > 0 (>= 1): the k-means split (maxsim / 2 + threshold / 2) is capped at split_cap x
  // threshold, so a subsample that clearly differs from the centre's surface counts as dissimilar
  // even when a third, far more different surface (often the background) is in the pixel.
  float split_cap = 1.5f;
  // "fetch": one bilinear fetch per pixel (the paper). "neighbours": a pixel whose dissimilar
  // subsamples point at outside pixels showing two different surfaces (3+ surfaces in the pixel)
  // is resolved as the mean over its subsamples, each dissimilar one taking its outside pixel's
  // colour (up to one texel fetch per subsample there); other pixels fetch as the paper.
  // "borrow" (the default): as "neighbours", and the record passes find for each subsample above
  // the threshold the pixel within two whose centre shows its surface (its triangle, else a
  // similar plane of its material); where such a pixel lies beyond the 3x3 (a bar or wire thinner
  // than a pixel, crossing between pixel centres) or the pixel holds 3+ surfaces, the mean over
  // the subsamples takes each dissimilar one's colour from it (README "Borrowed colours"). Needs a
  // pre-pass that writes records (msaa, records; auto's choice within its budget): with the
  // jittered pre-pass it resolves as "neighbours" (prepass_description() says so).
  std::string multi_surface = "borrow";
  // With "borrow": the mean's share in a pixel borrowed only for a source beyond the 3x3 (no 3+
  // surfaces: a plain two-surface edge there as often as a thin bar), the rest the table's fetch.
  // The mean of 4 subsamples quantises coverage to quarters where the table's fetch estimates it;
  // 0.75 won over 1 (the mean alone, session 30) on 38 scenes at 4x (+0.92 dB summed, none below
  // -0.08) and was level at 8x (+0.17) (README "Borrowed colours"). In [0, 1].
  float borrow_weight = 0.75f;
  // "off": the k-means split decides (the paper). "neighbours": a subsample above the threshold
  // that the split calls similar turns dissimilar when the outside pixel in its direction shows a
  // surface about as different from the centre (within a factor 1.5; one neighbour read per such
  // subsample). Raises the engine 40.21 -> 40.59 dB (README, "The split check").
  std::string split_check = "neighbours";
  // "off": every edge pixel fetches at its table offset (the paper). "neighbours": a pixel none of
  // whose dissimilar subsamples finds, in the outside pixel in its direction, a surface about as
  // different from the centre (within a factor 3) fetches with half the offset: the neighbours
  // do not show what the subsamples saw (one neighbour read per dissimilar subsample). Raises the
  // default scene 39.88 -> 40.04 dB and the fence 33.65 -> 33.82 (README, "The fetch check").
  std::string fetch_check = "neighbours";
  // Ours: colour edges between coplanar parts of different materials (a painted band on a wall,
  // a window in its frame, a decal), which no geometric similarity sees. false: the subsamples
  // compare geometry only (the paper). true: the engine writes each draw's material into
  // centre_primitive's second channel (GL_RG32UI) and passes it to the pre-pass; a subsample on
  // another material than the centre's is maximally different. Give materials that look alike
  // one id: a material edge is resampled as a colour edge, and distorts the masks of the real
  // edges near it. Off here so that an engine's frame contract does not change under it; the
  // renderer (`rsaa render`), whose scenes carry materials (one id per appearance), turns it on
  // by default (no scene measured loses, README "Material edges").
  bool material_edges = false;
  // Ours, with material_edges: the pass's own pre-pass program (render_subsamples) gives each
  // facet (a smoothing group parted from its neighbours by creases of the shading normals, or a
  // flat one: runtime/smoothing_groups.h) a material made from its colour in u_facet_colours and
  // u_material (shaders/scene_facet_material.glsl), so that the facets of a flat-shaded mesh,
  // which the geometric similarity calls one surface where they meet at a gentle angle, differ as
  // their shading does. The G-buffer must write the same materials (SceneRenderer with
  // facet_materials does; an engine drawing its own pre-pass gives its facets materials itself).
  // Off here, as material_edges (the renderer's `--facet-edges auto` turns both on; README, *Facet edges*).
  bool facet_materials = false;
  // How the pre-pass samples the subsamples: "jittered" draws the geometry once per subsample
  // with the image shifted so that it lands on the pixel centre (any pattern, any driver), each
  // fragment computing its subsample's code; "msaa" draws once into multisample targets, the
  // fragment shader run once per pixel writing the triangle's surface record, and two compute
  // passes then compute the codes (similarities only where a sample lies on another triangle than
  // the centre's). "msaa" needs the driver's sample positions for that count to be the table's
  // (gl4x on Mesa llvmpipe; d3d8x on GPUs whose 8x is the standard pattern), or, for a table of
  // 2m subsamples that are the driver's m positions and the same shifted by one sub-pixel offset
  // (a union pattern, such as tables/custom-gl4x-union.json), draws twice into m-sample targets,
  // the second shifted; for a cell pattern (the driver's m positions in each cell of the pixel
  // split into columns x rows, up to 8 x 8: cell_pattern(), rsaa train --cells; such as
  // tables/custom-gl4x-tall.json, -wide and -quad) draws once into m-sample targets that many
  // times the image's size, each cell a raster pixel (the callback draws into the viewport the
  // pass set: do not set your own; an engine fragment stage that reads gl_FragCoord sees raster
  // coordinates there, not the image's);
  // refused where the driver can do none of these. Its masks equal the jittered
  // pre-pass's (tests/test_msaa_prepass.cpp: up to float ties and, for a union, the image's
  // outermost pixels) at about half its cost for 4 subsamples on llvmpipe (README, *The
  // multisample pre-pass*). "records": the jittered draws, each writing the surface records (into
  // its own layers of array textures) instead of codes, and the same compute passes after: any
  // pattern, the same masks as "jittered" up to float ties (the records round the face normal to
  // 2 x 16 bits), more memory (12 bytes a subsample, see auto_records_max_bytes). "auto"
  // (default): "msaa" where the driver can (a cell or union pattern's draws only while their
  // records fit auto_records_max_bytes); else "records" while its records fit in
  // auto_records_max_bytes (d3d8x on a 4-sample driver: frames 8-41% cheaper than "jittered" on
  // the bench's eleven scenes at 640x480; at 1280x720 the pre-pass of the spider, which covers
  // little of the image, 11% dearer; README, *Jittered draws writing records*); else "jittered" (and
  // "jittered" with prepass_cull). RsaaPass::prepass_in_use() tells which.
  std::string prepass = "auto";
  // The most GL memory "auto" gives the records of "records" and of a cell or union pattern's
  // multisample draws (subsamples x 12 bytes a pixel: 8x at 1920x1080 takes 190 MiB; above this, "auto" takes
  // "jittered", 4 bytes a pixel). 0: never.
  std::int64_t auto_records_max_bytes = std::int64_t(256) << 20;
  // Culling of the jittered pre-pass (ours): "off" draws every subsample for every pixel (the
  // paper); "neighbours" first marks, once per frame, the pixels whose 3x3 neighbourhood of
  // centres (centre_primitive) shows another triangle or background, and the per-subsample draws
  // run behind an early stencil test there only; the other pixels' subsamples read as the
  // centre's surface. Faster where large triangles fill the image (default scene: pre-pass -30%),
  // slower on finely tessellated models (the marking pass costs more than it saves), and a
  // feature thinner than a pixel that covers no centre of the neighbourhood is missed (README:
  // "Culling the pre-pass"). Needs the jittered pre-pass.
  std::string prepass_cull = "off";
  // How resolve() runs the post-process, the same image (tests compare them: bit for bit into float
  // outputs, within one step into 8- and 10-bit ones, whose rounding or sRGB encoding is the
  // driver's in the fragment paths and the shader's in the compute one): "compute"
  // (default) copies the colour image, lists the pixels whose mask is not all-similar with a
  // compute shader (after a pre-pass that writes records, whose record passes list them as they
  // make the codes, no listing pass), then resolves the listed pixels only (an indirect dispatch; it binds
  // shader storage buffer 0 and image units 0 and 1, the listing pass also the codes and the centre
  // normal as images from unit 2, meanwhile, restored after); "edges" copies,
  // then an edge pass marks those pixels in a depth target and the resolve runs behind an early
  // depth test (a driver that executes both sides of a branch for a whole SIMD batch, as Mesa
  // llvmpipe, pays for every batch that holds an edge pixel; the list pays per edge pixel);
  // "single": one pass over every pixel. README, *Cheaper post-processes*.
  std::string post = "compute";
  // The frame's depth convention: "gl" | "zero-to-one" | "reverse-z" (DEPTH CONVENTION above).
  std::string depth = "gl";
  bool output_mask = false;       // resolve() also writes the mask (R32UI) for tests
  // Where the shaders find the pass's resources: the pre-pass's three textures at units
  // prepass_first_unit to +2, the uniform block (shaders/rsaa_uniforms.glsl) at uniform_binding.
  // The post-process, the pass's own program, uses units 0-9 (9: the in-place resolve's scratch).
  // Checked against the driver's limits.
  int prepass_first_unit = 13;
  int uniform_binding = 13;
  // With facet_materials: the unit the pass's own pre-pass program reads u_facet_colours from (the
  // caller's draw binds the facet colours there; GpuScene::draw binds them at the unit the
  // program names). Refused when it is one of the pre-pass's three units.
  int facet_colours_unit = 12;
};

// The #define lines that configure shaders/rsaa_prepass.glsl and rsaa_post.glsl for `settings`,
// `sample_count` subsamples and the jittered or the multisample pre-pass (for a union pattern:
// two draws of half the samples, see RsaaSettings::prepass). Needs no GL. Throws
// std::invalid_argument for a sample_count outside 1-16, code bits other than 8, 16 or 32, and
// (multisample) an odd union pattern or cells that do not divide the sample count.
std::string rsaa_shader_defines(const RsaaSettings& settings, int sample_count, bool multisample_prepass,
                                bool union_pattern = false, glm::ivec2 cells = {1, 1});
// The first of the record passes' four texture units (records and depths of each draw) beside
// the pre-pass's three from `prepass_first_unit`: 0, or after those three when they start below 4.
int rsaa_record_first_unit(int prepass_first_unit);
// The #define lines the multisample pre-pass's record passes (shaders/rsaa_prepass_list.comp,
// rsaa_prepass_codes.comp) need beside rsaa_shader_defines(): their resources (texture units from
// `first_record_unit`: records, depths, the union's second draw's; code images
// from `first_code_image`; the pixel list at storage binding `list_binding`; with borrowed
// colours the sources image at unit `sources_image`, read by the post-process at its unit
// RSAA_POST_FIRST_UNIT + 10) and where each subsample's point lies in its pixel. Needs no GL.
std::string rsaa_record_pass_defines(const SamplePattern& pattern, int first_record_unit, int first_code_image,
                                     int list_binding, int sources_image = 0);
// Borrowed colours' sources texture: a byte a subsample, four to a 32-bit channel, so 1, 2 or 4
// channels (GL_R32UI, GL_RG32UI, GL_RGBA32UI: no three-channel image format) for `sample_count`.
int rsaa_sources_channels(int sample_count);
// A file of shaders/ ("rsaa_prepass.glsl", "rsaa_post.glsl", "rsaa_post.hlsl", ...) with its
// #include lines replaced by the included text: one self-contained text. Needs no GL.
std::string rsaa_shader_file(const std::string& name);

// The name of the uniform a pre-pass built with `defines` (rsaa_shader_defines()) declares, as
// RSAA_PREPASS_SIGNATURE (prepass_glsl() and `rsaa shaders` define it): a hash of the defines
// the pre-pass reads (not the post-process's), which the pass looks for in the engine's program
// (render_subsamples_with_own_shaders).
std::string rsaa_prepass_signature(const std::string& defines);
// The pre-pass's text for `defines`: them, the signature's name, rsaa_prepass.glsl expanded
// (RsaaPass::prepass_glsl() and `rsaa shaders` both write it).
std::string rsaa_prepass_text(const std::string& defines);

// The engine's 1x frame (formats above). inverse_projection is that of the unjittered camera.
struct RsaaFrame {
  GlName colour = 0, centre_normal = 0, centre_primitive = 0, centre_depth = 0;
  int width = 0, height = 0;
  glm::mat4 inverse_projection{1.0f};
};

// The four 1x targets above, allocated, for an engine that has none of its own.
class RsaaTargets {
 public:
  // material_edges: the primitive target is GL_RG32UI (RsaaSettings::material_edges).
  RsaaTargets(int width, int height, bool material_edges = false);
  ~RsaaTargets();
  RsaaTargets(RsaaTargets&&) noexcept;
  RsaaTargets& operator=(RsaaTargets&&) noexcept;

  // Colour to `background` (linear RGB), normal and primitive to 0 (background), depth to
  // `far_depth` (0 for reverse Z): every pixel, whatever scissor test and masks the GL has.
  void clear(const float background[3], float far_depth = 1.0f) const;
  // Binds the framebuffer to GL_FRAMEBUFFER: colour at location 0, normal 1, primitive (and
  // material) 2, depth.
  void bind() const;
  RsaaFrame frame(const glm::mat4& inverse_projection) const;
  static constexpr double kBytesPerPixel = 8 + 4 + 4 + 4;
  static double bytes_per_pixel(bool material_edges) { return kBytesPerPixel + (material_edges ? 4 : 0); }
  // The colour texture the 1x frame is drawn into: the targets' own, or the one use_colour() set.
  GlName colour() const;
  // Draws the colour into `colour` (this size, one of RsaaFrame's colour formats; 0: the targets'
  // own GL_RGBA16F texture again) instead, for a frame resolved in place (RsaaPass::resolve with
  // output == frame.colour): the frame goes straight into the engine's output, without a copy
  // (an sRGB one is drawn with GL_FRAMEBUFFER_SRGB on, as any sRGB target, so that it holds the
  // linear colours encoded). Throws std::invalid_argument for another format or size.
  void use_colour(GlName colour);

 private:
  struct Objects;  // GL objects, defined in rsaa_pass.cpp
  int width_, height_;
  GlName colour_ = 0;  // use_colour()'s texture, 0: the targets' own
  std::unique_ptr<Objects> gl_;
};

// The 4x pattern of this GL driver, in pixel space (needs a current context).
SamplePattern query_gl_sample_pattern(int samples = 4);

class RsaaPass {
 public:
  using DrawGeometry = std::function<void(GlName program, glm::vec2 jitter_ndc)>;

  // Needs a current GL 4.5 context. Throws std::invalid_argument for bad settings or a size the
  // driver cannot hold (below 1 or above its texture, framebuffer or viewport limit) and
  // std::runtime_error when the baked table does not match the pattern's positions.
  RsaaPass(const RsaaSettings& settings, int width, int height);
  ~RsaaPass();
  RsaaPass(RsaaPass&&) noexcept;
  RsaaPass& operator=(RsaaPass&&) noexcept;

  void render_subsamples(const RsaaFrame& frame, const DrawGeometry& draw_geometry);
  // The pre-pass drawn by the engine's own program, which includes prepass_glsl() (above).
  void render_subsamples_with_own_shaders(const RsaaFrame& frame, const std::function<void()>& draw);
  // The text an engine's pre-pass stages include after #version: this pass's defines, then
  // rsaa_prepass.glsl with its includes expanded.
  std::string prepass_glsl() const;
  // Writes the anti-aliased colour into `output` (the frame's size, any of the colour formats above,
  // not necessarily the colour's), and the mask into `mask_output` (R32UI) when
  // settings.output_mask. Throws std::logic_error before any pre-pass
  // (or after one that did not finish), or for a frame whose normal, primitive or depth texture
  // is not the last pre-pass's: there are no codes to resolve it with. `output` may be the
  // frame's colour itself (resolved in place, post "compute" only), but not another texture that
  // shares its storage (a glTextureView of it): GL cannot tell, and the pass would read pixels it
  // has already written. The normal, primitive and depth textures must hold what the pre-pass
  // read until resolve() returns: a pre-pass that writes records lists the edge pixels from them
  // (the pass checks the names, not the contents).
  void resolve(const RsaaFrame& frame, GlName output, GlName mask_output = 0);

  const SamplePattern& pattern() const { return pattern_; }
  // The similarity codes of the last pre-pass, for an engine that runs its own post-process
  // (shaders/rsaa_post.glsl or .hlsl): RGBA 8/16/32-bit unsigned textures, subsample i in
  // channel i % 4 of texture i / 4, from every pre-pass.
  std::vector<GlName> code_textures() const;
  // True when the pre-pass is the multisample one (one draw, or two for a union pattern:
  // settings.prepass, "auto" resolved for this driver).
  bool multisample_prepass() const { return multisample_; }
  // The pre-pass this pass runs: "msaa", "records" or "jittered" (settings.prepass, "auto"
  // resolved for this driver and size).
  std::string prepass_in_use() const { return multisample_ ? "msaa" : layered_ ? "records" : "jittered"; }
  // The same with its draws, for a user: "msaa, one 4-sample draw at 1x2 cells (640x960)",
  // "records, 8 jittered draws writing surface records", ...
  std::string prepass_description() const;
  // Bytes per pixel of the GL memory this pass keeps (the frame's targets are RsaaTargets'): the
  // pre-pass's codes and depth, the post-process's edge list or edge-pass depth, and, for a pass
  // that resolves in place, the scratch image the listed pixels are resolved into.
  double bytes_per_pixel(bool resolves_in_place) const;

 private:
  struct Objects;  // GL objects, defined in rsaa_pass.cpp
  void write_frame_uniforms(const RsaaFrame& frame) const;
  void resolve_edge_list(const RsaaFrame& frame, GlName output, GlName mask_output);
  void copy_colour(GlName from, GlName to);
  // The compute post-process's edge list and the record passes' list of pixels to code, for
  // `capacity` pixels each (at least a row; fewer than the image's: both work in rounds of rows).
  void make_lists(std::int64_t capacity);
  friend struct RsaaPassTesting;  // tests/test_rsaa_pass_api.cpp: an edge list smaller than the image
  // The compute post-process's edge list as it is (x | y << 16 per pixel, in list order).
  std::vector<std::uint32_t> edge_list_pixels() const;
  void clear_to_all_similar(GlName mask_output) const;
  // Sets up the pre-pass and calls `draw` once per subsample (jittered) or once with -1.
  void run_prepass(const RsaaFrame& frame, const std::function<void(int subsample, glm::vec2 jitter_ndc)>& draw);
  // The multisample pre-pass's codes from its records (shaders/rsaa_prepass_records.glsl), and
  // the programs that make them (records read as images, or as textures where the driver lacks
  // multisample image loads).
  void codes_from_records();
  // Throws std::logic_error when a pre-pass draw left another uniform buffer, texture or sampler
  // on the pass's bindings.
  void require_prepass_bindings_kept(const RsaaFrame& frame) const;
  const std::string& prepass_signature() const;  // rsaa_prepass_signature() of this pass's defines
  void make_record_programs(bool record_images);
  RsaaSettings settings_;
  SamplePattern pattern_;
  bool multisample_ = false;
  bool union_ = false;   // the multisample pre-pass as two draws of half the samples (union pattern)
  bool layered_ = false;  // settings.prepass == "records": jittered draws writing surface records
  // The pre-pass writes surface records that the record passes turn into codes.
  bool writes_records() const { return multisample_ || layered_; }
  // Borrowed colours in use: asked for, and a pre-pass that keeps the subsamples' surfaces.
  bool borrows() const { return settings_.multi_surface == "borrow" && writes_records(); }
  bool cull_ = false;    // settings.prepass_cull == "neighbours"
  Vec2 union_shift_{};   // the second draw's shift, pixel space (+y down)
  // The multisample draw's raster pixels a pixel (columns, rows): 1 x 1, or a cell pattern's.
  glm::ivec2 cells_{1, 1};
  glm::ivec2 raster_size() const { return {width_ * cells_.x, height_ * cells_.y}; }
  // Samples a raster pixel of the multisample draw(s) has.
  int raster_samples() const { return pattern_.size() / (union_ ? 2 : cells_.x * cells_.y); }
  bool codes_ready_ = false;  // a pre-pass finished: the code textures hold its codes
  mutable std::string prepass_signature_;  // prepass_signature(), made at its first call
  GlName prepass_frame_[3] = {};  // its frame's centre_normal, centre_primitive, centre_depth
  std::int64_t list_capacity_ = 0;  // pixels each list holds (compute post-process, record passes)
  // The last pre-pass's record passes listed the compute post-process's edges (one round).
  bool edges_listed_ = false;
  int width_, height_;
  std::unique_ptr<Objects> gl_;
};

}  // namespace rsaa
