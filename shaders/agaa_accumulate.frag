// AGAA aggregate G-buffer generation: the scene drawn again (with the conservative expansion of
// coverage_fragments.geom, so every pixel a triangle touches runs this once); each fragment adds
// its shading inputs, weighted by its visible samples in each aggregate / n, to that aggregate's
// targets by additive blending. Visible = the pre-pass saw this primitive at the sample (the
// paper's depth-EQUAL test, exact).
#include "agaa_samples.glsl"
#include "scene_shading.glsl"

uniform usampler2D u_meta;
layout(location = 0) out vec4 o_albedo0;    // albedo * w, w
layout(location = 1) out vec4 o_geometry0;  // shading normal * w, view z * w
layout(location = 2) out vec4 o_albedo1;
layout(location = 3) out vec4 o_geometry1;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint me = scene_primitive_order() + 1u;
  uint meta = texelFetch(u_meta, p, 0).x;
  vec2 w = vec2(0.0);
  for (int s = 0; s < u_samples; ++s)
    if (agaa_sample_primitive(p, s) == me) w[agaa_aggregate_of(meta, s)] += 1.0;
  if (w == vec2(0.0)) discard;
  w /= float(u_samples);
  vec3 n = scene_shading_normal();
  if (dot(n, -f_in.view_position) < 0.0) n = -n;  // average the sides that are seen
  vec3 albedo = scene_albedo();
  float z = f_in.view_position.z;
  o_albedo0 = vec4(albedo * w.x, w.x);
  o_geometry0 = vec4(n * w.x, z * w.x);
  o_albedo1 = vec4(albedo * w.y, w.y);
  o_geometry1 = vec4(n * w.y, z * w.y);
}
