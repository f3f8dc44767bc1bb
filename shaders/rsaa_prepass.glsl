// The RSAA pre-pass as functions an engine calls from its own shaders (SMAA-style: set the
// defines, include this file in the vertex and the fragment stage, call two functions), so that
// the engine's own vertex stage (skinning, instancing, morphing) draws the pre-pass.
//
//   vertex stage    gl_Position = rsaa_jitter(clip_position);
//   fragment stage  layout(location = 0) out uvec4 o_code;
//                   o_code = rsaa_prepass_code(view_position, view_face_normal, primitive);
//
// rsaa_jitter() shifts the image so that the subsample being drawn lands on the pixel centre (the
// jittered pre-pass, one draw per subsample, each fragment writing its subsample's similarity
// code); in the multisample pre-pass (RSAA_PREPASS_MSAA: one draw, or two for a union pattern,
// into multisample targets, the fragment shader run once per pixel; for a cell pattern the one
// draw is a multiple of the image's size, so gl_FragCoord is the raster's there) it applies the
// second union draw's shift, and rsaa_prepass_code() returns the triangle's surface record (primitive,
// material, face normal) without reading anything: the pass then turns records and the samples'
// depths into the same codes with two compute passes (rsaa_prepass_records.glsl), computing
// similarities only for pixels with a sample on another triangle than the centre's. Each sample's
// point is rebuilt from its window position and depth, as the centre's is: Mesa llvmpipe's
// perspective-correct interpolation at a sample (interpolateAtSample/AtOffset, per-sample inputs)
// slides the point along the view ray (relative depth error up to 0.17 on a detailed model),
// which made points of one surface look dissimilar. On llvmpipe, which runs every branch of a
// shader for a whole SIMD batch, the jittered draws pay the similarity for every fragment; the
// multisample pre-pass pays a record write (README, *The multisample pre-pass*).
//
// Defines expected before inclusion (RsaaPass::prepass_glsl() writes them for a pass):
//   RSAA_SAMPLE_COUNT, RSAA_AUTH (0, 1, 2), RSAA_CODE_BITS, the similarity (rsaa_common.glsl)
//   RSAA_PREPASS_MSAA          (optional) the multisample pre-pass
//   RSAA_PREPASS_RECORDS       (optional) jittered draws that write surface records, as the
//                              multisample pre-pass does, each into its own layer
//   RSAA_MATERIAL_EDGES        (optional) material edges: the centre primitive target is RG32UI
//                              with the material in .y, and the fragment stage calls
//                              rsaa_prepass_code(view_position, view_face_normal, primitive, material)
//   RSAA_PREPASS_FIRST_UNIT    (13) the first of three texture units: centre normal, centre
//                              primitive, centre depth
//   RSAA_UNIFORM_BINDING       (13) the uniform block (rsaa_uniforms.glsl)
//   RSAA_INCLUDE_FS            (1) 0 in the vertex stage: only rsaa_jitter() is declared
//   RSAA_PREPASS_COMPUTE       (optional) included by a compute shader (the pass's record passes):
//                              no fragment-stage functions
#ifndef RSAA_PREPASS_GLSL
#define RSAA_PREPASS_GLSL

#ifndef RSAA_INCLUDE_FS
#define RSAA_INCLUDE_FS 1
#endif
#ifndef RSAA_PREPASS_FIRST_UNIT
#define RSAA_PREPASS_FIRST_UNIT 13
#endif

#include "rsaa_common.glsl"
#include "rsaa_uniforms.glsl"

vec4 rsaa_jitter(vec4 clip_position) {
  return vec4(clip_position.xy + rsaa_jitter_ndc * clip_position.w, clip_position.zw);
}

#if RSAA_INCLUDE_FS
layout(binding = RSAA_PREPASS_FIRST_UNIT) uniform usampler2D rsaa_centre_normal;         // RG16UI
layout(binding = RSAA_PREPASS_FIRST_UNIT + 1) uniform usampler2D rsaa_centre_primitive;  // R32UI (RG32UI)
layout(binding = RSAA_PREPASS_FIRST_UNIT + 2) uniform sampler2D rsaa_centre_depth;       // depth

// The geometric normal of the triangle being drawn, from the derivatives of the view-space
// position, for an engine without a geometry stage that computes it. Its sign is arbitrary
// (similarity measures use |n . r|).
#ifndef RSAA_PREPASS_COMPUTE
vec3 rsaa_face_normal(vec3 view_position) {
  vec3 n = cross(dFdx(view_position), dFdy(view_position));
  float len = length(n);
  return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}
#endif

vec3 rsaa_centre_position(ivec2 pixel) {
  return rsaa_view_position(vec2(pixel) + 0.5, texelFetch(rsaa_centre_depth, pixel, 0).x,
                            rsaa_inverse_projection, rsaa_viewport);
}

