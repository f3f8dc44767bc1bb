// The output image of RsaaPass's compute post-process (rsaa_post_resolve.comp, and
// rsaa_post_scatter.comp when it resolves in place): the engine's colour texture in its own
// format (a write-only image needs none), or, for an sRGB texture (image units have no sRGB
// format), an RGBA8 view of it, into which the linear colours are stored encoded.
#ifndef RSAA_POST_OUTPUT_GLSL
#define RSAA_POST_OUTPUT_GLSL

layout(binding = 0) uniform writeonly image2D rsaa_output;
// 1: the output is an RGBA8 view of an sRGB texture (RsaaPass sets it per resolve).
layout(location = 1) uniform int rsaa_output_srgb;

vec3 rsaa_linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void rsaa_store_output(ivec2 pixel, vec4 colour) {
  if (rsaa_output_srgb != 0) colour = vec4(rsaa_linear_to_srgb(colour.rgb), clamp(colour.a, 0.0, 1.0));
  imageStore(rsaa_output, pixel, colour);
}

#endif  // RSAA_POST_OUTPUT_GLSL
