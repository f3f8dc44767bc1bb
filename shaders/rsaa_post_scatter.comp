// The last pass of RsaaPass's compute post-process when it resolves in place (the output is the
// frame's colour): each listed pixel's resolved colour, which rsaa_post_resolve.comp wrote into a
// scratch image while every neighbour still held its 1x colour, copied into the colour image.
#include "rsaa_post_list.glsl"

layout(local_size_x = 64) in;

#include "rsaa_post_output.glsl"
// The scratch image as stored, in the output's format (for an sRGB output, its RGBA8 view: the
// encoded bytes, copied as they are), at texture unit RSAA_SCRATCH_UNIT.
layout(binding = RSAA_SCRATCH_UNIT) uniform sampler2D rsaa_resolved;

void main() {
  uint index = rsaa_list_index();
  if (index >= rsaa_list_count) return;
  uint entry = rsaa_list_pixels[index];
  ivec2 pixel = ivec2(entry & 0xffffu, entry >> 16u);
  rsaa_store_output(pixel, texelFetch(rsaa_resolved, pixel, 0));
}
