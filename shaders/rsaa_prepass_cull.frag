// The marking pass of the culled jittered pre-pass (RsaaSettings::prepass_cull = "neighbours"),
// drawn once per frame before the per-subsample draws. A pixel whose 3x3 neighbourhood of pixel
// centres shows only its own triangle is left with the clear values, code 1 (similarity 0: the
// centre's surface) for every subsample and stencil 0, and the per-subsample draws, behind an
// early stencil test, skip it. The other pixels get code 0 (no surface yet, as the full pre-pass
// clears it) and stencil 1.
//
// Why: on Mesa llvmpipe a jittered draw's cost is mostly its fragment work (draws whose fragments
// an early depth test rejects cost a fraction of full ones).
// Why triangles and not surfaces: a similarity test per neighbour in this pass cost more than
// the draws it saved (llvmpipe runs it for every pixel). The price: a feature thinner than a
// pixel that covers no centre of the 3x3 neighbourhood is not seen (README, "Culling the
// pre-pass").
#include "rsaa_prepass.glsl"

#define RSAA_CODE_TEXTURES ((RSAA_SAMPLE_COUNT + 3) / 4)

layout(location = 0) out uvec4 o_codes[RSAA_CODE_TEXTURES];

bool rsaa_prepass_needed(ivec2 pixel) {
  uint primitive = texelFetch(rsaa_centre_primitive, pixel, 0).x;
  ivec2 last = ivec2(rsaa_viewport) - 1;
  bool other = false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      other = other || texelFetch(rsaa_centre_primitive, clamp(pixel + ivec2(dx, dy), ivec2(0), last), 0).x != primitive;
  return other;
}

void main() {
  if (!rsaa_prepass_needed(ivec2(gl_FragCoord.xy))) discard;  // keeps code 1, stencil 0
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) o_codes[k] = uvec4(0u);
}
