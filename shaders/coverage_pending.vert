// Coverage-based techniques, the resolve's continuation passes (coverage_resolve.frag with
// COVERAGE_CONTINUE): one point per pending entry, at the centre of its pixel.
layout(std430, binding = 3) coherent buffer CoveragePending { uint coverage_pending[]; };
const uint PENDING_UINTS = 128u;  // as coverage_resolve.frag
uniform vec2 u_viewport;
flat out uint v_entry;

void main() {
  v_entry = uint(gl_VertexID);
  uint p = coverage_pending[v_entry * PENDING_UINTS];
  vec2 centre = vec2(float(p & 0xffffu), float(p >> 16)) + 0.5;
  gl_Position = vec4(centre / u_viewport * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
