// Scene vertices: view-space position for the similarity measures, clip position (optionally
// jittered by a sub-pixel translation in NDC), smooth normal, uv and albedo for shading.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_albedo;
layout(location = 4) in float a_filter_alpha;  // ssaa-filtered kernel 3: 1 sharp, 0 soft

uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_jitter_ndc;  // translation of the image, NDC units
uniform float u_depth_bias;  // NDC depth added: coplanar overlaps ordered by draw (runtime/coplanar_draws.h)

out VertexData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
} v_out;

void main() {
  vec4 view = u_view * vec4(a_position, 1.0);
  v_out.view_position = view.xyz;
  v_out.view_normal = mat3(u_view) * a_normal;
  v_out.uv = a_uv;
  v_out.albedo = a_albedo;
  v_out.filter_alpha = a_filter_alpha;
  vec4 clip = u_projection * view;
  if (u_depth_bias != 0.0) {
    if (view.z < 0.0) {
      // Moved along its view ray to the depth + u_depth_bias, so that the point the fragment
      // stages see lies on the surface the depth test sees (RSAA's pre-pass compares the two).
      float z = -u_projection[3][2] / (u_projection[2][2] + clip.z / clip.w + u_depth_bias);
      view.xyz *= z / view.z;
      v_out.view_position = view.xyz;
      clip = u_projection * view;
    } else {
      clip.z += u_depth_bias * clip.w;  // behind the eye: clipped anyway
    }
  }
  clip.xy += u_jitter_ndc * clip.w;
  gl_Position = clip;
}
