// The runtime's own RSAA pre-pass fragment shader (after scene.vert and scene.geom, which gives
// the exact face normal): the engine-facing functions of rsaa_prepass.glsl, called as an engine
// would. Jittered: drawn once per subsample; RSAA_PREPASS_MSAA: once (twice for a union
// pattern), run per sample.
#include "rsaa_prepass.glsl"

in FragmentData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
  flat vec3 face_normal;
} f_in;

uniform uint u_primitive_base;  // first primitive id of this draw in the centre primitive target

layout(location = 0) out uvec4 o_code;

void main() {
  o_code = rsaa_prepass_code(f_in.view_position, f_in.face_normal, u_primitive_base + uint(gl_PrimitiveID) + 1u);
}
