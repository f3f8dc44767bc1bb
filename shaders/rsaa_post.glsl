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
//   RSAA_SPLIT_CAP           (optional) cap of the k-means split, x threshold (rsaa_common.glsl)
//   RSAA_MULTI_SURFACE_NEIGHBOURS  (optional) pixels whose dissimilar subsamples point at two
//                            different surfaces: a sample average from the neighbours (below)
//   RSAA_MULTI_SURFACE_BORROW  (optional, with RSAA_MULTI_SURFACE_NEIGHBOURS; the pre-passes that
//                            write records) the sources the record passes found (unit
//                            RSAA_POST_FIRST_UNIT + 10): where a subsample's surface is shown only
//                            beyond the 3x3, or the pixel holds 3+ surfaces, the sample average
//                            takes each dissimilar subsample's colour from the pixel showing it
//   RSAA_SPLIT_CHECK_NEIGHBOURS  (optional) a subsample above the threshold that the split calls
//                            similar turns dissimilar when its outside pixel shows a like surface
//   RSAA_FETCH_CHECK_NEIGHBOURS  (optional) a pixel none of whose dissimilar subsamples finds a like
//                            surface in its outside pixel fetches with half the offset
//   RSAA_MATERIAL_EDGES      (optional) the centre primitive target (RG32UI, the material in .y)
//                            at unit RSAA_POST_FIRST_UNIT + 8: two centres of different materials
//                            compare as maximally different, as the pre-pass codes them
//   RSAA_TABLE_ARRAY         (optional) take offsets from a table include (tables/P.glsl, included
//                            before this file) instead of the table texture
//   RSAA_CODE_IMAGES         (optional, RsaaPass's compute passes) the codes, the centre normal
//                            and (material edges) the centre primitive are read as images, from
//                            image unit RSAA_CODE_IMAGES on (codes, then the normal, then the
//                            primitive): on llvmpipe an image load costs less than a texel fetch
//                            (README, *Cheaper post-processes*); the depth and colour stay textures
//   RSAA_POST_FIRST_UNIT     (0) texture units, in order: colour, centre normal, centre depth,
//                            table, the code textures (ceil(RSAA_SAMPLE_COUNT / 4) units from
//                            + 4), the centre primitive at + 8, the sources at + 10
//   RSAA_UNIFORM_BINDING     (13) the uniform block (rsaa_uniforms.glsl)
//
// The table texture (RGBA32F, min(masks, 256) x ceil(masks / 256)): texel (mask % 256, mask / 256) holds the
// offset in GL window space (+y up) and the mask's representative dissimilar subsample (post-pass
// authentication). Codes arrive packed, four subsamples per RGBA texel: subsample i is channel
// i % 4 of code texture i / 4, from either pre-pass (the multisample one packs them so too).
#ifndef RSAA_POST_GLSL
#define RSAA_POST_GLSL

#ifndef RSAA_POST_FIRST_UNIT
#define RSAA_POST_FIRST_UNIT 0
#endif

#include "rsaa_common.glsl"
#include "rsaa_uniforms.glsl"

#define RSAA_ALL_SIMILAR ((1u << RSAA_SAMPLE_COUNT) - 1u)

layout(binding = RSAA_POST_FIRST_UNIT) uniform sampler2D rsaa_colour;  // linear, clamp to edge
layout(binding = RSAA_POST_FIRST_UNIT + 1) uniform usampler2D rsaa_post_centre_normal;
layout(binding = RSAA_POST_FIRST_UNIT + 2) uniform sampler2D rsaa_post_centre_depth;
#ifndef RSAA_TABLE_ARRAY
layout(binding = RSAA_POST_FIRST_UNIT + 3) uniform sampler2D rsaa_table;
#endif
layout(binding = RSAA_POST_FIRST_UNIT + 4) uniform usampler2D rsaa_codes[RSAA_CODE_TEXTURES];

