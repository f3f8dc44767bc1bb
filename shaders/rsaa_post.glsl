// The RSAA post-process as an include with one entry point (SMAA-style): similarity codes ->
// mask -> offset from the table -> one bilinear fetch of the 1x colour.
//
//   vec4 rsaa_resolve(ivec2 pixel, out uint mask)
//
// rsaa_post.frag is the fragment shader around it that RsaaPass runs; an engine may call it from
// its own pass (a fragment or compute shader) with the same resources bound.
//
// Defines expected before inclusion (rsaa_shader_defines() in runtime/rsaa_pass.h writes them):
//   RSAA_SAMPLE_COUNT, RSAA_AUTH (1 = post-pass authentication), RSAA_CODE_BITS, the similarity
//   RSAA_PREPASS_MSAA        (optional) codes are the samples of one multisample texture
//   RSAA_PREPASS_MSAA_UNION  (optional, with RSAA_MS_SAMPLES m) codes of a union pattern: samples
//                            0..m-1 in the first multisample texture, the shifted draw's in a
//                            second one, read at the raster pixel rsaa_neighbours[i].zw away
//   RSAA_SPLIT_CAP           (optional) cap of the k-means split, x threshold (rsaa_common.glsl)
//   RSAA_MULTI_SURFACE_NEIGHBOURS  (optional) pixels whose dissimilar subsamples point at two
//                            different surfaces: a sample average from the neighbours (below)
//   RSAA_SPLIT_CHECK_NEIGHBOURS  (optional) a subsample above the threshold that the split calls
//                            similar turns dissimilar when its outside pixel shows a like surface
//   RSAA_FETCH_CHECK_NEIGHBOURS  (optional) a pixel none of whose dissimilar subsamples finds a like
//                            surface in its outside pixel fetches with half the offset
//   RSAA_MATERIAL_EDGES      (optional) the centre primitive target (RG32UI, the material in .y)
//                            at unit RSAA_POST_FIRST_UNIT + 8: two centres of different materials
//                            compare as maximally different, as the pre-pass codes them
//   RSAA_TABLE_ARRAY         (optional) take offsets from a table include (tables/P.glsl, included
//                            before this file) instead of the table texture
//   RSAA_POST_FIRST_UNIT     (0) texture units, in order: colour, centre normal, centre depth,
//                            table, the code textures (ceil(RSAA_SAMPLE_COUNT / 4) units from
//                            + 4), the centre primitive at + 8
//   RSAA_UNIFORM_BINDING     (13) the uniform block (rsaa_uniforms.glsl)
//
// The table texture (RGBA32F, min(masks, 256) x ceil(masks / 256)): texel (mask % 256, mask / 256) holds the
// offset in GL window space (+y up) and the mask's representative dissimilar subsample (post-pass
// authentication). Codes arrive packed, four subsamples per RGBA texel: subsample i is channel
// i % 4 of code texture i / 4; or, from the multisample pre-pass, sample i of one texture.
#ifndef RSAA_POST_GLSL
#define RSAA_POST_GLSL

#ifndef RSAA_POST_FIRST_UNIT
#define RSAA_POST_FIRST_UNIT 0
#endif

#include "rsaa_common.glsl"
#include "rsaa_uniforms.glsl"

#define RSAA_CODE_TEXTURES ((RSAA_SAMPLE_COUNT + 3) / 4)
#define RSAA_ALL_SIMILAR ((1u << RSAA_SAMPLE_COUNT) - 1u)

