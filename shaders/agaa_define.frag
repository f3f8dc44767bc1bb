// AGAA aggregate definition (seed 001, Algorithm 1 with eq. 1), c = 1..4: the rules of
// core/reference/agaa.cpp define_aggregates(), the tests' oracle.
#include "rsaa_common.glsl"
#include "agaa_samples.glsl"

uniform vec2 u_sample_offsets[AGAA_MAX_SAMPLES];  // window space (+y up), from the pixel centre
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
uniform float u_k;            // AgaaSettings::k (scene units), used when u_k_per_depth is 0
uniform float u_k_per_depth;  // AgaaSettings::k_per_depth
float k;
uniform float u_min_separation;
uniform int u_aggregates;  // c, 1..4
out uvec2 o_meta;

vec3 position[AGAA_MAX_SAMPLES];
vec3 normal[AGAA_MAX_SAMPLES];
bool valid[AGAA_MAX_SAMPLES];

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
    o_meta = uvec2(0u);
    return;
  }
  mean_position /= float(count);
  k = u_k_per_depth > 0.0 ? u_k_per_depth * abs(mean_position.z) : u_k;
  float len = length(mean_normal);
  if (len > 1e-6) mean_normal /= len;
  // Seeds (define_aggregates() of core/reference/agaa.cpp): s0 the farthest from the mean, s1 the farthest
  // from s0, each further one the largest sum of squared distances to the seeds; only samples
  // farther than t from every seed qualify (else no further aggregate).
  int seeds[4];
  int count_seeds = 0;
  float best = 0.0;
  int s0 = -1;
  for (int s = 0; s < u_samples; ++s) {
    if (!valid[s]) continue;
    float d = distance_eq1(position[s], normal[s], mean_position, mean_normal);
    if (s0 < 0 || d > best) {
      s0 = s;
      best = d;
    }
  }
  seeds[count_seeds++] = s0;
  while (count_seeds < u_aggregates) {
    int candidate = -1;
    bool candidate_separated = false;
    for (int s = 0; s < u_samples; ++s) {
      if (!valid[s]) continue;
      bool separated = true;
      float score = 0.0;
      for (int a = 0; a < count_seeds; ++a) {
        float d = distance_eq1(position[s], normal[s], position[seeds[a]], normal[seeds[a]]);
        if (!(d > u_min_separation)) separated = false;
        score += count_seeds == 1 ? d : d * d;
      }
      if (!separated) score = -1.0;
      if (candidate < 0 || score > best) {
        candidate = s;
        best = score;
        candidate_separated = separated;
      }
    }
    if (!candidate_separated) break;
    seeds[count_seeds++] = candidate;
  }
  uvec2 meta = uvec2(0u, uint(count_seeds) << 24);
  for (int s = 0; s < u_samples; ++s) {
    if (!valid[s]) continue;
    meta.y |= 1u << uint(s);
    int nearest = 0;
    float nearest_d = distance_eq1(position[s], normal[s], position[seeds[0]], normal[seeds[0]]);
    for (int a = 1; a < count_seeds; ++a) {
      float d = distance_eq1(position[s], normal[s], position[seeds[a]], normal[seeds[a]]);
      if (d < nearest_d) {
        nearest = a;
        nearest_d = d;
      }
    }
    meta.x |= uint(nearest) << uint(2 * s);
  }
  o_meta = meta;
}