#ifdef RSAA_CODE_IMAGES
layout(binding = RSAA_CODE_IMAGES, RSAA_CODE_IMAGE_FORMAT) uniform readonly uimage2D rsaa_code_images[RSAA_CODE_TEXTURES];
layout(binding = RSAA_CODE_IMAGES + RSAA_CODE_TEXTURES, rg16ui) uniform readonly uimage2D rsaa_centre_normal_image;
#define RSAA_READS_CODE_IMAGES
#define RSAA_POST_NORMAL_AT(pixel) imageLoad(rsaa_centre_normal_image, pixel).xy
#else
#define RSAA_POST_NORMAL_AT(pixel) texelFetch(rsaa_post_centre_normal, pixel, 0).xy
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
#ifdef RSAA_READS_CODE_IMAGES
layout(binding = RSAA_CODE_IMAGES + RSAA_CODE_TEXTURES + 1, rg32ui) uniform readonly uimage2D
    rsaa_centre_primitive_image;
#else
layout(binding = RSAA_POST_FIRST_UNIT + 8) uniform usampler2D rsaa_post_centre_primitive;  // RG32UI
#endif
#endif

// The material at a pixel's centre (material edges), else one material for all.
uint rsaa_post_material(ivec2 pixel) {
#ifdef RSAA_MATERIAL_EDGES
#ifdef RSAA_READS_CODE_IMAGES
  return imageLoad(rsaa_centre_primitive_image, pixel).y;
#else
  return texelFetch(rsaa_post_centre_primitive, pixel, 0).y;
#endif
#else
  return 0u;
#endif
}

// The similarity of the surfaces at two pixel centres (materials, positions and normals given),
// on the scale of the pre-pass codes: two materials are as different as a code can say, as the
// pre-pass writes them.
float rsaa_centres_similarity(uint a_material, vec3 a_position, vec3 a_normal, uint b_material, vec3 b_position,
                              vec3 b_normal) {
  if (a_material != b_material) return rsaa_decode_similarity(RSAA_CODE_MAX, true);
  return rsaa_similarity(a_position, a_normal, b_position, b_normal);
}

#if defined(RSAA_SPLIT_CHECK_NEIGHBOURS) || defined(RSAA_FETCH_CHECK_NEIGHBOURS) || \
    defined(RSAA_MULTI_SURFACE_NEIGHBOURS) || RSAA_AUTH == 1
#define RSAA_READS_OUTSIDE_PIXELS
// The outside pixel nearest each subsample (rsaa_neighbours[i].xy away, clamped to the image),
// read and compared with the centre once and shared by every check below: each of them once
// read and compared it on its own, and a driver that runs both sides of every branch for a
// whole SIMD batch (llvmpipe) paid for all of them on every edge pixel.
struct RsaaOutside {
  uint centre_material;                // rsaa_post_material() of the pixel itself
  ivec2 pixel[RSAA_SAMPLE_COUNT];
  uvec2 normal[RSAA_SAMPLE_COUNT];     // encoded: (0, 0) is the background
  vec3 position[RSAA_SAMPLE_COUNT];    // view space
  uint material[RSAA_SAMPLE_COUNT];    // rsaa_post_material()
  // rsaa_centres_similarity(centre, outside pixel): meaningful where both show a surface.
  float similarity[RSAA_SAMPLE_COUNT];
};

RsaaOutside rsaa_outside_pixels(ivec2 pixel, vec3 position, vec3 normal) {
  RsaaOutside o;
  ivec2 last = ivec2(rsaa_viewport) - 1;
  uint material = rsaa_post_material(pixel);
  o.centre_material = material;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    o.pixel[i] = clamp(pixel + rsaa_neighbours[i].xy, ivec2(0), last);
    o.normal[i] = RSAA_POST_NORMAL_AT(o.pixel[i]);
    o.position[i] = rsaa_post_position(o.pixel[i]);
    o.material[i] = rsaa_post_material(o.pixel[i]);
    o.similarity[i] = rsaa_centres_similarity(material, position, normal, o.material[i], o.position[i],
                                              rsaa_decode_normal(o.normal[i]));
  }
  return o;
}
#endif

