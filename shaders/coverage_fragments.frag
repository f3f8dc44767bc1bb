// Coverage-based techniques, fragment stage: shades the fragment once at the pixel centre (with
// COVERAGE_SHADING_INPUTS: stores its albedo and shading normal for the resolve to shade),
// computes its coverage mask from the half-plane LUT and its depth plane, and appends a record
// to the pixel's list (llvmpipe has no fragment-shader interlock; coverage_resolve.frag replays
// each list in primitive order instead). Record layout: coverage_record.glsl.
#include "rsaa_common.glsl"
#include "scene_shading.glsl"
#include "coverage_record.glsl"

in CoverageTriangle {
  flat vec4 s01;
  flat vec2 s2;
  flat vec3 depth_plane;
  flat vec4 bounds;
  flat int exact;
} f_cov;

uniform usampler2D u_halfplane_lut;
uniform uvec2 u_full_mask;  // the coverage pattern's samples
layout(r32ui) uniform coherent uimage2D u_heads;
uniform bool u_z_prepass;         // coverage_max_depth.frag's result is bound
uniform sampler2D u_max_depth;    // farthest visible depth of the pixel (window depth)

void main() {
  vec2 c = gl_FragCoord.xy;
  // Window depth is linear in screen space over a triangle: these are its plane's slopes (taken
  // before any branch, so that the quad's derivatives are defined).
  vec2 depth_slopes = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
  SceneUvGradients footprint = scene_uv_gradients();  // the texture's, likewise
  uvec2 coverage;
  vec3 plane;  // depth at the centre, d/dx, d/dy in pixel space (y down)
  if (f_cov.exact == 1) {
    if (any(lessThan(c, f_cov.bounds.xy - 0.5)) || any(greaterThan(c, f_cov.bounds.zw + 0.5))) discard;
    // Pixel space relative to this pixel's centre: y down.
    vec2 a = vec2(f_cov.s01.x - c.x, c.y - f_cov.s01.y);
    vec2 b = vec2(f_cov.s01.z - c.x, c.y - f_cov.s01.w);
    vec2 d = vec2(f_cov.s2.x - c.x, c.y - f_cov.s2.y);
    coverage = rsaa_triangle_coverage(u_halfplane_lut, a, b, d) & u_full_mask;
    plane = vec3(dot(f_cov.depth_plane.xy, c) + f_cov.depth_plane.z, f_cov.depth_plane.x, -f_cov.depth_plane.y);
  } else {
    // Near-plane triangle, hardware rasterised: this fragment covers the centre; give it every
    // sample (no-AA behaviour) and the rasteriser's depth plane (flat, a floor reaching behind the
    // eye took the samples of whatever stands on it wherever it lies nearer at the centre).
    coverage = u_full_mask;
    plane = vec3(gl_FragCoord.z, depth_slopes.x, -depth_slopes.y);
  }
  if (coverage == uvec2(0u)) discard;
  // Behind everything the z-prepass saw in this pixel (the tolerance covers the difference
  // between the rasteriser's depth and our plane's).
  if (u_z_prepass && plane.x - 0.5 * (abs(plane.y) + abs(plane.z)) > texelFetch(u_max_depth, ivec2(c), 0).x + 1e-6)
    discard;
#ifdef COVERAGE_SHADING_INPUTS
  vec3 colour = scene_albedo(footprint);  // shaded once per surface by the resolve
#else
  vec3 colour = shade_scene_fragment(footprint).rgb;
#endif
  if (any(isnan(colour)) || any(isinf(colour)) || any(isnan(plane)) || any(isinf(plane))) discard;

  uint index = atomicAdd(coverage_records_used, 1u);
  if (index >= coverage_record_capacity) return;  // overflow: the host sees the count and redraws
  uint previous = imageAtomicExchange(u_heads, ivec2(c), index);
  CoverageRecord r;
  r.next = previous;
  r.order = scene_primitive_order();
  r.coverage = coverage;
  r.depth = plane;
  r.normal = encode_unit_vector(f_in.face_normal);
  r.colour = colour;
#ifdef COVERAGE_SHADING_INPUTS
  r.shading_normal = scene_shading_normal();
#endif
  coverage_store(index, r);
}
