// The second half of the pre-passes that write surface records (RsaaPass, RsaaSettings::prepass
// "msaa": one multisample draw, two for a union pattern; "records": a jittered draw per
// subsample into the layers of array textures): records and depths turned into the similarity
// codes the jittered pre-pass writes, packed the same way (subsample i in channel i % 4 of code
// image i / 4), so that the post-process reads one layout. Two compute passes:
//   rsaa_prepass_list.comp   every pixel: the codes the records tell alone (a sample on the
//                            centre's triangle: 1; no surface: 0) and, for a pixel with a sample
//                            on another triangle, an entry in the list (rsaa_post_list.glsl)
//   rsaa_prepass_codes.comp  each listed pixel: every code, rsaa_subsample_code() of the jittered
//                            pre-pass on the point the sample's depth gives
// On a driver that runs every branch for a whole SIMD batch (llvmpipe) the similarity is paid for
// the listed pixels only.
//
// Defines expected before inclusion, beside rsaa_prepass.glsl's:
//   RSAA_PREPASS_MSAA, RSAA_PREPASS_MSAA_UNION + RSAA_MS_SAMPLES (a union pattern),
//   RSAA_PREPASS_MSAA_CELLS + RSAA_MS_SAMPLES (a cell pattern: one draw at a multiple of the
//   image's size, ivec2(columns, rows) raster pixels a pixel), or RSAA_PREPASS_RECORDS
//   RSAA_RECORD_FIRST_UNIT   texture units: records, depths, (union) the shifted draw's
//   RSAA_RECORD_CODE_IMAGES  first image unit of the code images (ceil(RSAA_SAMPLE_COUNT / 4))
//   RSAA_RECORD_IMAGES       (optional) first image unit of the records, read as
//                            multisample images (one per draw; where the
//                            driver's GL_MAX_IMAGE_SAMPLES and image units allow: on llvmpipe an
//                            image load costs less than a texel fetch)
//   RSAA_LIST_BINDING        the list's storage buffer (rsaa_post_list.glsl)
//   RSAA_EDGE_LIST_BINDING   (optional) a second list of the same layout, the post-process's edge
//                            list: each pass appends the pixels whose codes it finished and whose
//                            mask is not all-similar (rsaa_codes_edge()), so that RsaaPass's
//                            compute post-process does not read every pixel's codes again
//   RSAA_SUBSAMPLE_WINDOWS   vec2[](...): per subsample, its point in the pixel, window space from
//                            the lower-left corner (0.5 + its pattern position, +y up)
//   RSAA_RECORD_SOURCES_IMAGE  (with RSAA_MULTI_SURFACE_BORROW) the image unit of the sources
//                            (RSAA_SOURCES_FORMAT: r32ui, rg32ui or rgba32ui, a byte a subsample)
//                            the codes pass writes for each listed pixel (rsaa_borrow_source())
// (rsaa_record_pass_defines() in runtime/rsaa_pass.h writes these.) Uniforms: rsaa_rows (location
// 0), the rows [x, y) a dispatch covers; with RSAA_EDGE_LIST_BINDING rsaa_list_edges (location 1).
#ifndef RSAA_PREPASS_RECORDS_GLSL
#define RSAA_PREPASS_RECORDS_GLSL

#define RSAA_PREPASS_COMPUTE
#include "rsaa_prepass.glsl"

// Where the records are: the samples of multisample textures (RSAA_PREPASS_MSAA), or the layers of
// array textures, layer i = subsample i (RSAA_PREPASS_RECORDS: jittered draws writing records).
#if defined(RSAA_PREPASS_RECORDS)
#define RSAA_RECORD_USAMPLER usampler2DArray
#define RSAA_RECORD_SAMPLER sampler2DArray
#define RSAA_RECORD_UIMAGE uimage2DArray
#define RSAA_RECORD_FETCH(records, raster, index) texelFetch(records, ivec3(raster, index), 0)
#define RSAA_RECORD_LOAD(records, raster, index) imageLoad(records, ivec3(raster, index))
#elif defined(RSAA_PREPASS_MSAA)
#define RSAA_RECORD_USAMPLER usampler2DMS
#define RSAA_RECORD_SAMPLER sampler2DMS
#define RSAA_RECORD_UIMAGE uimage2DMS
#define RSAA_RECORD_FETCH(records, raster, index) texelFetch(records, raster, index)
#define RSAA_RECORD_LOAD(records, raster, index) imageLoad(records, raster, index)
#else
#error "the record passes need RSAA_PREPASS_MSAA or RSAA_PREPASS_RECORDS"
#endif

