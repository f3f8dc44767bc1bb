// The scene's shading function, shared by every program that shades (forward passes and the
// aggregate shading of agaa): a fixed directional light in view space and optional point lights,
// Lambert diffuse plus a Phong lobe, two-sided (the normal given on the side the eye sees).
// Linear light. core/reference/scene_shading.h is its CPU twin (the AGAA oracle).
#ifndef RSAA_SHADING_GLSL
#define RSAA_SHADING_GLSL

const float SCENE_SPECULAR_EXPONENT = 32.0;
const float SCENE_SPECULAR_SCALE = 0.25;

// Point lights in view space beside the fixed light (rsaa bench --lights N: N - 1 of them), the
// shading-cost axis. GpuScene binds the block (count 0 unless the scene has point lights), so
// every program that shades sees the same lights, including the fullscreen AGAA resolve.
const int SCENE_MAX_POINT_LIGHTS = 64;
layout(std140, binding = 4) uniform ScenePointLights {
  int count;
  vec4 position_radius[SCENE_MAX_POINT_LIGHTS];  // view-space position, falloff radius
  vec4 colour[SCENE_MAX_POINT_LIGHTS];
} u_point_lights;

// diffuse_scale: AGAA's filtered Lambert term, |Na| for an aggregate whose unit normals average
// to Na (the mean of n.l is Na.l while no normal faces away from the light); 1 elsewhere.
vec3 shade_surface(vec3 albedo, vec3 n, vec3 view_position, float specular_exponent, float specular_scale,
                   float diffuse_scale) {
  // n is on the seen side already (scene_shading_normal(), or the mean of such normals).
  vec3 to_eye = normalize(-view_position);
  const vec3 light = normalize(vec3(-0.4, 0.7, 0.6));
  float diffuse = max(dot(n, light), 0.0);
  float specular = pow(max(dot(reflect(-light, n), to_eye), 0.0), specular_exponent);
  vec3 colour = albedo * (0.12 + 0.88 * diffuse_scale * diffuse) + specular_scale * specular;
  for (int i = 0; i < min(u_point_lights.count, SCENE_MAX_POINT_LIGHTS); ++i) {
    vec3 to_light = u_point_lights.position_radius[i].xyz - view_position;
    float r = u_point_lights.position_radius[i].w;
    float falloff = 1.0 / (1.0 + dot(to_light, to_light) / (r * r));
    vec3 l = normalize(to_light);
    float d = diffuse_scale * max(dot(n, l), 0.0);
    float s = pow(max(dot(reflect(-l, n), to_eye), 0.0), specular_exponent);
    colour += u_point_lights.colour[i].rgb * falloff * (albedo * d + specular_scale * s);
  }
  return colour;
}

vec3 shade_surface(vec3 albedo, vec3 n, vec3 view_position, float specular_exponent, float specular_scale) {
  return shade_surface(albedo, n, view_position, specular_exponent, specular_scale, 1.0);
}

#endif  // RSAA_SHADING_GLSL
