// The scene's shading at one point, shared by every program that draws the scene: a fixed
// directional light in view space, albedo (vertex colour times texture), two-sided. Linear light.
// Alpha carries the object's filter alpha (ssaa-filtered kernel 3); 1 unless a scene says so.
#ifndef RSAA_SCENE_SHADING_GLSL
#define RSAA_SCENE_SHADING_GLSL

in FragmentData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
  flat vec3 face_normal;
} f_in;

uniform sampler2D u_texture;
uniform bool u_has_texture;
uniform uint u_primitive_base;

vec4 shade_scene_fragment() {
  vec3 n = normalize(f_in.view_normal);
  if (!all(equal(n, n))) n = f_in.face_normal;  // NaN normals from a model: use the face
  vec3 to_eye = normalize(-f_in.view_position);
  if (dot(n, to_eye) < 0.0) n = -n;
  const vec3 light = normalize(vec3(-0.4, 0.7, 0.6));
  float diffuse = max(dot(n, light), 0.0);
  float specular = pow(max(dot(reflect(-light, n), to_eye), 0.0), 32.0);
  vec3 albedo = f_in.albedo;
  if (u_has_texture) albedo *= texture(u_texture, f_in.uv).rgb;
  return vec4(albedo * (0.12 + 0.88 * diffuse) + 0.25 * specular, f_in.filter_alpha);
}

// The submission order of this fragment's primitive over the whole scene (draw base + id).
uint scene_primitive_order() { return u_primitive_base + uint(gl_PrimitiveID); }

#endif  // RSAA_SCENE_SHADING_GLSL