layout(binding = RSAA_RECORD_FIRST_UNIT) uniform RSAA_RECORD_USAMPLER rsaa_records;
layout(binding = RSAA_RECORD_FIRST_UNIT + 1) uniform RSAA_RECORD_SAMPLER rsaa_record_depths;
#ifdef RSAA_PREPASS_MSAA_UNION
layout(binding = RSAA_RECORD_FIRST_UNIT + 2) uniform RSAA_RECORD_USAMPLER rsaa_records2;
layout(binding = RSAA_RECORD_FIRST_UNIT + 3) uniform RSAA_RECORD_SAMPLER rsaa_record_depths2;
#endif
#ifdef RSAA_RECORD_IMAGES
layout(binding = RSAA_RECORD_IMAGES, rg32ui) uniform readonly RSAA_RECORD_UIMAGE rsaa_record_images[2];
#endif
#if !defined(RSAA_PREPASS_MSAA_UNION) && !defined(RSAA_PREPASS_MSAA_CELLS)
#define RSAA_MS_SAMPLES RSAA_SAMPLE_COUNT
#endif
layout(binding = RSAA_RECORD_CODE_IMAGES, RSAA_CODE_IMAGE_FORMAT) uniform writeonly uimage2D
    rsaa_code_images[RSAA_CODE_TEXTURES];

#ifdef RSAA_MULTI_SURFACE_BORROW
layout(binding = RSAA_RECORD_SOURCES_IMAGE, RSAA_SOURCES_FORMAT) uniform writeonly uimage2D rsaa_source_image;
#endif

// The rows [x, y) this dispatch covers (RsaaPass runs bands of rows when the list cannot hold
// every pixel).
layout(location = 0) uniform ivec2 rsaa_rows;
// Per subsample, the window-space position of the point it sees relative to its pixel's
// lower-left corner (0.5 + its pattern position, +y up).
const vec2 rsaa_subsample_window[RSAA_SAMPLE_COUNT] = RSAA_SUBSAMPLE_WINDOWS;

#include "rsaa_post_list.glsl"

// The raster pixel and sample whose record is subsample i of `pixel`: the pixel itself for the
// first draw's samples, rsaa_neighbours[i].zw away for the shifted draw's; false outside the
// image (one column and one row at the border, by the shift's direction), where the subsample
// counts as the centre's surface (code 1), as no pixel reads it.
bool rsaa_record_at(ivec2 pixel, int i, out ivec2 raster, out int sample_index) {
  raster = pixel, sample_index = i;
#ifdef RSAA_PREPASS_MSAA_CELLS
  // The pixel's cells are raster pixels of the one draw: subsample i is sample i % RSAA_MS_SAMPLES
  // of the cell rsaa_neighbours[i].zw (window space) from the pixel's lower-left cell.
  raster = pixel * RSAA_PREPASS_MSAA_CELLS + rsaa_neighbours[i].zw, sample_index = i % RSAA_MS_SAMPLES;
#endif
#ifdef RSAA_PREPASS_MSAA_UNION
  if (i >= RSAA_MS_SAMPLES) {
    raster = pixel + rsaa_neighbours[i].zw, sample_index = i - RSAA_MS_SAMPLES;
    return all(greaterThanEqual(raster, ivec2(0))) && all(lessThan(raster, ivec2(rsaa_viewport)));
  }
#endif
  return true;
}

uvec2 rsaa_record(int i, ivec2 raster, int sample_index) {
#ifdef RSAA_RECORD_IMAGES
#ifdef RSAA_PREPASS_MSAA_UNION
  return RSAA_RECORD_LOAD(rsaa_record_images[i < RSAA_MS_SAMPLES ? 0 : 1], raster, sample_index).xy;
#else
  return RSAA_RECORD_LOAD(rsaa_record_images[0], raster, sample_index).xy;
#endif
#else
#ifdef RSAA_PREPASS_MSAA_UNION
  if (i >= RSAA_MS_SAMPLES) return RSAA_RECORD_FETCH(rsaa_records2, raster, sample_index).xy;
#endif
  return RSAA_RECORD_FETCH(rsaa_records, raster, sample_index).xy;
#endif
}

