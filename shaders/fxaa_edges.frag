// The edge pass of the FXAA-style post-process: it keeps the full-screen triangle's depth where
// fxaa.frag may change the pixel (fxaa_contrast: not `keep`) and discards every other pixel. The
// technique copies the colour image into the output first; fxaa.frag then runs behind the depth
// test, only where this pass wrote depth (on llvmpipe, which runs every instruction for a whole
// SIMD batch, the depth test is what skips the kept pixels). Two luma gathers a pixel.
#include "fxaa_edge.glsl"

uniform sampler2D u_luma;  // fxaa_luma of the colour, R16F, clamp to edge
uniform vec2 u_viewport;

void main() {
  vec2 texel = 1.0 / u_viewport;
  vec2 corner = vec2(ivec2(gl_FragCoord.xy)) * texel;  // the pixel's lower left corner
  // As fxaa.frag: a gather at a corner returns (i0, j1), (i1, j1), (i1, j0), (i0, j0).
  vec4 lower_left = textureGather(u_luma, corner, 0);           // w, m, s, sw
  vec4 upper_right = textureGather(u_luma, corner + texel, 0);  // n, ne, e, m
  bool keep;
  fxaa_contrast(lower_left.y, upper_right.x, lower_left.z, upper_right.z, lower_left.x, keep);
  if (keep) discard;
}
