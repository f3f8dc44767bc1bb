// Shading at one sample position (scene_shading.glsl). With RSAA_GBUFFER also writes the
// compressed geometric normal, the primitive id (+1; 0 = background) and the triangle's material
// (scene_facet_material.glsl; a second channel, kept where the primitive target has one) for
// the RSAA pre-pass;
// with FXAA_LUMA the luma the FXAA-style post-process reads (fxaa_luma.glsl).
#include "rsaa_common.glsl"
#include "scene_shading.glsl"
#ifdef FXAA_LUMA
#include "fxaa_luma.glsl"
#endif

layout(location = 0) out vec4 o_colour;
#ifdef RSAA_GBUFFER
layout(location = 1) out uvec2 o_normal;
layout(location = 2) out uvec2 o_primitive;
#endif
#ifdef FXAA_LUMA
layout(location = 1) out float o_luma;
#endif

void main() {
  o_colour = shade_scene_fragment();
#ifdef RSAA_GBUFFER
  o_normal = rsaa_encode_normal(f_in.face_normal);
  o_primitive = uvec2(scene_primitive_order() + 1u, f_in.material);
#endif
#ifdef FXAA_LUMA
  o_luma = fxaa_luma(o_colour.rgb);
#endif
}