// What a record's x must hold to be on the centre's triangle: the centre primitive target's
// texel (primitive, and with material edges material) as rsaa_record_surface() packs it.
uint rsaa_centre_record_surface(uvec2 centre) {
#ifdef RSAA_MATERIAL_EDGES
  return rsaa_record_surface(centre.x, centre.y);
#else
  return rsaa_record_surface(centre.x, 0u);
#endif
}

// Whether a record is on the centre's triangle (`centre_surface`: rsaa_centre_record_surface());
// primitive 0 never is, as in the jittered pre-pass.
bool rsaa_record_on_centres_triangle(uvec2 record, uint centre_surface) {
  return (record.x & RSAA_RECORD_PRIMITIVE_BITS) != 0u && record.x == centre_surface;
}

// The code of subsample i of `pixel` whose record shows a surface at view-space `point`: the
// jittered pre-pass's rsaa_subsample_code(), with the record's primitive and material widened to
// the centre's (`c`: rsaa_centre(pixel)) where their stored bits agree with it, so that it decides
// as the listing pass did.
uint rsaa_record_code(RsaaCentre c, ivec2 pixel, int i, vec3 point, uvec2 record) {
  uvec2 centre = c.primitive;
  uint primitive = record.x, material = 0u;
#ifdef RSAA_MATERIAL_EDGES
  primitive &= RSAA_RECORD_PRIMITIVE_BITS;
  if (primitive == (centre.x & RSAA_RECORD_PRIMITIVE_BITS)) primitive = centre.x;
  // The stored bits stand for the centre's material, else the outside pixel's (the code tells
  // whether that pixel shows it), else for themselves: a value unlike both.
  uint stored = record.x >> RSAA_RECORD_MATERIAL_SHIFT;
  if (stored == (centre.y & RSAA_RECORD_MATERIAL_BITS)) material = centre.y;
  else {
    uint outside = rsaa_outside_material(pixel, i);
    material = stored == (outside & RSAA_RECORD_MATERIAL_BITS) ? outside : stored;
  }
#endif
  return rsaa_subsample_code(c, pixel, i, point, rsaa_record_normal(record), primitive, material);
}

float rsaa_record_depth(int i, ivec2 raster, int sample_index) {
#ifdef RSAA_PREPASS_MSAA_UNION
  if (i >= RSAA_MS_SAMPLES) return RSAA_RECORD_FETCH(rsaa_record_depths2, raster, sample_index).x;
#endif
  return RSAA_RECORD_FETCH(rsaa_record_depths, raster, sample_index).x;
}

#ifdef RSAA_MULTI_SURFACE_BORROW
// Borrowed colours (RsaaSettings::multi_surface = "borrow"): for a subsample that may be
// dissimilar, the pixel whose centre shows the surface it sees, for the post-process to take that
// colour from (rsaa_post.glsl, rsaa_borrow()). The records know which surface a subsample sees;
// the post-process knows only how different it is from the centre.
const int RSAA_BORROW_RADIUS = 2;  // the window searched: 5 x 5 pixels
#define RSAA_BORROW_WINDOW 25
#define RSAA_BORROW_OUTSIDE_IMAGE 0xffffffffu

// The centres of the window around `pixel`, read once for all its subsamples: row-major from the
// lower-left (window space), rsaa_centre_record_surface() (0: the background, primitive 0),
// RSAA_BORROW_OUTSIDE_IMAGE beyond the image.
void rsaa_borrow_window(ivec2 pixel, out uint keys[RSAA_BORROW_WINDOW]) {
  ivec2 last = ivec2(rsaa_viewport) - 1;
  for (int k = 0; k < RSAA_BORROW_WINDOW; ++k) {
    ivec2 q = pixel + ivec2(k % 5, k / 5) - RSAA_BORROW_RADIUS;
    keys[k] = RSAA_BORROW_OUTSIDE_IMAGE;
    if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;
    // (The background's primitive is 0, as the engine writes it: one read a pixel.)
    keys[k] = rsaa_centre_record_surface(texelFetch(rsaa_centre_primitive, q, 0).xy);
  }
}

