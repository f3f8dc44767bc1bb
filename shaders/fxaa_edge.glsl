// FXAA's local-contrast test, shared by its edge pass (fxaa_edges.frag) and fxaa.frag so that
// both decide alike: a pixel whose luma cross (the centre m and its neighbours n, s, e, w)
// spans too little contrast keeps its colour.
const float kEdgeThreshold = 0.125;     // local contrast relative to the brightest neighbour
const float kEdgeThresholdMin = 0.0312; // ignore contrast below this (dark areas)

// The cross's contrast (largest - smallest luma); `keep`: too low for FXAA to change the pixel.
float fxaa_contrast(float m, float n, float s, float e, float w, out bool keep) {
  float hi = max(max(max(n, s), max(e, w)), m), lo = min(min(min(n, s), min(e, w)), m);
  float contrast = hi - lo;
  keep = contrast < max(kEdgeThresholdMin, hi * kEdgeThreshold);
  return contrast;
}