#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
// Split check (ours, RsaaSettings::split_check = "neighbours"). The k-means split lies above the
// threshold (up to RSAA_SPLIT_CAP x), so a subsample that differs from the centre's surface by
// more than the threshold counts as similar beside a far more different one. It turns dissimilar
// when the outside pixel in its direction shows a surface about as different from the centre
// (within a factor 1.5): a second surface the 1x image holds there, not a facet of the centre's
// own curved surface beside something else (thin wires, legs). Returns the corrected mask.
uint rsaa_split_check(uvec2 centre_normal, float similarity[RSAA_SAMPLE_COUNT], uint mask, RsaaOutside o) {
  if (!rsaa_is_surface(centre_normal)) return mask;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    float s = similarity[i], t = o.similarity[i];
    if ((mask & (1u << i)) == 0u || !(s > rsaa_threshold) || !rsaa_is_surface(o.normal[i])) continue;
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
// surface for a subsample of a background pixel). With material edges the materials decide
// first: a subsample on another material is matched exactly when that pixel shows its material
// (the pre-pass's code says which, `other_material`: rsaa_pixel_mask()), and a subsample on the
// centre's material is not matched by a pixel of another material (facets of one mesh are
// materials of their own: two facets are not "about as different" for both being other facets).
// When no dissimilar subsample is matched (a sliver whose surface no neighbour centre shows: thin
// side faces, a contour line beside another surface), the offset is halved. Returns the factor
// for the offset, 1 or 0.5.
float rsaa_fetch_check(uvec2 centre_normal, float similarity[RSAA_SAMPLE_COUNT], uint mask, uvec2 other_material,
                       RsaaOutside o) {
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  bool matched = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    if ((mask & (1u << i)) != 0u) continue;
    bool q_is_surface = rsaa_is_surface(o.normal[i]);
    float s = similarity[i], t = o.similarity[i];
    // s is 1e9 for a subsample that sees no surface (rsaa_decode_similarity).
    if (!centre_is_surface || s >= 1.0e9 || !q_is_surface)
      matched = matched || (centre_is_surface ? s >= 1.0e9 && !q_is_surface : q_is_surface);
#ifdef RSAA_MATERIAL_EDGES
    else if (((other_material.x | other_material.y) & (1u << i)) != 0u)
      matched = matched || (other_material.x & (1u << i)) != 0u;
    else if (o.material[i] != o.centre_material)
      continue;
#endif
    else
      matched = matched || (t * 3.0 > s && t < s * 3.0);
  }
  return matched ? 1.0 : 0.5;
}
#endif

#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
// Does the centre of pixel `other` (its normal and view position given) show another surface than
// the centre of `pixel`? Background and surface differ; two surfaces compare with the pass's
// similarity (`similarity`, of the two, when both are surfaces) against the threshold.
bool rsaa_centres_differ(ivec2 pixel, uvec2 normal, ivec2 other, uvec2 other_normal, float similarity) {
  if (other == pixel) return false;
  bool a = rsaa_is_surface(normal), b = rsaa_is_surface(other_normal);
  if (a != b) return true;
  if (!a) return false;
  return similarity > rsaa_threshold;
}

#ifdef RSAA_MULTI_SURFACE_BORROW
// The sources (rsaa_prepass_records.glsl, rsaa_borrow_source()): byte i % 4 of channel i / 4 is
// subsample i's, 0 for none, else 1 + (dy + 2) * 5 + (dx + 2) for the pixel (dx, dy) away (window
// space) whose centre shows the subsample's surface.
layout(binding = RSAA_POST_FIRST_UNIT + 10) uniform usampler2D rsaa_post_sources;
#ifndef RSAA_BORROW_WEIGHT
#define RSAA_BORROW_WEIGHT 0.75  // RsaaSettings::borrow_weight's default
#endif