// The window pixel nearest subsample i of `pixel` (its record, and the view-space point it sees)
// that shows its surface: whose centre is on the same triangle (primitive, and material with
// material edges; the background for a subsample seeing none) or, with `similar`, on the same
// material and similar to the subsample (rsaa_similarity() below the threshold: another triangle
// of its surface). 0 for none, else 1 + the window index; never the pixel itself.
uint rsaa_borrow_nearest(ivec2 pixel, int i, uvec2 record, vec3 point, uint keys[RSAA_BORROW_WINDOW], bool similar) {
  bool surface = rsaa_record_is_surface(record);
  uint wanted = surface ? record.x : 0u;
  vec2 at = vec2(pixel) + rsaa_subsample_window[i];
  vec3 normal = surface ? rsaa_record_normal(record) : vec3(0.0);
  uint found = 0u;
  float nearest = 1.0e30;
  for (int k = 0; k < RSAA_BORROW_WINDOW; ++k) {
    ivec2 q = pixel + ivec2(k % 5, k / 5) - RSAA_BORROW_RADIUS;
    vec2 d = vec2(q) + 0.5 - at;
    if (k == RSAA_BORROW_WINDOW / 2 || dot(d, d) >= nearest) continue;
    bool shows = keys[k] == wanted;
    if (similar) {
      shows = keys[k] != 0u && keys[k] != RSAA_BORROW_OUTSIDE_IMAGE;
#ifdef RSAA_MATERIAL_EDGES
      shows = shows && (keys[k] >> RSAA_RECORD_MATERIAL_SHIFT) == (record.x >> RSAA_RECORD_MATERIAL_SHIFT);
#endif
      shows = shows && rsaa_similarity(point, normal, rsaa_centre_position(q),
                                       rsaa_decode_normal(texelFetch(rsaa_centre_normal, q, 0).xy)) < rsaa_threshold;
    }
    if (shows) nearest = dot(d, d), found = uint(k + 1);
  }
  return found;
}

// The source of subsample i of `pixel`: the nearest window pixel on its triangle, else (a surface)
// the nearest on a similar plane of its material (rsaa_borrow_nearest). Triangles first: the
// similar plane nearer the subsample is often a neighbouring facet of another thin wire or bar
// (measured: the fence 35.69 dB triangles first, 34.98 nearest of either). 0 for none, else
// 1 + the window index (1 + (dy + 2) * 5 + (dx + 2), window space), never the pixel itself.
uint rsaa_borrow_source(ivec2 pixel, int i, uvec2 record, vec3 point, uint keys[RSAA_BORROW_WINDOW]) {
  uint found = rsaa_borrow_nearest(pixel, i, record, point, keys, false);
  if (found != 0u || !rsaa_record_is_surface(record)) return found;
  return rsaa_borrow_nearest(pixel, i, record, point, keys, true);
}
#endif

#ifdef RSAA_EDGE_LIST_BINDING
layout(std430, binding = RSAA_EDGE_LIST_BINDING) buffer RsaaPostEdgeList {
  uint rsaa_edge_list_groups[3];  // (set by rsaa_post_list_size.comp before the resolve)
  uint rsaa_edge_list_count;
  uint rsaa_edge_list_pixels[];
};
// Whether this pre-pass lists the edges (RsaaPass lists them there when its list holds every
// pixel; else its post-process lists them in rounds of rows).
layout(location = 1) uniform bool rsaa_list_edges;
#endif

// Appends `pixel` to the post-process's edge list when its final codes make a mask other than
// all-similar (the post-process's rsaa_pixel_has_edge() on them); nothing without the list.
void rsaa_list_if_edge(ivec2 pixel, uint codes[RSAA_SAMPLE_COUNT]) {
#ifdef RSAA_EDGE_LIST_BINDING
  if (!rsaa_list_edges) return;
  int edge = rsaa_codes_edge(codes, rsaa_threshold);
  if (edge == RSAA_CODES_EDGE_IF_CENTRE_IS_SURFACE)
    edge = rsaa_is_surface(texelFetch(rsaa_centre_normal, pixel, 0).xy) ? RSAA_CODES_EDGE : RSAA_CODES_ALL_SIMILAR;
  if (edge != RSAA_CODES_EDGE) return;
  uint slot = atomicAdd(rsaa_edge_list_count, 1u);
  rsaa_edge_list_pixels[slot] = uint(pixel.x) | (uint(pixel.y) << 16u);
#endif
}

void rsaa_store_codes(ivec2 pixel, uint codes[RSAA_SAMPLE_COUNT]) {
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) {
    uvec4 texel = uvec4(0u);
    for (int c = 0; c < 4 && 4 * k + c < RSAA_SAMPLE_COUNT; ++c) texel[c] = codes[4 * k + c];
    imageStore(rsaa_code_images[k], pixel, texel);
  }
}

#endif  // RSAA_PREPASS_RECORDS_GLSL