#ifdef RSAA_MATERIAL_EDGES
// The material at the centre of the outside pixel nearest subsample `subsample` of `pixel`, the
// one the post-process's checks read (rsaa_outside_pixels(): clamped to the image).
uint rsaa_outside_material(ivec2 pixel, int subsample) {
  ivec2 outside = clamp(pixel + rsaa_neighbours[subsample].xy, ivec2(0), ivec2(rsaa_viewport) - 1);
  return texelFetch(rsaa_centre_primitive, outside, 0).y;
}
#endif

// What a subsample is compared with: the surface at its pixel's centre, as the G-buffer holds it.
struct RsaaCentre {
  uvec2 primitive;  // the centre primitive target's texel (.y the material with material edges)
  uvec2 normal;     // encoded (rsaa_is_surface(): (0, 0) is the background)
  vec3 position;    // view space
};

RsaaCentre rsaa_centre(ivec2 pixel) {
  RsaaCentre c;
  c.primitive = texelFetch(rsaa_centre_primitive, pixel, 0).xy;
  c.normal = texelFetch(rsaa_centre_normal, pixel, 0).xy;
  c.position = rsaa_centre_position(pixel);
  return c;
}

// Whether a subsample of this primitive (and material) lies on the centre's triangle
// (`centre_primitive`: the centre primitive target's texel); primitive 0 never does. With
// material edges both must match: primitive ids repeated across draws must not hide a material
// edge.
bool rsaa_on_centres_triangle(uvec2 centre_primitive, uint primitive, uint material) {
#ifdef RSAA_MATERIAL_EDGES
  return primitive != 0u && centre_primitive == uvec2(primitive, material);
#else
  return primitive != 0u && centre_primitive.x == primitive;
#endif
}

// The compressed similarity code of subsample `subsample` of `pixel` (whose centre is `centre`:
// rsaa_centre(), read once for all of a pixel's subsamples by the record passes): how different
// the surface it sees (view-space position and geometric normal) is from the surface at the pixel
// centre. `primitive` is the value the engine wrote into the centre primitive target for that
// triangle (id + 1): when equal, the subsample is on the centre's triangle and the test is
// skipped; 0 never skips it. With RSAA_MATERIAL_EDGES `material` is the value the engine wrote
// into the centre primitive target's second channel for that draw (else ignored): a subsample on
// another material than the centre's is maximally different, so that colour edges between
// coplanar parts (a painted band on a wall, a decal, a window in its frame), which no geometric
// similarity sees, are resampled.
uint rsaa_subsample_code(RsaaCentre centre, ivec2 pixel, int subsample, vec3 view_position, vec3 view_face_normal,
                         uint primitive, uint material) {
  if (rsaa_on_centres_triangle(centre.primitive, primitive, material)) return 1u;  // decodes to 0
  // A surface subsample in a background pixel: different.
  if (!rsaa_is_surface(centre.normal)) return RSAA_CODE_MAX;
#ifdef RSAA_MATERIAL_EDGES
  if (centre.primitive.y != material)
    return rsaa_outside_material(pixel, subsample) == material ? RSAA_CODE_MAX : RSAA_CODE_UNSEEN_MATERIAL;
#endif
  float similarity = rsaa_similarity(view_position, view_face_normal, centre.position,
                                     rsaa_decode_normal(centre.normal));
#if RSAA_AUTH == 2
  // Pre-pass authentication (paper section 2.4): a subsample that looks different from the
  // centre but even more different from its nearest outside pixel joins the similar cluster.
  ivec2 outside = pixel + rsaa_neighbours[subsample].xy;
  if (similarity > 0.5 * rsaa_threshold && all(greaterThanEqual(outside, ivec2(0))) &&
      all(lessThan(outside, ivec2(rsaa_viewport)))) {
    uvec2 outside_normal = texelFetch(rsaa_centre_normal, outside, 0).xy;
    if (rsaa_is_surface(outside_normal)) {
      float to_outside = rsaa_similarity(view_position, view_face_normal, rsaa_centre_position(outside),
                                         rsaa_decode_normal(outside_normal));
#ifdef RSAA_MATERIAL_EDGES
      if (texelFetch(rsaa_centre_primitive, outside, 0).y != material) to_outside = 1.0e9;  // another material
#endif
      if (to_outside > similarity) similarity = 0.0;
    }
  }
#endif
  return rsaa_encode_similarity(similarity);
}

// The same, reading the centre itself, lazily: a fragment on the centre's triangle (most of
// them) reads the centre's primitive only, as a GPU that branches per pixel can skip the rest.
uint rsaa_subsample_code(ivec2 pixel, int subsample, vec3 view_position, vec3 view_face_normal, uint primitive,
                         uint material) {
  RsaaCentre centre;
  centre.primitive = texelFetch(rsaa_centre_primitive, pixel, 0).xy;
  if (rsaa_on_centres_triangle(centre.primitive, primitive, material)) return 1u;
  centre.normal = texelFetch(rsaa_centre_normal, pixel, 0).xy;
  if (!rsaa_is_surface(centre.normal)) return RSAA_CODE_MAX;
  centre.position = rsaa_centre_position(pixel);
  return rsaa_subsample_code(centre, pixel, subsample, view_position, view_face_normal, primitive, material);
}

