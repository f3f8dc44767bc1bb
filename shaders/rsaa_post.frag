// RSAA post-process: similarity codes -> mask -> offset from the table -> one bilinear fetch of
// the 1x colour. The table is a texture filled by the pass from table data (core's OffsetTable),
// so any table renders without rebuilding: texel (mask % 256, mask / 256) holds the offset in GL
// window space (+y up) and, for post-pass authentication, the mask's representative subsample.
#include "rsaa_common.glsl"

// Codes arrive packed, four subsamples per texel (RSAA_CODE_TEXTURES = ceil(n / 4) textures):
// subsample i is channel i % 4 of texture i / 4; or, from the multisample pre-pass
// (RSAA_PREPASS_MSAA), as sample i of one multisample texture.
#define RSAA_CODE_TEXTURES ((RSAA_SAMPLE_COUNT + 3) / 4)

uniform sampler2D u_colour;  // linear filtering, clamp to edge
uniform usampler2D u_centre_normal;
uniform sampler2D u_centre_depth;
#ifdef RSAA_PREPASS_MSAA
uniform usampler2DMS u_codes_ms;  // sample i = subsample i
#ifdef RSAA_PREPASS_MSAA_UNION
// Union pattern: u_codes_ms holds subsamples 0..RSAA_MS_SAMPLES-1; the shifted draw's sample i
// is subsample RSAA_MS_SAMPLES + i of the pixel at its raster pixel - u_union_raster[i].
uniform usampler2DMS u_codes_ms2;
uniform ivec2 u_union_raster[RSAA_MS_SAMPLES];
#endif
#else
uniform usampler2D u_codes[RSAA_CODE_TEXTURES];
#endif
uniform sampler2D u_table;  // RGBA32F: offset.xy, representative subsample, unused
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
uniform float u_threshold;
uniform ivec2 u_neighbours[RSAA_SAMPLE_COUNT];  // nearest outside pixel per subsample

layout(location = 0) out vec4 o_colour;
#ifdef RSAA_OUTPUT_MASK
layout(location = 1) out uint o_mask;
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint codes[RSAA_SAMPLE_COUNT];
#ifndef RSAA_PREPASS_MSAA
  uvec4 code_texels[RSAA_CODE_TEXTURES];
  for (int k = 0; k < RSAA_CODE_TEXTURES; ++k) code_texels[k] = texelFetch(u_codes[k], pixel, 0);
#endif
  bool any_different = false, any_uncovered = false;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
#if defined(RSAA_PREPASS_MSAA_UNION)
    if (i < RSAA_MS_SAMPLES) {
      codes[i] = texelFetch(u_codes_ms, pixel, i).x;
    } else {
      // Its raster pixel is outside the image (one column and one row at the edge, by the
      // shift's direction): the shifted draw has no code there; call it similar.
      ivec2 r = pixel + u_union_raster[i - RSAA_MS_SAMPLES];
      bool inside = all(greaterThanEqual(r, ivec2(0))) && all(lessThan(r, ivec2(u_viewport)));
      codes[i] = inside ? texelFetch(u_codes_ms2, r, i - RSAA_MS_SAMPLES).x : 1u;
    }
#elif defined(RSAA_PREPASS_MSAA)
    codes[i] = texelFetch(u_codes_ms, pixel, i).x;
#else
    codes[i] = code_texels[i / 4][i % 4];
#endif
    any_different = any_different || codes[i] > 1u;
    any_uncovered = any_uncovered || codes[i] == 0u;
  }
  // Most pixels: every subsample on the centre's surface (code 1 = similarity 0), or a background
  // pixel whose subsamples see no surface (code 0) or its surface. Their colour stays.
  uvec2 centre_normal = uvec2(1u);
  if (!any_different && any_uncovered) centre_normal = texelFetch(u_centre_normal, pixel, 0).xy;
  if (!any_different && (!any_uncovered || !rsaa_is_surface(centre_normal))) {
    o_colour = texelFetch(u_colour, pixel, 0);
#ifdef RSAA_OUTPUT_MASK
    o_mask = (1u << RSAA_SAMPLE_COUNT) - 1u;
#endif
    return;
  }
  centre_normal = texelFetch(u_centre_normal, pixel, 0).xy;
  bool centre_is_surface = rsaa_is_surface(centre_normal);
  float similarity[RSAA_SAMPLE_COUNT];
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) similarity[i] = rsaa_decode_similarity(codes[i], centre_is_surface);
  float split;
  uint mask = rsaa_classify(similarity, u_threshold, split);
  vec4 colour = texelFetch(u_colour, pixel, 0);
  if (mask != (1u << RSAA_SAMPLE_COUNT) - 1u) {
    vec4 entry = texelFetch(u_table, ivec2(mask & 255u, mask >> 8u), 0);
    vec2 offset = entry.xy;
#if RSAA_AUTH == 1
    // Post-pass authentication (paper section 2.4): if the outside pixel nearest to the
    // representative dissimilar subsample differs from the centre much more than that subsample
    // does, the fetch would blend in a surface the pixel does not show: halve the offset.
    int fs = int(entry.z);
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
    // A zero offset keeps the texel exactly (a filtered fetch at the texel centre may not).
    if (offset != vec2(0.0)) {
      vec4 fetched = texture(u_colour, (gl_FragCoord.xy + offset) / u_viewport);
      // As the CPU reference: a NaN or infinite neighbour never spreads into this pixel.
      if (!any(isnan(fetched)) && !any(isinf(fetched))) colour = fetched;
    }
  }
  o_colour = colour;
#ifdef RSAA_OUTPUT_MASK
  o_mask = mask;
#endif
}
