// The resolve of RsaaPass's compute post-process (RsaaSettings::post = "compute"): rsaa_resolve()
// on each pixel of the edge list (rsaa_post_classify.comp), written into the output image, whose
// other pixels hold the copied colour (and the all-similar mask).
#include "rsaa_post.glsl"

layout(local_size_x = 64) in;

#include "rsaa_post_list.glsl"

#include "rsaa_post_output.glsl"
#ifdef RSAA_OUTPUT_MASK
layout(binding = 1, r32ui) uniform writeonly uimage2D rsaa_output_mask;
#endif

void main() {
  uint index = rsaa_list_index();
  if (index >= rsaa_list_count) return;
  uint entry = rsaa_list_pixels[index];
  ivec2 pixel = ivec2(entry & 0xffffu, entry >> 16u);
  uint mask;
  vec4 colour = rsaa_resolve(pixel, mask);
  rsaa_store_output(pixel, colour);
#ifdef RSAA_OUTPUT_MASK
  imageStore(rsaa_output_mask, pixel, uvec4(mask));
#endif
}