// Borrowed colours (ours, RsaaSettings::multi_surface = "borrow"): the mean over the subsamples,
// a similar one taking the centre's colour and a dissimilar one the colour of the pixel the record
// passes found showing its surface (else its outside pixel's where that shows another surface
// than the centre, else the centre's), where one such pixel lies beyond the 3x3 (a sliver whose
// surface the neighbours do not show: a thin bar, a wire crossing between pixel centres) or the
// pixel holds 3+ surfaces (`three`, as rsaa_multi_surface() tells it). `outside`: the dissimilar
// subsamples whose outside pixel shows another surface than the centre. `weight`: the mean's share
// against the table's fetch, 1 with 3+ surfaces, else RSAA_BORROW_WEIGHT (RsaaSettings::
// borrow_weight: beyond the 3x3 is as often another triangle of a plain edge's surface, whose
// coverage the fetch estimates better than a mean of few subsamples). Returns false and weight 0
// (the caller fetches as usual) for every other pixel.
bool rsaa_borrow(ivec2 pixel, vec4 colour, uint mask, bool three, uint outside, RsaaOutside o, out vec4 resolved,
                 out float weight) {
  resolved = colour;
  weight = 0.0;
  uvec4 sources = texelFetch(rsaa_post_sources, pixel, 0);
  ivec2 last = ivec2(rsaa_viewport) - 1;
  ivec2 source[RSAA_SAMPLE_COUNT];
  bool far = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    uint index = (sources[i / 4] >> uint(8 * (i % 4))) & 255u;
    source[i] = pixel;
    if ((mask & (1u << i)) != 0u) continue;
    if (index != 0u && index <= 25u) {
      ivec2 step = ivec2(int(index - 1u) % 5, int(index - 1u) / 5) - 2;
      source[i] = clamp(pixel + step, ivec2(0), last);
      far = far || max(abs(step.x), abs(step.y)) > 1;
    } else if ((outside & (1u << i)) != 0u) {
      source[i] = o.pixel[i];
    }
  }
  if (!far && !three) return false;
  vec3 sum = vec3(0.0);  // in subsample order, as the other resolves
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    vec3 fetched = source[i] == pixel ? colour.rgb : texelFetch(rsaa_colour, source[i], 0).rgb;
    // As the fetch path: a NaN or infinite neighbour never spreads into this pixel.
    sum += !any(isnan(fetched)) && !any(isinf(fetched)) ? fetched : colour.rgb;
  }
  resolved = vec4(sum / float(RSAA_SAMPLE_COUNT), colour.a);
  weight = three ? 1.0 : RSAA_BORROW_WEIGHT;
  return true;
}
#endif

// Multi-surface resolve (ours, RsaaSettings::multi_surface = "neighbours"). One bilinear fetch
// blends the centre with neighbours of one quadrant, which suits two surfaces. When the outside
// pixels nearest the dissimilar subsamples (rsaa_neighbours) show two surfaces that differ from
// the centre's and from each other, the pixel holds 3+ surfaces: it is resolved as the mean over
// its subsamples instead, a similar subsample taking the centre's colour and a dissimilar one
// the colour of its outside pixel (the centre's when that pixel shows the centre's surface).
// Returns false and weight 0 (the caller fetches as usual) for every other pixel. `weight`: the
// share of `resolved` against the table's fetch (1: `resolved` alone; below only with borrowed
// colours).
bool rsaa_multi_surface(ivec2 pixel, uvec2 centre_normal, vec4 colour, uint mask, RsaaOutside o, out vec4 resolved,
                        out float weight) {
  resolved = colour;
  weight = 0.0;
  // A non-finite pixel is left to the fetch path, which keeps it (as the CPU reference).
  if (any(isnan(colour)) || any(isinf(colour))) return false;
  // Dissimilar subsamples whose outside pixel shows another surface than the centre; the first
  // of them (in subsample order) is the one the others are compared with.
  uint outside = 0u;
  int first = -1;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    bool differs = (mask & (1u << i)) == 0u &&
                   rsaa_centres_differ(pixel, centre_normal, o.pixel[i], o.normal[i], o.similarity[i]);
    if (differs) outside |= 1u << i;
    if (differs && first < 0) first = i;
  }
#ifdef RSAA_MULTI_SURFACE_BORROW
  if (first < 0) return rsaa_borrow(pixel, colour, mask, false, outside, o, resolved, weight);
#else
  if (first < 0) return false;