layout(binding = RSAA_POST_FIRST_UNIT) uniform sampler2D rsaa_colour;  // linear, clamp to edge
layout(binding = RSAA_POST_FIRST_UNIT + 1) uniform usampler2D rsaa_post_centre_normal;
layout(binding = RSAA_POST_FIRST_UNIT + 2) uniform sampler2D rsaa_post_centre_depth;
#ifndef RSAA_TABLE_ARRAY
layout(binding = RSAA_POST_FIRST_UNIT + 3) uniform sampler2D rsaa_table;
#endif
#ifdef RSAA_PREPASS_MSAA
layout(binding = RSAA_POST_FIRST_UNIT + 4) uniform usampler2DMS rsaa_codes_ms;
#ifdef RSAA_PREPASS_MSAA_UNION
layout(binding = RSAA_POST_FIRST_UNIT + 5) uniform usampler2DMS rsaa_codes_ms2;
#endif
#else
layout(binding = RSAA_POST_FIRST_UNIT + 4) uniform usampler2D rsaa_codes[RSAA_CODE_TEXTURES];
#endif

// The resampling offset of a mask (GL window space) and its representative dissimilar subsample.
void rsaa_table_entry(uint mask, out vec2 offset, out int representative) {
#ifdef RSAA_TABLE_ARRAY
#if RSAA_TABLE_SAMPLE_COUNT != RSAA_SAMPLE_COUNT
#error "the table include is for another sample count than RSAA_SAMPLE_COUNT"
#endif
  offset = rsaa_offsets[mask];
  // Listing 3 of the paper: the dissimilar subsample farthest from the centre (the later on ties).
  representative = 0;
  float farthest = -1.0;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    float d = dot(rsaa_sample_positions[i], rsaa_sample_positions[i]);
    if ((mask & (1u << i)) == 0u && d >= farthest) representative = i, farthest = d;
  }
#else
  vec4 entry = texelFetch(rsaa_table, ivec2(mask & 255u, mask >> 8u), 0);
  offset = entry.xy;
  representative = int(entry.z);
#endif
}

vec3 rsaa_post_position(ivec2 pixel) {
  return rsaa_view_position(vec2(pixel) + 0.5, texelFetch(rsaa_post_centre_depth, pixel, 0).x,
                            rsaa_inverse_projection, rsaa_viewport);
}

#ifdef RSAA_MATERIAL_EDGES
layout(binding = RSAA_POST_FIRST_UNIT + 8) uniform usampler2D rsaa_post_centre_primitive;  // RG32UI
#endif

// The similarity of the surfaces at the centres of pixels a and b (positions and normals given),
// on the scale of the pre-pass codes: with material edges, two materials are as different as a
// code can say, as the pre-pass writes them.
float rsaa_centres_similarity(ivec2 a, vec3 a_position, vec3 a_normal, ivec2 b, vec3 b_position, vec3 b_normal) {
#ifdef RSAA_MATERIAL_EDGES
  if (texelFetch(rsaa_post_centre_primitive, a, 0).y != texelFetch(rsaa_post_centre_primitive, b, 0).y)
    return rsaa_decode_similarity(RSAA_CODE_MAX, true);
#endif
  return rsaa_similarity(a_position, a_normal, b_position, b_normal);
}

#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
// Split check (ours, RsaaSettings::split_check = "neighbours"). The k-means split lies above the
// threshold (up to RSAA_SPLIT_CAP x), so a subsample that differs from the centre's surface by
// more than the threshold counts as similar beside a far more different one. It turns dissimilar
// when the outside pixel in its direction shows a surface about as different from the centre
// (within a factor 1.5): a second surface the 1x image holds there, not a facet of the centre's
// own curved surface beside something else (thin wires, legs). Returns the corrected mask.
uint rsaa_split_check(ivec2 pixel, uvec2 centre_normal, float similarity[RSAA_SAMPLE_COUNT], uint mask) {
  if (!rsaa_is_surface(centre_normal)) return mask;
  vec3 position = rsaa_post_position(pixel);
  vec3 normal = rsaa_decode_normal(centre_normal);
  ivec2 last = ivec2(rsaa_viewport) - 1;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    float s = similarity[i];
    if ((mask & (1u << i)) == 0u || !(s > rsaa_threshold)) continue;
    ivec2 q = clamp(pixel + rsaa_neighbours[i].xy, ivec2(0), last);
    uvec2 q_normal = texelFetch(rsaa_post_centre_normal, q, 0).xy;
    if (!rsaa_is_surface(q_normal)) continue;
    float t = rsaa_centres_similarity(pixel, position, normal, q, rsaa_post_position(q), rsaa_decode_normal(q_normal));
    if (t * 1.5 > s && t < s * 1.5) mask &= ~(1u << i);
  }
  return mask;
}
#endif

