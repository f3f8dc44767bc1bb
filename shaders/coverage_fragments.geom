// Coverage-based techniques (DCAA, dynamic coverage), geometry stage: emulated conservative
// rasterisation (llvmpipe has none) and the triangle data the fragment stage needs to compute
// its exact coverage mask from the half-plane LUT.
//
// Each edge is pushed out by the pixel's half-extent along its normal (0.5 (|nx| + |ny|)), so
// that every pixel the triangle touches gets a fragment (Hasselgren et al., GPU Gems 2 ch. 42).
// The moved vertices are placed on the triangle's own plane in clip space, with attributes
// extrapolated perspective-correctly, so interpolation inside the triangle is unchanged.
// Triangles that reach behind the eye (w <= 0) are drawn as they are and flagged: the fragment
// stage then gives a fragment covering the pixel centre every sample (no-AA behaviour at the near
// plane) and the rasteriser's depth plane.
#include "scene_facet_material.glsl"
#include "scene_normal_side.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

uniform vec2 u_viewport;

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

out CoverageTriangle {
  flat vec4 s01;          // window positions of vertices 0 and 1
  flat vec2 s2;           // of vertex 2
  flat vec3 depth_plane;  // window depth = x * s.x + y * s.y + z
  flat vec4 bounds;       // window-space bounding box (min x, min y, max x, max y)
  flat int exact;         // 0: behind-the-eye triangle, centre coverage only
} g_cov;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

void main() {
  vec3 e1 = v_in[1].view_position - v_in[0].view_position;
  vec3 e2 = v_in[2].view_position - v_in[0].view_position;
  vec3 face = cross(e1, e2);
  float len = length(face);
  face = len > 0.0 ? face / len : vec3(0.0, 0.0, 1.0);
  if (dot(face, -v_in[0].view_position) < 0.0) face = -face;  // facing the viewer
  float side = scene_normal_side(face, v_in[0].view_normal + v_in[1].view_normal + v_in[2].view_normal,
                                 v_in[0].view_position);

  vec4 clip[3] = vec4[3](gl_in[0].gl_Position, gl_in[1].gl_Position, gl_in[2].gl_Position);
  bool in_front = clip[0].w > 1e-6 && clip[1].w > 1e-6 && clip[2].w > 1e-6;
  vec2 s[3];
  float z[3];
  for (int i = 0; i < 3; ++i) {
    s[i] = (clip[i].xy / clip[i].w * 0.5 + 0.5) * u_viewport;
    z[i] = clip[i].z / clip[i].w * 0.5 + 0.5;
  }
  float area2 = cross2(s[1] - s[0], s[2] - s[0]);
  bool exact = in_front && abs(area2) > 1e-12 && !isnan(area2) && !isinf(area2);
  if (in_front && !exact) return;  // zero area on screen: covers no sample

  vec4 out_clip[3] = clip;
  vec3 mu[3] = vec3[3](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
  g_cov.depth_plane = vec3(0.0);
  if (exact) {
    // Window depth is affine in window space: solve z = A x + B y + C from the vertices.
    vec2 ab = s[1] - s[0], ac = s[2] - s[0];
    float dz1 = z[1] - z[0], dz2 = z[2] - z[0];
    float A = (dz1 * ac.y - dz2 * ab.y) / area2;
    float B = (ab.x * dz2 - ac.x * dz1) / area2;
    g_cov.depth_plane = vec3(A, B, z[0] - A * s[0].x - B * s[0].y);

    float o = area2 > 0.0 ? 1.0 : -1.0;
    vec2 n[3];
    float d[3];
    for (int i = 0; i < 3; ++i) {  // edge i: s[i] -> s[i+1], inner normal n, inner side n.p > d
      vec2 e = s[(i + 1) % 3] - s[i];
      n[i] = o * vec2(-e.y, e.x) / length(e);
      d[i] = dot(n[i], s[i]) - 0.5 * (abs(n[i].x) + abs(n[i].y)) - 1e-3;
    }
    for (int i = 0; i < 3; ++i) {  // vertex i: meeting point of the moved edges i-1 and i
      vec2 na = n[(i + 2) % 3], nb = n[i];
      float det = cross2(na, nb);
      vec2 p = vec2(d[(i + 2) % 3] * nb.y - d[i] * na.y, na.x * d[i] - nb.x * d[(i + 2) % 3]) / det;
      // Screen-space barycentrics of p, then clip-space weights on the triangle's plane.
      float l1 = cross2(p - s[0], s[2] - s[0]) / area2;
      float l2 = cross2(s[1] - s[0], p - s[0]) / area2;
      vec3 l = vec3(1.0 - l1 - l2, l1, l2);
      vec3 lw = l / vec3(clip[0].w, clip[1].w, clip[2].w);
      float inv_w = lw.x + lw.y + lw.z;
      if (!(inv_w > 0.0) || isinf(inv_w) || abs(det) < 1e-6) continue;  // keep the original vertex
      mu[i] = lw / inv_w;
      out_clip[i] = mu[i].x * clip[0] + mu[i].y * clip[1] + mu[i].z * clip[2];
    }
  }
  g_cov.s01 = vec4(s[0], s[1]);
  g_cov.s2 = s[2];
  g_cov.bounds = vec4(min(s[0], min(s[1], s[2])), max(s[0], max(s[1], s[2])));
  g_cov.exact = exact ? 1 : 0;
  for (int i = 0; i < 3; ++i) {
    vec3 m = mu[i];
    gl_Position = out_clip[i];
    gl_PrimitiveID = gl_PrimitiveIDIn;
    g_out.view_position = m.x * v_in[0].view_position + m.y * v_in[1].view_position + m.z * v_in[2].view_position;
    g_out.view_normal = m.x * v_in[0].view_normal + m.y * v_in[1].view_normal + m.z * v_in[2].view_normal;
    g_out.uv = m.x * v_in[0].uv + m.y * v_in[1].uv + m.z * v_in[2].uv;
    g_out.albedo = m.x * v_in[0].albedo + m.y * v_in[1].albedo + m.z * v_in[2].albedo;
    g_out.filter_alpha = m.x * v_in[0].filter_alpha + m.y * v_in[1].filter_alpha + m.z * v_in[2].filter_alpha;
    g_out.face_normal = face;
    g_out.normal_side = side;
    g_out.material = u_material;
    EmitVertex();
  }
  EndPrimitive();
}
