// The edge list of RsaaPass's compute post-process (RsaaSettings::post = "compute"): one
// invocation per pixel appends the pixels where rsaa_resolve() does more than keep the colour
// (rsaa_pixel_has_edge()) to a list; rsaa_post_list_size.comp then sizes the resolve's dispatch
// and rsaa_post_resolve.comp runs on the listed pixels only, every SIMD lane on an edge pixel (the
// edge pass + depth test of the "edges" post-process skips edge-free SIMD batches, but runs a
// whole batch for one edge pixel in it). One atomic per listed pixel: a group-wide count in shared
// memory (three barriers) cost more on llvmpipe, which has no subgroup operations. RsaaPass
// defines RSAA_CODE_IMAGES for it (the codes and the normal read as images); groups of 64 x 4
// pixels cost less than 8 x 8 on llvmpipe (README, *Cheaper post-processes*).
#include "rsaa_post.glsl"

// (RsaaPass reads the group size from the program.)
layout(local_size_x = 64, local_size_y = 4) in;

#include "rsaa_post_list.glsl"

// The rows [x, y) this dispatch lists, from row x: all of them, or a band when the list cannot
// hold every pixel of the image (RsaaPass then lists and resolves band after band).
layout(location = 0) uniform ivec2 rsaa_rows;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, rsaa_rows.x);
  if (pixel.x >= int(rsaa_viewport.x) || pixel.y >= rsaa_rows.y || !rsaa_pixel_has_edge(pixel)) return;
  uint slot = atomicAdd(rsaa_list_count, 1u);
  rsaa_list_pixels[slot] = uint(pixel.x) | (uint(pixel.y) << 16u);
}