#ifdef RSAA_FETCH_CHECK_NEIGHBOURS
// Fetch check (ours, RsaaSettings::fetch_check = "neighbours"). The fetch brings in the colours of
// the outside pixels; it helps only where they show what the dissimilar subsamples saw. A
// dissimilar subsample is matched when the outside pixel in its direction shows a surface about as
// different from the centre (within a factor 3; the background for a background subsample, any
// surface for a subsample of a background pixel). When no dissimilar subsample is matched (a
// sliver whose surface no neighbour centre shows: thin side faces, a contour line beside another
// surface), the offset is halved. Returns the factor for the offset, 1 or 0.5.
float rsaa_fetch_check(ivec2 pixel, uvec2 centre_normal, float similarity[RSAA_SAMPLE_COUNT], uint mask) {
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  vec3 position = rsaa_post_position(pixel);
  vec3 normal = rsaa_decode_normal(centre_normal);
  ivec2 last = ivec2(rsaa_viewport) - 1;
  bool matched = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    if ((mask & (1u << i)) != 0u) continue;
    ivec2 q = clamp(pixel + rsaa_neighbours[i].xy, ivec2(0), last);
    uvec2 q_normal = texelFetch(rsaa_post_centre_normal, q, 0).xy;
    bool q_is_surface = rsaa_is_surface(q_normal);
    float s = similarity[i];
    if (!centre_is_surface || s >= 1.0e9 || !q_is_surface) {
      // s is 1e9 for a subsample that sees no surface (rsaa_decode_similarity).
      matched = matched || (centre_is_surface ? s >= 1.0e9 && !q_is_surface : q_is_surface);
      continue;
    }
    float t = rsaa_centres_similarity(pixel, position, normal, q, rsaa_post_position(q), rsaa_decode_normal(q_normal));
    matched = matched || (t * 3.0 > s && t < s * 3.0);
  }
  return matched ? 1.0 : 0.5;
}
#endif

#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
// Does the centre of pixel `other` (its normal and view position given) show another surface than
// the centre of `pixel`? Background and surface differ; two surfaces compare with the pass's
// similarity against the threshold.
bool rsaa_centres_differ(ivec2 pixel, uvec2 normal, vec3 position, ivec2 other, uvec2 other_normal,
                         vec3 other_position) {
  if (other == pixel) return false;
  bool a = rsaa_is_surface(normal), b = rsaa_is_surface(other_normal);
  if (a != b) return true;
  if (!a) return false;
  return rsaa_centres_similarity(pixel, position, rsaa_decode_normal(normal), other, other_position,
                                 rsaa_decode_normal(other_normal)) > rsaa_threshold;
}