#endif
  ivec2 first_pixel = o.pixel[first];
  uvec2 first_normal = o.normal[first];
  vec3 first_position = o.position[first], first_decoded = rsaa_decode_normal(first_normal);
  // 3+ surfaces: another such outside pixel that differs from the first one too. A loop over
  // the set bits, not over every subsample: a driver that runs a SIMD batch's branches both ways
  // still stops a loop once no lane needs another turn.
  bool three = false;
  for (uint rest = outside & ~(1u << uint(first)); rest != 0u; rest &= rest - 1u) {
    int i = findLSB(rest);
    float t = rsaa_centres_similarity(o.material[first], first_position, first_decoded, o.material[i],
                                      o.position[i], rsaa_decode_normal(o.normal[i]));
    three = three || rsaa_centres_differ(first_pixel, first_normal, o.pixel[i], o.normal[i], t);
  }
#ifdef RSAA_MULTI_SURFACE_BORROW
  return rsaa_borrow(pixel, colour, mask, three, outside, o, resolved, weight);
#else
  if (!three) return false;
  // The mean over the subsamples: a similar one takes the centre's colour, a dissimilar one the
  // colour of its outside pixel where that pixel shows another surface.
  // Summed in subsample order (as the CPU reference), the outside colours fetched in a loop over
  // the set bits.
  vec3 sum = vec3(0.0);
  int next = 0;
  for (uint rest = outside; rest != 0u; rest &= rest - 1u) {
    int i = findLSB(rest);
    for (; next < i; ++next) sum += colour.rgb;
    vec3 fetched = texelFetch(rsaa_colour, o.pixel[i], 0).rgb;
    // As the fetch path: a NaN or infinite neighbour never spreads into this pixel.
    sum += !any(isnan(fetched)) && !any(isinf(fetched)) ? fetched : colour.rgb;
    next = i + 1;
  }
  for (; next < RSAA_SAMPLE_COUNT; ++next) sum += colour.rgb;
  resolved = vec4(sum / float(RSAA_SAMPLE_COUNT), colour.a);
  weight = 1.0;
  return true;
#endif
}
#endif

// The pixel's similarity codes, subsample i in codes[i].
void rsaa_pixel_codes(ivec2 pixel, out uint codes[RSAA_SAMPLE_COUNT]) {
  uvec4 code_texels[RSAA_CODE_TEXTURES];
#ifdef RSAA_READS_CODE_IMAGES
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) code_texels[k] = imageLoad(rsaa_code_images[k], pixel);
#else
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) code_texels[k] = texelFetch(rsaa_codes[k], pixel, 0);
#endif
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) codes[i] = code_texels[i / 4][i % 4];
}

// The pixel's similarity mask (paper section 2.2) from its subsamples' codes, with the decoded
// similarities, the centre's normal and (material edges) the subsamples on another material,
// bits of other_material.x where their outside pixel shows it, .y where not, that the resolve
// reads further. The all-similar mask means
// rsaa_resolve() keeps the pixel's colour. Most pixels leave early: every subsample on the
// centre's surface (code 1 = similarity 0), or a background pixel whose subsamples see no surface
// (code 0) or its surface.
uint rsaa_pixel_mask(ivec2 pixel, out float similarity[RSAA_SAMPLE_COUNT], out uvec2 centre_normal,
                     out uvec2 other_material) {
  uint codes[RSAA_SAMPLE_COUNT];
  rsaa_pixel_codes(pixel, codes);
  bool any_different = false, any_uncovered = false;
  other_material = uvec2(0u);
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    any_different = any_different || codes[i] > 1u;
    any_uncovered = any_uncovered || codes[i] == 0u;
    similarity[i] = 0.0;
#ifdef RSAA_MATERIAL_EDGES
    // (RSAA_CODE_MAX over a background centre is no material's; the fetch check tells them apart.)
    if (codes[i] == RSAA_CODE_MAX) other_material.x |= 1u << i;
    if (codes[i] == RSAA_CODE_UNSEEN_MATERIAL) other_material.y |= 1u << i;
#endif
  }
  centre_normal = uvec2(0u);
  if (!any_different && !any_uncovered) return RSAA_ALL_SIMILAR;
  centre_normal = RSAA_POST_NORMAL_AT(pixel);
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  if (!any_different && !centre_is_surface) return RSAA_ALL_SIMILAR;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) similarity[i] = rsaa_decode_similarity(codes[i], centre_is_surface);
  float split;
  return rsaa_classify(similarity, rsaa_threshold, split);
}

