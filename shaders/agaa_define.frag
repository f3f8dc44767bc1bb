// AGAA aggregate definition (seed 001, Algorithm 1 with eq. 1), c = 2: the rules of
// core/agaa.cpp define_aggregates(), the tests' oracle.
#include "rsaa_common.glsl"
#include "agaa_samples.glsl"

uniform vec2 u_sample_offsets[8];  // window space (+y up), from the pixel centre
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
uniform float u_k;            // AgaaSettings::k (scene units), used when u_k_per_depth is 0
uniform float u_k_per_depth;  // AgaaSettings::k_per_depth
float k;
uniform float u_min_separation;
out uint o_meta;

vec3 position[8];
vec3 normal[8];
bool valid[8];

float distance_eq1(vec3 pa, vec3 na, vec3 pb, vec3 nb) {
  vec3 d = (pa - pb) / k;
  float bend = 1.0 - dot(na, nb);
  return dot(d, d) + bend * bend;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 mean_position = vec3(0.0), mean_normal = vec3(0.0);
  int count = 0;
  for (int s = 0; s < u_samples; ++s) {
    valid[s] = agaa_sample_primitive(p, s) != 0u;
    if (!valid[s]) continue;
    position[s] = rsaa_view_position(gl_FragCoord.xy + u_sample_offsets[s], agaa_sample_depth(p, s),
                                     u_inverse_projection, u_viewport);
    normal[s] = rsaa_decode_normal(agaa_sample_normal(p, s));
    mean_position += position[s];
    mean_normal += normal[s];
    ++count;
  }
  if (count == 0) {
    o_meta = 0u;
    return;
  }
  mean_position /= float(count);
  k = u_k_per_depth > 0.0 ? u_k_per_depth * abs(mean_position.z) : u_k;
  float len = length(mean_normal);
  if (len > 1e-6) mean_normal /= len;
  int s0 = -1, s1 = -1;
  float best = 0.0;
  for (int s = 0; s < u_samples; ++s) {
    if (!valid[s]) continue;
    float d = distance_eq1(position[s], normal[s], mean_position, mean_normal);
    if (s0 < 0 || d > best) {
      s0 = s;
      best = d;
    }
  }
  for (int s = 0; s < u_samples; ++s) {
    if (!valid[s]) continue;
    float d = distance_eq1(position[s], normal[s], position[s0], normal[s0]);
    if (s1 < 0 || d > best) {
      s1 = s;
      best = d;
    }
  }
  bool two = distance_eq1(position[s1], normal[s1], position[s0], normal[s0]) > u_min_separation;
  uint meta = two ? 2u << 16 : 1u << 16;
  for (int s = 0; s < u_samples; ++s) {
    if (!valid[s]) continue;
    meta |= 1u << uint(s);
    if (two && distance_eq1(position[s], normal[s], position[s1], normal[s1]) <
                   distance_eq1(position[s], normal[s], position[s0], normal[s0]))
      meta |= 1u << uint(8 + s);
  }
  o_meta = meta;
}