// Multi-surface resolve (ours, RsaaSettings::multi_surface = "neighbours"). One bilinear fetch
// blends the centre with neighbours of one quadrant, which suits two surfaces. When the outside
// pixels nearest the dissimilar subsamples (rsaa_neighbours) show two surfaces that differ from
// the centre's and from each other, the pixel holds 3+ surfaces: it is resolved as the mean over
// its subsamples instead, a similar subsample taking the centre's colour and a dissimilar one
// the colour of its outside pixel (the centre's when that pixel shows the centre's surface).
// Returns false (the caller fetches as usual) for every other pixel.
bool rsaa_multi_surface(ivec2 pixel, uvec2 centre_normal, vec4 colour, uint mask, out vec4 resolved) {
  resolved = colour;
  // A non-finite pixel is left to the fetch path, which keeps it (as the CPU reference).
  if (any(isnan(colour)) || any(isinf(colour))) return false;
  ivec2 last = ivec2(rsaa_viewport) - 1;
  // The outside pixels the dissimilar subsamples point at: bit (step.y + 1) * 3 + step.x + 1 of
  // the 3x3 neighbourhood.
  uint pointed = 0u;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    if ((mask & (1u << i)) != 0u) continue;
    ivec2 step = rsaa_neighbours[i].xy;
    pointed |= 1u << uint((step.y + 1) * 3 + step.x + 1);
  }
  // Each of them read and compared with the centre once (a driver that runs every branch for a
  // whole SIMD batch, as llvmpipe, pays for each fetch written, taken or not).
  vec3 position = rsaa_post_position(pixel);
  ivec2 q[9];
  uvec2 q_normal[9];
  vec3 q_position[9], q_colour[9];
  uint differing = 0u;
  for (int b = 0; b < 9; ++b) {
    q[b] = clamp(pixel + ivec2(b % 3 - 1, b / 3 - 1), ivec2(0), last);
    q_normal[b] = uvec2(0u), q_position[b] = vec3(0.0), q_colour[b] = colour.rgb;
    if ((pointed & (1u << uint(b))) == 0u) continue;
    q_normal[b] = texelFetch(rsaa_post_centre_normal, q[b], 0).xy;
    q_position[b] = rsaa_post_position(q[b]);
    vec3 outside = texelFetch(rsaa_colour, q[b], 0).rgb;
    // As the fetch path: a NaN or infinite neighbour never spreads into this pixel.
    if (!any(isnan(outside)) && !any(isinf(outside))) q_colour[b] = outside;
    if (rsaa_centres_differ(pixel, centre_normal, position, q[b], q_normal[b], q_position[b]))
      differing |= 1u << uint(b);
  }
  // 3+ surfaces: a second differing outside pixel that differs from the first one too.
  int first = -1;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    ivec2 step = rsaa_neighbours[i].xy;
    int b = (step.y + 1) * 3 + step.x + 1;
    if (first < 0 && (mask & (1u << i)) == 0u && (differing & (1u << uint(b))) != 0u) first = b;
  }
  if (first < 0) return false;
  bool three = false;
  for (int b = 0; b < 9; ++b)
    if (b != first && (differing & (1u << uint(b))) != 0u)
      three = three || rsaa_centres_differ(q[first], q_normal[first], q_position[first], q[b], q_normal[b], q_position[b]);
  if (!three) return false;
  // The mean over the subsamples: a similar one takes the centre's colour, a dissimilar one the
  // colour of its outside pixel where that pixel shows another surface.
  vec3 sum = vec3(0.0);
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    ivec2 step = rsaa_neighbours[i].xy;
    int b = (step.y + 1) * 3 + step.x + 1;
    bool outside = (mask & (1u << i)) == 0u && (differing & (1u << uint(b))) != 0u;
    sum += outside ? q_colour[b] : colour.rgb;
  }
  resolved = vec4(sum / float(RSAA_SAMPLE_COUNT), colour.a);
  return true;
}
#endif

// The pixel's similarity mask (paper section 2.2) from its subsamples' codes, with the decoded
// similarities and the centre's normal that the resolve reads further. The all-similar mask means
// rsaa_resolve() keeps the pixel's colour: the cheap test an edge pass runs for every pixel
// (rsaa_post_edges.frag). Most pixels leave early: every subsample on the centre's surface (code 1
// = similarity 0), or a background pixel whose subsamples see no surface (code 0) or its surface.
uint rsaa_pixel_mask(ivec2 pixel, out float similarity[RSAA_SAMPLE_COUNT], out uvec2 centre_normal) {
  uint codes[RSAA_SAMPLE_COUNT];
#ifndef RSAA_PREPASS_MSAA
  uvec4 code_texels[RSAA_CODE_TEXTURES];
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) code_texels[k] = texelFetch(rsaa_codes[k], pixel, 0);
#endif
  bool any_different = false, any_uncovered = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
