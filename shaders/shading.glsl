// The scene's shading function, shared by every program that shades (forward passes and the
// aggregate shading of agaa): a fixed directional light in view space, Lambert diffuse plus a
// Phong lobe, two-sided. Linear light. core/scene_shading.h is its CPU twin (the AGAA oracle).
#ifndef RSAA_SHADING_GLSL
#define RSAA_SHADING_GLSL

const float SCENE_SPECULAR_EXPONENT = 32.0;
const float SCENE_SPECULAR_SCALE = 0.25;

// diffuse_scale: AGAA's filtered Lambert term, |Na| for an aggregate whose unit normals average
// to Na (the mean of n.l is Na.l while no normal faces away from the light); 1 elsewhere.
vec3 shade_surface(vec3 albedo, vec3 n, vec3 view_position, float specular_exponent, float specular_scale,
                   float diffuse_scale) {
  vec3 to_eye = normalize(-view_position);
  if (dot(n, to_eye) < 0.0) n = -n;
  const vec3 light = normalize(vec3(-0.4, 0.7, 0.6));
  float diffuse = max(dot(n, light), 0.0);
  float specular = pow(max(dot(reflect(-light, n), to_eye), 0.0), specular_exponent);
  return albedo * (0.12 + 0.88 * diffuse_scale * diffuse) + specular_scale * specular;
}

vec3 shade_surface(vec3 albedo, vec3 n, vec3 view_position, float specular_exponent, float specular_scale) {
  return shade_surface(albedo, n, view_position, specular_exponent, specular_scale, 1.0);
}

#endif  // RSAA_SHADING_GLSL
