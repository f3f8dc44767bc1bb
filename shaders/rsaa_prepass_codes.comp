// The multisample pre-pass's second record pass (rsaa_prepass_records.glsl): every code of each
// pixel rsaa_prepass_list.comp listed, as the jittered pre-pass computes it, and the pixel in the
// post-process's edge list when they make an edge (RSAA_EDGE_LIST_BINDING); with borrowed colours
// (RSAA_MULTI_SURFACE_BORROW) each listed pixel's sources too.
#include "rsaa_prepass_records.glsl"

layout(local_size_x = 64) in;

void main() {
  uint index = rsaa_list_index();
  if (index >= rsaa_list_count) return;
  uint entry = rsaa_list_pixels[index];
  ivec2 pixel = ivec2(entry & 0xffffu, entry >> 16u);
  RsaaCentre centre = rsaa_centre(pixel);  // once for all subsamples
  uint codes[RSAA_SAMPLE_COUNT];
#ifdef RSAA_MULTI_SURFACE_BORROW
  uvec2 records[RSAA_SAMPLE_COUNT];
  vec3 points[RSAA_SAMPLE_COUNT];
  uint may_differ = 0u;  // subsamples above the threshold: only they can be dissimilar
  bool centre_is_surface = rsaa_is_surface(centre.normal);
#endif
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    ivec2 raster;
    int sample_index;
    codes[i] = 1u;
    if (!rsaa_record_at(pixel, i, raster, sample_index)) continue;
    uvec2 record = rsaa_record(i, raster, sample_index);
    float depth = rsaa_record_depth(i, raster, sample_index);
    vec3 point = rsaa_view_position(vec2(pixel) + rsaa_subsample_window[i], depth, rsaa_inverse_projection,
                                    rsaa_viewport);
    codes[i] = rsaa_record_is_surface(record) ? rsaa_record_code(centre, pixel, i, point, record) : 0u;
#ifdef RSAA_MULTI_SURFACE_BORROW
    records[i] = record, points[i] = point;
    if (rsaa_decode_similarity(codes[i], centre_is_surface) > rsaa_threshold) may_differ |= 1u << i;
#endif
  }
  rsaa_store_codes(pixel, codes);
#ifdef RSAA_MULTI_SURFACE_BORROW
  uvec4 sources = uvec4(0u);
  if (may_differ != 0u) {
    uint keys[RSAA_BORROW_WINDOW];
    rsaa_borrow_window(pixel, keys);
    for (uint rest = may_differ; rest != 0u; rest &= rest - 1u) {
      int i = findLSB(rest);
      sources[i / 4] |= rsaa_borrow_source(pixel, i, records[i], points[i], keys) << uint(8 * (i % 4));
    }
  }
  imageStore(rsaa_source_image, pixel, sources);
#endif
  rsaa_list_if_edge(pixel, codes);
}
