// The runtime's own RSAA pre-pass fragment shader (after scene.vert and scene.geom, which gives
// the exact face normal): the engine-facing functions of rsaa_prepass.glsl, called as an engine
// would. Jittered: drawn once per subsample, writing codes; RSAA_PREPASS_MSAA: once (twice for a
// union pattern), shaded once per pixel, writing surface records; RSAA_PREPASS_RECORDS: once per
// subsample, writing surface records.
#include "rsaa_prepass.glsl"

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

uniform uint u_primitive_base;  // first primitive id of this draw in the centre primitive target

layout(location = 0) out uvec4 o_code;

void main() {
  uint primitive = u_primitive_base + uint(gl_PrimitiveID) + 1u;
#ifdef RSAA_MATERIAL_EDGES
  o_code = rsaa_prepass_code(f_in.view_position, f_in.face_normal, primitive, f_in.material);
#else
  o_code = rsaa_prepass_code(f_in.view_position, f_in.face_normal, primitive);
#endif
}
