// AGAA aggregate G-buffer generation: the scene drawn again (with the conservative expansion of
// coverage_fragments.geom, so every pixel a triangle touches runs this once); each fragment adds
// its shading inputs, weighted by its visible samples in each aggregate / n, to that aggregate's
// targets by additive blending. Visible = the pre-pass saw this primitive at the sample (the
// paper's depth-EQUAL test, exact).
#include "agaa_samples.glsl"
#include "scene_shading.glsl"

uniform usampler2D u_meta;
// Per aggregate a: target 2a = albedo * w, w; target 2a + 1 = shading normal * w, view z * w.
// Only the first 2c are attached.
layout(location = 0) out vec4 o_targets[8];

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  SceneUvGradients footprint = scene_uv_gradients();  // before the discard below
  uint me = scene_primitive_order() + 1u;
  uvec2 meta = texelFetch(u_meta, p, 0).xy;
  vec4 w = vec4(0.0);
  for (int s = 0; s < u_samples; ++s)
    if (agaa_sample_primitive(p, s) == me) w[agaa_aggregate_of(meta, s)] += 1.0;
  if (w == vec4(0.0)) discard;
  w /= float(u_samples);
  vec3 n = scene_shading_normal();  // on the side of its triangle that is seen
  vec3 albedo = scene_albedo(footprint);
  float z = f_in.view_position.z;
  for (int a = 0; a < 4; ++a) {
    o_targets[2 * a] = vec4(albedo * w[a], w[a]);
    o_targets[2 * a + 1] = vec4(n * w[a], z * w[a]);
  }
}
