// AGAA deferred shading and resolve: each aggregate shaded once (mean albedo, normalised mean
// normal with Toksvig's widening of the specular lobe, the pixel ray at the mean depth), then
// composited by coverage over the background. core/reference/agaa.cpp agaa_resolve() is the oracle.
#include "rsaa_common.glsl"
#include "shading.glsl"

uniform sampler2D u_albedo[4], u_geometry[4];  // per aggregate (agaa_accumulate.frag's targets)
uniform int u_aggregates;
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
uniform vec3 u_background;
uniform bool u_filtered_diffuse;  // agaa_resolve()'s filtered_diffuse
out vec4 o_colour;

float toksvig_exponent(float normal_length, float exponent) {
  float l = clamp(normal_length, 0.0, 1.0);
  float denominator = l + exponent * (1.0 - l);
  return max(denominator > 0.0 ? l / denominator * exponent : 0.0, 1e-3);  // pow(0, 0) is undefined
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 ray = rsaa_view_position(gl_FragCoord.xy, 0.5, u_inverse_projection, u_viewport);
  vec3 colour = vec3(0.0);
  float covered = 0.0;
  for (int a = 0; a < u_aggregates; ++a) {
    vec4 albedo_w = texelFetch(u_albedo[a], p, 0), geometry_w = texelFetch(u_geometry[a], p, 0);
    float w = albedo_w.w;
    if (!(w > 1e-6) || isinf(w)) continue;
    vec3 albedo = albedo_w.rgb / w;
    vec3 mean = geometry_w.xyz / w;
    float len = length(mean);
    float z = geometry_w.w / w;
    vec3 position = vec3(ray.xy * (ray.z != 0.0 ? z / ray.z : 1.0), z);
    vec3 n = len > 1e-6 ? mean / len : normalize(-position);
    float s = toksvig_exponent(len, SCENE_SPECULAR_EXPONENT);
    float diffuse_scale = u_filtered_diffuse && len > 1e-6 ? min(len, 1.0) : 1.0;
    colour += w * shade_surface(albedo, n, position, s, SCENE_SPECULAR_SCALE * (1.0 + s) / (1.0 + SCENE_SPECULAR_EXPONENT),
                                diffuse_scale);
    covered += w;
  }
  o_colour = vec4(colour + clamp(1.0 - covered, 0.0, 1.0) * u_background, 1.0);
}
