// The last pass of RsaaPass's compute post-process when it resolves in place (the output is the
// frame's colour): each listed pixel's resolved colour, which rsaa_post_resolve.comp wrote into a
// scratch image while every neighbour still held its 1x colour, copied into the colour image.
#include "rsaa_post_list.glsl"

layout(local_size_x = 64) in;

// No format: a write-only image takes the bound texture's (RsaaPass binds the output's own).
layout(binding = 0) uniform writeonly image2D rsaa_output;
layout(binding = 1, rgba16f) uniform readonly image2D rsaa_resolved;

void main() {
  uint index = rsaa_list_index();
  if (index >= rsaa_list_count) return;
  uint entry = rsaa_list_pixels[index];
  ivec2 pixel = ivec2(entry & 0xffffu, entry >> 16u);
  imageStore(rsaa_output, pixel, imageLoad(rsaa_resolved, pixel));
}
