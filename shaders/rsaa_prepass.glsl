// The RSAA pre-pass as functions an engine calls from its own shaders (SMAA-style: set the
// defines, include this file in the vertex and the fragment stage, call two functions), so that
// the engine's own vertex stage (skinning, instancing, morphing) draws the pre-pass.
//
//   vertex stage    gl_Position = rsaa_jitter(clip_position);
//   fragment stage  layout(location = 0) out uvec4 o_code;
//                   o_code = rsaa_prepass_code(view_position, view_face_normal, primitive);
//
// rsaa_jitter() shifts the image so that the subsample being drawn lands on the pixel centre (the
// jittered pre-pass, one draw per subsample); in the multisample pre-pass (RSAA_PREPASS_MSAA: one
// draw, or two for a union pattern, the fragment shader run per sample) it applies the second
// union draw's shift. There rsaa_prepass_code() ignores view_position and rebuilds the sample's
// point from its window position and depth (gl_FragCoord.z), as the centre's is: Mesa llvmpipe's
// perspective-correct interpolation at a sample (interpolateAtSample/AtOffset, per-sample inputs)
// slides the point along the view ray (relative depth error up to 0.17 on a detailed model),
// which made points of one surface look dissimilar.
//
// Defines expected before inclusion (RsaaPass::prepass_glsl() writes them for a pass):
//   RSAA_SAMPLE_COUNT, RSAA_AUTH (0, 1, 2), RSAA_CODE_BITS, the similarity (rsaa_common.glsl)
//   RSAA_PREPASS_MSAA          (optional) the multisample pre-pass
//   RSAA_MATERIAL_EDGES        (optional) material edges: the centre primitive target is RG32UI
//                              with the material in .y, and the fragment stage calls
//                              rsaa_prepass_code(view_position, view_face_normal, primitive, material)
//   RSAA_PREPASS_FIRST_UNIT    (13) the first of three texture units: centre normal, centre
//                              primitive, centre depth
//   RSAA_UNIFORM_BINDING       (13) the uniform block (rsaa_uniforms.glsl)
//   RSAA_INCLUDE_FS            (1) 0 in the vertex stage: only rsaa_jitter() is declared
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
vec3 rsaa_face_normal(vec3 view_position) {
  vec3 n = cross(dFdx(view_position), dFdy(view_position));
  float len = length(n);
  return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

vec3 rsaa_centre_position(ivec2 pixel) {
  return rsaa_view_position(vec2(pixel) + 0.5, texelFetch(rsaa_centre_depth, pixel, 0).x,
                            rsaa_inverse_projection, rsaa_viewport);
}

// The compressed similarity code of the subsample being shaded: how different the surface it sees
// (view-space position and geometric normal) is from the surface at the pixel centre. `primitive`
// is the value the engine wrote into the centre primitive target for this triangle (id + 1): when
// equal, the subsample is on the centre's triangle and the test is skipped; 0 never skips it.
// All four channels carry the code: the pass masks the ones of other subsamples.
// With RSAA_MATERIAL_EDGES `material` is the value the engine wrote into the centre primitive
// target's second channel for this draw: a subsample on another material than the centre's is
// maximally different, so that colour edges between coplanar parts (a painted band on a wall, a
// decal, a window in its frame), which no geometric similarity sees, are resampled.
#ifdef RSAA_MATERIAL_EDGES
uvec4 rsaa_prepass_code(vec3 view_position, vec3 view_face_normal, uint primitive, uint material) {
#else
uvec4 rsaa_prepass_code(vec3 view_position, vec3 view_face_normal, uint primitive) {
#endif
#ifdef RSAA_PREPASS_MSAA
  // The point this sample sees (window space) and the pixel that contains it: the sample's own
  // pixel, but for the shifted second draw of a union pattern.
  vec2 window = floor(gl_FragCoord.xy) + gl_SamplePosition + rsaa_sample_shift;
  ivec2 pixel = ivec2(floor(window));
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, ivec2(rsaa_viewport))))
    return uvec4(1u);  // a point outside the image: no pixel reads it
  view_position = rsaa_view_position(window, gl_FragCoord.z, rsaa_inverse_projection, rsaa_viewport);
  int subsample = rsaa_subsample + gl_SampleID;
#else
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int subsample = rsaa_subsample;
#endif
  uvec2 centre_primitive = texelFetch(rsaa_centre_primitive, pixel, 0).xy;
#ifdef RSAA_MATERIAL_EDGES
  // Primitive ids repeated across draws must not hide a material edge: both must match.
  if (primitive != 0u && centre_primitive == uvec2(primitive, material)) return uvec4(1u);  // decodes to 0
#else
  if (primitive != 0u && centre_primitive.x == primitive) return uvec4(1u);  // decodes to 0
#endif
  uvec2 centre_normal = texelFetch(rsaa_centre_normal, pixel, 0).xy;
  // A surface subsample in a background pixel: different.
  if (!rsaa_is_surface(centre_normal)) return uvec4(RSAA_CODE_MAX);
#ifdef RSAA_MATERIAL_EDGES
  if (centre_primitive.y != material) return uvec4(RSAA_CODE_MAX);
#endif
  float similarity = rsaa_similarity(view_position, view_face_normal, rsaa_centre_position(pixel),
                                     rsaa_decode_normal(centre_normal));
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
  return uvec4(rsaa_encode_similarity(similarity));
}
#endif  // RSAA_INCLUDE_FS

#endif  // RSAA_PREPASS_GLSL