#if defined(RSAA_PREPASS_MSAA_UNION)
    if (i < RSAA_MS_SAMPLES) {
      codes[i] = texelFetch(rsaa_codes_ms, pixel, i).x;
    } else {
      // The raster pixel whose shifted sample saw subsample i; outside the image (one column and
      // one row at the edge, by the shift's direction) the shifted draw has no code: similar.
      ivec2 r = pixel + rsaa_neighbours[i].zw;
      bool inside = all(greaterThanEqual(r, ivec2(0))) && all(lessThan(r, ivec2(rsaa_viewport)));
      codes[i] = inside ? texelFetch(rsaa_codes_ms2, r, i - RSAA_MS_SAMPLES).x : 1u;
    }
#elif defined(RSAA_PREPASS_MSAA)
    codes[i] = texelFetch(rsaa_codes_ms, pixel, i).x;
#else
    codes[i] = code_texels[i / 4][i % 4];
#endif
    any_different = any_different || codes[i] > 1u;
    any_uncovered = any_uncovered || codes[i] == 0u;
    similarity[i] = 0.0;
  }
  centre_normal = uvec2(0u);
  if (!any_different && !any_uncovered) return RSAA_ALL_SIMILAR;
  centre_normal = texelFetch(rsaa_post_centre_normal, pixel, 0).xy;
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  if (!any_different && !centre_is_surface) return RSAA_ALL_SIMILAR;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) similarity[i] = rsaa_decode_similarity(codes[i], centre_is_surface);
  float split;
  return rsaa_classify(similarity, rsaa_threshold, split);
}

vec4 rsaa_resolve(ivec2 pixel, out uint mask) {
  float similarity[RSAA_SAMPLE_COUNT];
  uvec2 centre_normal;
  mask = rsaa_pixel_mask(pixel, similarity, centre_normal);
  vec4 colour = texelFetch(rsaa_colour, pixel, 0);
  if (mask == RSAA_ALL_SIMILAR) return colour;
#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
  mask = rsaa_split_check(pixel, centre_normal, similarity, mask);
#endif
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  vec2 offset;
  int representative;
  rsaa_table_entry(mask, offset, representative);
#ifdef RSAA_FETCH_CHECK_NEIGHBOURS
  offset *= rsaa_fetch_check(pixel, centre_normal, similarity, mask);
#endif
#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
  // A mask the table leaves alone (offset 0, as every mask of an all-zero table) stays alone.
  vec4 resolved;
  if (offset != vec2(0.0) && rsaa_multi_surface(pixel, centre_normal, colour, mask, resolved)) return resolved;
#endif
#if RSAA_AUTH == 1
  // Post-pass authentication (paper section 2.4): if the outside pixel nearest to the
  // representative dissimilar subsample differs from the centre much more than that subsample
  // does, the fetch would blend in a surface the pixel does not show: halve the offset.
  ivec2 outside = clamp(pixel + rsaa_neighbours[representative].xy, ivec2(0), ivec2(rsaa_viewport) - 1);
  uvec2 outside_normal = texelFetch(rsaa_post_centre_normal, outside, 0).xy;
  if (centre_is_surface && rsaa_is_surface(outside_normal)) {
    float to_outside = rsaa_centres_similarity(pixel, rsaa_post_position(pixel), rsaa_decode_normal(centre_normal),
                                               outside, rsaa_post_position(outside), rsaa_decode_normal(outside_normal));
    if (to_outside - similarity[representative] > similarity[representative]) offset *= 0.5;
  }
#endif
  // A zero offset keeps the texel exactly (a filtered fetch at the texel centre may not).
  if (offset == vec2(0.0)) return colour;
  // Level 0, bilinear (the magnification filter) in every stage: implicit derivatives would turn
  // to the minification filter where neighbouring pixels' offsets differ.
  vec4 fetched = textureLod(rsaa_colour, (vec2(pixel) + 0.5 + offset) / rsaa_viewport, 0.0);
  // As the CPU reference: a NaN or infinite neighbour never spreads into this pixel.
  return any(isnan(fetched)) || any(isinf(fetched)) ? colour : fetched;
}

#endif  // RSAA_POST_GLSL
