// The multisample pre-pass's first record pass (rsaa_prepass_records.glsl): per pixel, the codes
// its records tell alone, and the pixel listed when a sample lies on another triangle than the
// centre's (or another material, with material edges; with borrowed colours also a surface pixel
// with a sample on the background, whose sources the codes pass finds); a pixel not listed, whose codes are
// final, goes to the post-process's edge list when they make an edge (RSAA_EDGE_LIST_BINDING).
#include "rsaa_prepass_records.glsl"

// (RsaaPass reads the group size from the program.)
layout(local_size_x = 64, local_size_y = 4) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, rsaa_rows.x);
  if (pixel.x >= int(rsaa_viewport.x) || pixel.y >= rsaa_rows.y) return;
  uint centre_surface = rsaa_centre_record_surface(texelFetch(rsaa_centre_primitive, pixel, 0).xy);
  uint codes[RSAA_SAMPLE_COUNT];
  bool listed = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    ivec2 raster;
    int sample_index;
    codes[i] = 1u;
    if (!rsaa_record_at(pixel, i, raster, sample_index)) continue;
    uvec2 record = rsaa_record(i, raster, sample_index);
    if (!rsaa_record_is_surface(record)) codes[i] = 0u;
    else if (!rsaa_record_on_centres_triangle(record, centre_surface)) listed = true;
  }
#ifdef RSAA_MULTI_SURFACE_BORROW
  // A surface pixel with a sample on the background is an edge: the codes pass finds its sources.
  bool uncovered = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) uncovered = uncovered || codes[i] == 0u;
  // (The background's primitive is 0: most background pixels skip the normal's read.)
  if (!listed && uncovered && centre_surface != 0u) listed = rsaa_is_surface(texelFetch(rsaa_centre_normal, pixel, 0).xy);
#endif
  rsaa_store_codes(pixel, codes);
  if (!listed) {  // these codes are final (0 or 1)
    rsaa_list_if_edge(pixel, codes);
    return;
  }
  uint slot = atomicAdd(rsaa_list_count, 1u);
  rsaa_list_pixels[slot] = uint(pixel.x) | (uint(pixel.y) << 16u);
}
