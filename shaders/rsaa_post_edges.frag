// The edge pass of RsaaPass's two-pass post-process (RsaaSettings::post = "edges"): every pixel
// gets its colour as rsaa_resolve() would keep it (and the all-similar mask), and a depth of 0
// where rsaa_resolve() would do more (rsaa_pixel_mask() is not all-similar), 1 elsewhere. The
// resolve pass then runs rsaa_post.frag with the depth test, only where the depth is 0: on a
// driver that executes both sides of a branch for a whole SIMD batch (Mesa llvmpipe), an early
// depth test is what skips the edge-free pixels' work. (SMAA masks its passes with stencil alike.)
#include "rsaa_post.glsl"

layout(location = 0) out vec4 o_colour;
#ifdef RSAA_OUTPUT_MASK
layout(location = 1) out uint o_mask;
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float similarity[RSAA_SAMPLE_COUNT];
  uvec2 centre_normal;
  bool edge = rsaa_pixel_mask(pixel, similarity, centre_normal) != RSAA_ALL_SIMILAR;
  o_colour = texelFetch(rsaa_colour, pixel, 0);
  gl_FragDepth = edge ? 0.0 : 1.0;
#ifdef RSAA_OUTPUT_MASK
  o_mask = RSAA_ALL_SIMILAR;
#endif
}