// ---- the multisample pre-pass's surface records (RSAA_PREPASS_MSAA): what a sample sees,
// written once per pixel for every covered sample (the fragment shader runs once per pixel, as
// in any MSAA G-buffer pass; the depth buffer holds each sample's own depth), then turned into
// codes by the pass (rsaa_prepass_records.glsl). Two 32-bit words, so that the draw writes and
// the pass reads 8 bytes a sample (16-byte records, tried first, made the draw markedly slower on
// llvmpipe): x the primitive, y the face normal as the centre's is stored (rsaa_encode_normal,
// 2 x 16 bits, its sign flipped to z >= 0: the similarity measures use |n . r| only). y = 0: no
// surface covers the sample (the records are cleared to 0; an encoded normal is never 0);
// y = 1: a NaN normal (compares as similar, as in the jittered pre-pass). With
// RSAA_MATERIAL_EDGES x packs the primitive's low 24 bits and the material's low 8 bits above them,
// so that the draw still writes 8 bytes a sample (a second target for the material cost the draw
// about a fifth of its time on llvmpipe, and the first record pass four more loads a pixel). The
// record passes compare those bits with the centre's: primitives whose values differ only above
// bit 24, or materials only above bit 8, compare as the same there (the jittered pre-pass compares
// whole values); materials numbered below 256 compare exactly.
#ifdef RSAA_MATERIAL_EDGES
#define RSAA_RECORD_PRIMITIVE_BITS 0x00ffffffu
#else
#define RSAA_RECORD_PRIMITIVE_BITS 0xffffffffu
#endif
#define RSAA_RECORD_MATERIAL_SHIFT 24u
#define RSAA_RECORD_MATERIAL_BITS 0xffu

// What a record's x holds for a surface of this primitive and material (material 0 without
// material edges).
uint rsaa_record_surface(uint primitive, uint material) {
  return (primitive & RSAA_RECORD_PRIMITIVE_BITS) | (material << RSAA_RECORD_MATERIAL_SHIFT);
}

uvec2 rsaa_surface_record(vec3 view_face_normal, uint primitive, uint material) {
  uint surface = rsaa_record_surface(primitive, material);
  vec3 n = view_face_normal.z < 0.0 ? -view_face_normal : view_face_normal;
  if (any(isnan(n))) return uvec2(surface, 1u);
  uvec2 q = rsaa_encode_normal(vec3(clamp(n.xy, -1.0, 1.0), n.z));
  return uvec2(surface, q.x | (q.y << 16u));
}

bool rsaa_record_is_surface(uvec2 record) { return record.y != 0u; }

vec3 rsaa_record_normal(uvec2 record) {
  if (record.y == 1u) return vec3(uintBitsToFloat(0x7fc00000u));
  return rsaa_decode_normal(uvec2(record.y & 0xffffu, record.y >> 16u));
}

#ifndef RSAA_PREPASS_COMPUTE
#ifdef RSAA_PREPASS_SIGNATURE
// Named after the settings the pre-pass reads (RsaaPass::prepass_glsl() and `rsaa shaders`
// define the name, rsaa_prepass_signature()): the pass finds it in the engine's program, so that
// a program built for other pre-pass settings is refused rather than drawn with. GL's initial
// value 0, never set: it adds nothing.
uniform uint RSAA_PREPASS_SIGNATURE;
#define RSAA_SIGNED(value) ((value) + uvec4(RSAA_PREPASS_SIGNATURE))
#else
#define RSAA_SIGNED(value) (value)
#endif

// What the engine's fragment stage writes (to location 0, a uvec4 output): jittered, the code of
// the subsample this draw samples (all four channels carry it: the pass masks the ones of other
// subsamples); multisample, the surface record of the samples the fragment covers (.xy).
#ifdef RSAA_MATERIAL_EDGES
uvec4 rsaa_prepass_code(vec3 view_position, vec3 view_face_normal, uint primitive, uint material) {
#else
uvec4 rsaa_prepass_code(vec3 view_position, vec3 view_face_normal, uint primitive) {
  const uint material = 0u;
#endif
#if defined(RSAA_PREPASS_MSAA) || defined(RSAA_PREPASS_RECORDS)
  return RSAA_SIGNED(uvec4(rsaa_surface_record(view_face_normal, primitive, material), 0u, 0u));
#else
  return RSAA_SIGNED(uvec4(rsaa_subsample_code(ivec2(gl_FragCoord.xy), rsaa_subsample, view_position,
                                               view_face_normal, primitive, material)));
#endif
}
#endif  // RSAA_PREPASS_COMPUTE
#endif  // RSAA_INCLUDE_FS

#endif  // RSAA_PREPASS_GLSL
