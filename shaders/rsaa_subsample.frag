// RSAA pre-pass: compares the surface seen by a subsample with the one seen by the pixel centre
// (from the 1x G-buffer) and stores the compressed similarity code. Two ways to run it:
//   jittered (default): drawn once per subsample with the image jittered so that the subsample
//     lands on the pixel centre; the pass packs four subsamples per texel (it writes all four
//     channels and masks the others);
//   RSAA_PREPASS_MSAA: one draw into a multisample target whose sample positions are the
//     pattern's, the shader run per sample (gl_SampleID = subsample index).
#include "rsaa_common.glsl"

in FragmentData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
  flat vec3 face_normal;
} f_in;

uniform usampler2D u_centre_normal;
uniform usampler2D u_centre_primitive;
uniform sampler2D u_centre_depth;
uniform mat4 u_inverse_projection;  // unjittered
uniform vec2 u_viewport;
uniform uint u_primitive_base;
#ifdef RSAA_PREPASS_MSAA
uniform ivec2 u_neighbours[RSAA_SAMPLE_COUNT];  // nearest outside pixel per subsample, window space
uniform vec2 u_shift;       // window space: the point a sample sees is its position + u_shift
uniform int u_sample_base;  // subsample index of this draw's sample 0
#else
uniform ivec2 u_neighbour;  // nearest outside pixel of this subsample, window space
#endif
uniform float u_threshold;

layout(location = 0) out uvec4 o_code;

vec3 centre_position(ivec2 pixel) {
  return rsaa_view_position(vec2(pixel) + 0.5, texelFetch(u_centre_depth, pixel, 0).x,
                            u_inverse_projection, u_viewport);
}

void main() {
#ifdef RSAA_PREPASS_MSAA
  // The point this sample sees (window space) and the pixel that contains it: the sample's own
  // pixel, but for the shifted second draw of a union pattern (RSAA_PREPASS_MSAA_UNION).
  vec2 window = floor(gl_FragCoord.xy) + gl_SamplePosition + u_shift;
  ivec2 pixel = ivec2(floor(window));
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, ivec2(u_viewport)))) {
    o_code = uvec4(1u);  // a point outside the image: no pixel reads it
    return;
  }
#else
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#endif
  // Shortcut: the triangle that covers this subsample also covers the centre.
  if (texelFetch(u_centre_primitive, pixel, 0).x == u_primitive_base + uint(gl_PrimitiveID) + 1u) {
    o_code = uvec4(1u);  // decodes to 0
    return;
  }
  uvec2 centre_normal = texelFetch(u_centre_normal, pixel, 0).xy;
  if (!rsaa_is_surface(centre_normal)) {
    o_code = uvec4(RSAA_CODE_MAX);  // a surface subsample in a background pixel: different
    return;
  }
#ifdef RSAA_PREPASS_MSAA
  // The sample's point from its window position and its own rasterized depth, as the centre's
  // is from the G-buffer: Mesa llvmpipe's perspective-correct interpolation at a sample
  // (per-sample shading, interpolateAtSample/AtOffset alike) slides the point along the view ray
  // (relative depth error 4e-4 median, up to 0.17 on 2CylinderEngine), which made same-surface
  // subsamples look dissimilar.
  vec3 ps = rsaa_view_position(window, gl_FragCoord.z, u_inverse_projection, u_viewport);
  ivec2 neighbour_step = u_neighbours[u_sample_base + gl_SampleID];
#else
  vec3 ps = f_in.view_position;
  ivec2 neighbour_step = u_neighbour;
#endif
  vec3 ns = f_in.face_normal;
  float similarity = rsaa_similarity(ps, ns, centre_position(pixel), rsaa_decode_normal(centre_normal));
#if RSAA_AUTH == 2
  // Pre-pass authentication (paper section 2.4): a subsample that looks different from the
  // centre but even more different from its nearest outside pixel joins the similar cluster.
  ivec2 outside = pixel + neighbour_step;
  if (similarity > 0.5 * u_threshold && all(greaterThanEqual(outside, ivec2(0))) &&
      all(lessThan(outside, ivec2(u_viewport)))) {
    uvec2 outside_normal = texelFetch(u_centre_normal, outside, 0).xy;
    if (rsaa_is_surface(outside_normal)) {
      float to_outside = rsaa_similarity(ps, ns, centre_position(outside),
                                         rsaa_decode_normal(outside_normal));
      if (to_outside > similarity) similarity = 0.0;
    }
  }
#endif
  o_code = uvec4(rsaa_encode_similarity(similarity));
}