uint rsaa_pixel_mask(ivec2 pixel, out float similarity[RSAA_SAMPLE_COUNT], out uvec2 centre_normal) {
  uvec2 other_material;
  return rsaa_pixel_mask(pixel, similarity, centre_normal, other_material);
}

// Whether rsaa_resolve() does more than keep the pixel's colour: the test the edge pass runs on
// every pixel (rsaa_post_edges.frag, rsaa_post_classify.comp), rsaa_pixel_mask() !=
// RSAA_ALL_SIMILAR as rsaa_codes_edge() tells it. Only a code 0 needs the centre's normal (is the
// centre a surface?): on a driver that branches per pixel, most pixels read their codes only.
bool rsaa_pixel_has_edge(ivec2 pixel) {
  uint codes[RSAA_SAMPLE_COUNT];
  rsaa_pixel_codes(pixel, codes);
  int edge = rsaa_codes_edge(codes, rsaa_threshold);
  if (edge != RSAA_CODES_EDGE_IF_CENTRE_IS_SURFACE) return edge == RSAA_CODES_EDGE;
  return rsaa_is_surface(RSAA_POST_NORMAL_AT(pixel));
}

vec4 rsaa_resolve(ivec2 pixel, out uint mask) {
  float similarity[RSAA_SAMPLE_COUNT];
  uvec2 centre_normal, other_material;
  mask = rsaa_pixel_mask(pixel, similarity, centre_normal, other_material);
  vec4 colour = texelFetch(rsaa_colour, pixel, 0);
  if (mask == RSAA_ALL_SIMILAR) return colour;
  bool centre_is_surface = rsaa_is_surface(centre_normal);
#ifdef RSAA_READS_OUTSIDE_PIXELS
  RsaaOutside o = rsaa_outside_pixels(pixel, rsaa_post_position(pixel), rsaa_decode_normal(centre_normal));
#endif
#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
  mask = rsaa_split_check(centre_normal, similarity, mask, o);
#endif
  vec2 offset;
  int representative;
  rsaa_table_entry(mask, offset, representative);
#ifdef RSAA_FETCH_CHECK_NEIGHBOURS
  offset *= rsaa_fetch_check(centre_normal, similarity, mask, other_material, o);
#endif
#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
  // A mask the table leaves alone (offset 0, as every mask of an all-zero table) stays alone.
  vec4 mean;
  float mean_weight = 0.0;  // the share of `mean` in the result, the rest the fetch's
  if (offset != vec2(0.0)) rsaa_multi_surface(pixel, centre_normal, colour, mask, o, mean, mean_weight);
  if (mean_weight >= 1.0) return mean;
#endif
#if RSAA_AUTH == 1
  // Post-pass authentication (paper section 2.4): if the outside pixel nearest to the
  // representative dissimilar subsample differs from the centre much more than that subsample
  // does, the fetch would blend in a surface the pixel does not show: halve the offset.
  if (centre_is_surface && rsaa_is_surface(o.normal[representative])) {
    float to_outside = o.similarity[representative];
    if (to_outside - similarity[representative] > similarity[representative]) offset *= 0.5;
  }
#endif
  // A zero offset keeps the texel exactly (a filtered fetch at the texel centre may not).
  if (offset == vec2(0.0)) return colour;
  // Level 0, bilinear (the magnification filter) in every stage: implicit derivatives would turn
  // to the minification filter where neighbouring pixels' offsets differ.
  vec4 fetched = textureLod(rsaa_colour, (vec2(pixel) + 0.5 + offset) / rsaa_viewport, 0.0);
  // As the CPU reference: a NaN or infinite neighbour never spreads into this pixel.
  if (any(isnan(fetched)) || any(isinf(fetched))) fetched = colour;
#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
  if (mean_weight > 0.0) fetched = mix(fetched, mean, mean_weight);
#endif
  return fetched;
}

#endif  // RSAA_POST_GLSL
