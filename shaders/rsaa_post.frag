// RSAA post-process: similarity codes -> mask -> offset from the baked table -> one bilinear
// fetch of the 1x colour. The table (tables/P.glsl, GL window space) is included before this.
#include "rsaa_common.glsl"

uniform sampler2D u_colour;  // linear filtering, clamp to edge
uniform usampler2D u_centre_normal;
uniform sampler2D u_centre_depth;
uniform usampler2DArray u_codes;  // layer i = subsample i
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
uniform float u_threshold;
uniform ivec2 u_neighbours[RSAA_SAMPLE_COUNT];  // nearest outside pixel per subsample
#if RSAA_AUTH == 1
// Per mask: the representative dissimilar subsample (core's representative_dissimilar()).
uniform int u_representative[1 << RSAA_SAMPLE_COUNT];
#endif

layout(location = 0) out vec4 o_colour;
#ifdef RSAA_OUTPUT_MASK
layout(location = 1) out uint o_mask;
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uvec2 centre_normal = texelFetch(u_centre_normal, pixel, 0).xy;
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  float similarity[RSAA_SAMPLE_COUNT];
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i)
    similarity[i] = rsaa_decode_similarity(texelFetch(u_codes, ivec3(pixel, i), 0).x, centre_is_surface);
  float split;
  uint mask = rsaa_classify(similarity, u_threshold, split);
  vec4 colour = texelFetch(u_colour, pixel, 0);
  if (mask != (1u << RSAA_SAMPLE_COUNT) - 1u) {
    vec2 offset = rsaa_offsets[mask];
#if RSAA_AUTH == 1
    // Post-pass authentication (paper section 2.4): if the outside pixel nearest to the
    // representative dissimilar subsample differs from the centre much more than that subsample
    // does, the fetch would blend in a surface the pixel does not show: halve the offset.
    int fs = u_representative[mask];
    ivec2 outside = clamp(pixel + u_neighbours[fs], ivec2(0), ivec2(u_viewport) - 1);
    uvec2 outside_normal = texelFetch(u_centre_normal, outside, 0).xy;
    if (centre_is_surface && rsaa_is_surface(outside_normal)) {
      vec3 pc = rsaa_view_position(vec2(pixel) + 0.5, texelFetch(u_centre_depth, pixel, 0).x,
                                   u_inverse_projection, u_viewport);
      vec3 po = rsaa_view_position(vec2(outside) + 0.5, texelFetch(u_centre_depth, outside, 0).x,
                                   u_inverse_projection, u_viewport);
      float to_outside = rsaa_similarity(pc, rsaa_decode_normal(centre_normal), po,
                                         rsaa_decode_normal(outside_normal));
      if (to_outside - similarity[fs] > similarity[fs]) offset *= 0.5;
    }
#endif
    vec4 fetched = texture(u_colour, (gl_FragCoord.xy + offset) / u_viewport);
    // As the CPU reference: a NaN or infinite neighbour never spreads into this pixel.
    if (!any(isnan(fetched)) && !any(isinf(fetched))) colour = fetched;
  }
  o_colour = colour;
#ifdef RSAA_OUTPUT_MASK
  o_mask = mask;
#endif
}
