// The paper's preGS: the geometric normal of each triangle, computed here so that no
// application data is needed; passes the primitive id on for the fully-covered shortcut.
#include "scene_facet_material.glsl"
#include "scene_normal_side.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
} v_in[];

out FragmentData {
  vec3 view_position;
  vec3 view_normal;
  vec2 uv;
  vec3 albedo;
  float filter_alpha;
  flat vec3 face_normal;
  flat float normal_side;  // scene_normal_side.glsl
  flat uint material;      // scene_facet_material.glsl
} g_out;

void main() {
  vec3 e1 = v_in[1].view_position - v_in[0].view_position;
  vec3 e2 = v_in[2].view_position - v_in[0].view_position;
  vec3 n = cross(e1, e2);
  float len = length(n);
  // A degenerate triangle has no plane; it covers no pixel, give it any unit normal.
  vec3 face = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
  float side = scene_normal_side(face, v_in[0].view_normal + v_in[1].view_normal + v_in[2].view_normal,
                                 v_in[0].view_position);
  uint material = scene_facet_material();
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    gl_PrimitiveID = gl_PrimitiveIDIn;
    g_out.view_position = v_in[i].view_position;
    g_out.view_normal = v_in[i].view_normal;
    g_out.uv = v_in[i].uv;
    g_out.albedo = v_in[i].albedo;
    g_out.filter_alpha = v_in[i].filter_alpha;
    g_out.face_normal = face;
    g_out.normal_side = side;
    g_out.material = material;
    EmitVertex();
  }
  EndPrimitive();
}
