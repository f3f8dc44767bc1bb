// The RSAA post-process RsaaPass runs: rsaa_resolve() (rsaa_post.glsl) per pixel of a full-screen
// triangle; with RSAA_OUTPUT_MASK the similarity mask too (for tests). After the edge pass
// (rsaa_post_edges.frag) it runs only where that pass wrote depth 0: the depth test comes first.
#include "rsaa_post.glsl"

layout(early_fragment_tests) in;

layout(location = 0) out vec4 o_colour;
#ifdef RSAA_OUTPUT_MASK
layout(location = 1) out uint o_mask;
#endif

void main() {
  uint mask;
  o_colour = rsaa_resolve(ivec2(gl_FragCoord.xy), mask);
#ifdef RSAA_OUTPUT_MASK
  o_mask = mask;
#endif
}
