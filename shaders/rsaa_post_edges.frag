// The edge pass of RsaaPass's two-pass post-process (RsaaSettings::post = "edges"): it keeps the
// full-screen triangle's depth where rsaa_resolve() would do more than keep the pixel's colour
// (rsaa_pixel_has_edge()) and discards every other pixel. RsaaPass copies the
// colour image into the output first; the resolve pass then runs rsaa_post.frag with the depth
// test, only where this pass wrote depth: on a driver that executes both sides of a branch for a
// whole SIMD batch (Mesa llvmpipe), an early depth test is what skips the edge-free pixels' work.
// (SMAA masks its passes with stencil alike.) No colour output: the pass's target is depth only.
#include "rsaa_post.glsl"

void main() {
  if (!rsaa_pixel_has_edge(ivec2(gl_FragCoord.xy))) discard;
}
