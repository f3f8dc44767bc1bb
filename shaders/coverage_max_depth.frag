// DCAA's z-prepass (its section 4.2), the approximate form the paper names: the farthest of the
// pixel's 4 hardware MSAA depths. A fragment whose nearest depth over the pixel is behind it is
// behind every visible surface at those 4 samples and is not stored (not exact at the coverage
// samples between them: background may leak along cracks, the paper's Fig. 10(d)).
uniform sampler2DMS u_depth;
out float o_max_depth;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float m = 0.0;
  for (int s = 0; s < 4; ++s) m = max(m, texelFetch(u_depth, p, s).x);
  o_max_depth = m;
}
