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
  flat uint material;      // scene_facet_material.glsl
} f_in;

uniform sampler2D u_texture;
uniform bool u_has_texture;
uniform float u_texture_anisotropy = 1.0;  // Scene::texture_anisotropy, 1..16
uniform uint u_primitive_base;

// The interpolated shading normal, unit, on the side of the triangle the eye sees (two-sided
// shading, scene_normal_side.glsl); where a model's normals are broken, the face's, towards the eye.
vec3 scene_shading_normal() {
  vec3 n = normalize(f_in.view_normal);
  if (!all(equal(n, n)))  // NaN normals from a model: use the face
    return dot(f_in.face_normal, f_in.view_position) > 0.0 ? -f_in.face_normal : f_in.face_normal;
  return n * f_in.normal_side;
}

// The texture's footprint: the uv's screen-space derivatives. Implicit derivatives are undefined
// after a discard or in a branch some pixels of a quad skip: shaders that discard before shading
// take these at the top of main(), in uniform control flow, and pass them on.
struct SceneUvGradients {
  vec2 dx, dy;
};
SceneUvGradients scene_uv_gradients() { return SceneUvGradients(dFdx(f_in.uv), dFdy(f_in.uv)); }

// Anisotropic filtering in the shader (not the sampler's: Mesa llvmpipe's made the coverage
// techniques' fragment passes 55 times slower on a textured model, and the driver's filter differs
// between drivers): up to u_texture_anisotropy trilinear probes spread along the footprint's long
// axis, at the mip level of the long axis over the probe count, as GL's description of anisotropic
// filtering has it. One probe is trilinear filtering at the level GL describes for texture() (the
// longer axis; drivers approximate it: llvmpipe's texture() images differ from one probe's by
// 0.1 dB on a textured globe). A broken file's coordinates (not finite, or beyond float's
// fraction: the texture repeats) are looked up at their fraction, 0 if none, so no NaN reaches
// the image.
vec3 scene_texture(vec2 uv, SceneUvGradients footprint) {
  if (any(isnan(uv)) || any(isinf(uv))) uv = vec2(0.0);
  else if (any(greaterThanEqual(abs(uv), vec2(16777216.0)))) uv = fract(uv);
  vec2 size = vec2(textureSize(u_texture, 0));
  vec2 dx = footprint.dx * size, dy = footprint.dy * size;  // in texels of level 0
  // A footprint wider than any texture (edge-on triangles, broken coordinates; NaN too) takes
  // the coarsest level at the centre: probes spread that far would leave float's range.
  vec4 spans = vec4(dx, dy);
  if (any(isnan(spans)) || any(greaterThanEqual(abs(spans), vec4(65536.0))))  // isnan: compilers
    return textureLod(u_texture, uv, 1e3).rgb;  // may turn !(a < b) into a >= b, false for NaN
  float lx = length(dx), ly = length(dy);
  float longest = max(lx, ly), shortest = min(lx, ly);
  float probes = floor(clamp(ceil(longest / max(shortest, 1e-30)), 1.0, u_texture_anisotropy));
  float level = log2(max(longest / probes, 1e-30));
  vec2 axis = lx >= ly ? footprint.dx : footprint.dy;
  int count = int(probes);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < count; ++i) sum += textureLod(u_texture, uv + axis * ((float(i) + 0.5) / probes - 0.5), level).rgb;
  return sum / probes;
}

vec3 scene_albedo(SceneUvGradients footprint) {
  vec3 albedo = f_in.albedo;
  if (u_has_texture) albedo *= scene_texture(f_in.uv, footprint);
  return albedo;
}

// In uniform control flow only (see scene_uv_gradients()).
vec3 scene_albedo() { return scene_albedo(scene_uv_gradients()); }

vec4 shade_scene_fragment(SceneUvGradients footprint) {
  return vec4(shade_surface(scene_albedo(footprint), scene_shading_normal(), f_in.view_position, SCENE_SPECULAR_EXPONENT,
                            SCENE_SPECULAR_SCALE),
              f_in.filter_alpha);
}

// In uniform control flow only.
vec4 shade_scene_fragment() { return shade_scene_fragment(scene_uv_gradients()); }

// The submission order of this fragment's primitive over the whole scene (draw base + id).
uint scene_primitive_order() { return u_primitive_base + uint(gl_PrimitiveID); }

#endif  // RSAA_SCENE_SHADING_GLSL
