// The scene's fragment inputs and their shading (shading.glsl), shared by every program that
// draws the scene: albedo = vertex colour times texture. Alpha carries the object's filter alpha
// (ssaa-filtered kernel 3); 1 unless a scene says so.
#ifndef RSAA_SCENE_SHADING_GLSL
#define RSAA_SCENE_SHADING_GLSL

#include "shading.glsl"

in FragmentData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
  flat vec3 face_normal;
  flat float normal_side;  // scene_normal_side.glsl
} f_in;

uniform sampler2D u_texture;
uniform bool u_has_texture;
uniform uint u_primitive_base;
uniform uint u_material;  // the draw's material (Scene::draws), for RSAA's material edges

// The interpolated shading normal, unit, on the side of the triangle the eye sees (two-sided
// shading, scene_normal_side.glsl); where a model's normals are broken, the face's, towards the eye.
vec3 scene_shading_normal() {
  vec3 n = normalize(f_in.view_normal);
  if (!all(equal(n, n)))  // NaN normals from a model: use the face
    return dot(f_in.face_normal, f_in.view_position) > 0.0 ? -f_in.face_normal : f_in.face_normal;
  return n * f_in.normal_side;
}

vec3 scene_albedo() {
  vec3 albedo = f_in.albedo;
  if (u_has_texture) albedo *= texture(u_texture, f_in.uv).rgb;
  return albedo;
}

vec4 shade_scene_fragment() {
  return vec4(shade_surface(scene_albedo(), scene_shading_normal(), f_in.view_position, SCENE_SPECULAR_EXPONENT,
                            SCENE_SPECULAR_SCALE),
              f_in.filter_alpha);
}

// The submission order of this fragment's primitive over the whole scene (draw base + id).
uint scene_primitive_order() { return u_primitive_base + uint(gl_PrimitiveID); }

#endif  // RSAA_SCENE_SHADING_GLSL
