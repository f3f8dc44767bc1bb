// An FXAA-style luminance-edge post-process (after T. Lottes' FXAA 3.11 quality path, written
// here from its description): the baseline a user would otherwise pick. One colour sample per
// pixel, no geometry: find a local luma edge, walk along it to both ends, and move the fetch
// across the edge by how far the pixel is from the nearer end; also soften sub-pixel aliasing.
uniform sampler2D u_colour;  // linear RGBA16F, GL_LINEAR, clamp to edge
uniform vec2 u_viewport;
layout(location = 0) out vec4 o_colour;

const float kEdgeThreshold = 0.125;     // local contrast relative to the brightest neighbour
const float kEdgeThresholdMin = 0.0312; // ignore contrast below this (dark areas)
const float kSubpixel = 0.75;           // strength of the sub-pixel softening
const int kSearchSteps = 10;

// Luma of display values: edges are judged as seen.
float luma(vec3 linear_rgb) { return sqrt(dot(max(linear_rgb, vec3(0.0)), vec3(0.299, 0.587, 0.114))); }
float luma_at(vec2 p) { return luma(texture(u_colour, p / u_viewport).rgb); }
// The 3x3 neighbourhood at texel centres: unfiltered fetches, cheaper than filtered ones.
float luma_of(ivec2 pixel) {
  return luma(texelFetch(u_colour, clamp(pixel, ivec2(0), ivec2(u_viewport) - 1), 0).rgb);
}

void main() {
  vec2 pos = gl_FragCoord.xy;
  ivec2 pixel = ivec2(pos);
  vec4 centre = texelFetch(u_colour, pixel, 0);
  float m = luma(centre.rgb);
  float n = luma_of(pixel + ivec2(0, 1)), s = luma_of(pixel - ivec2(0, 1));
  float e = luma_of(pixel + ivec2(1, 0)), w = luma_of(pixel - ivec2(1, 0));
  float hi = max(max(max(n, s), max(e, w)), m), lo = min(min(min(n, s), min(e, w)), m);
  float contrast = hi - lo;
  if (contrast < max(kEdgeThresholdMin, hi * kEdgeThreshold) || any(isnan(centre)) || any(isinf(centre))) {
    o_colour = centre;
    return;
  }
  float ne = luma_of(pixel + ivec2(1, 1)), nw = luma_of(pixel + ivec2(-1, 1));
  float se = luma_of(pixel + ivec2(1, -1)), sw = luma_of(pixel + ivec2(-1, -1));
  // Sub-pixel aliasing: how far the centre stands out from its neighbourhood average.
  float average = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
  float subpixel = clamp(abs(average - m) / contrast, 0.0, 1.0);
  subpixel = smoothstep(0.0, 1.0, subpixel);
  subpixel = subpixel * subpixel * kSubpixel;
  // Edge orientation from second differences.
  float horizontal = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
  float vertical = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
  bool is_horizontal = horizontal >= vertical;  // the edge runs along x
  float l1 = is_horizontal ? s : w, l2 = is_horizontal ? n : e;
  float g1 = abs(l1 - m), g2 = abs(l2 - m);
  bool first_side = g1 >= g2;
  float gradient = 0.25 * max(g1, g2);
  vec2 across = is_horizontal ? vec2(0, 1) : vec2(1, 0);
  vec2 along = is_horizontal ? vec2(1, 0) : vec2(0, 1);
  float step_across = first_side ? -1.0 : 1.0;
  float edge_luma = 0.5 * (m + (first_side ? l1 : l2));
  vec2 on_edge = pos + across * (0.5 * step_across);
  // Walk both ways along the edge until the luma pair there no longer matches the edge.
  vec2 p1 = on_edge - along, p2 = on_edge + along;
  float d1 = luma_at(p1) - edge_luma, d2 = luma_at(p2) - edge_luma;
  bool done1 = abs(d1) >= gradient, done2 = abs(d2) >= gradient;
  for (int i = 1; i < kSearchSteps && !(done1 && done2); ++i) {
    float stride = i < 4 ? 1.0 : 2.0;
    if (!done1) { p1 -= along * stride; d1 = luma_at(p1) - edge_luma; done1 = abs(d1) >= gradient; }
    if (!done2) { p2 += along * stride; d2 = luma_at(p2) - edge_luma; done2 = abs(d2) >= gradient; }
  }
  float dist1 = is_horizontal ? pos.x - p1.x : pos.y - p1.y;
  float dist2 = is_horizontal ? p2.x - pos.x : p2.y - pos.y;
  bool nearer_is_1 = dist1 < dist2;
  float nearer = min(dist1, dist2);
  float length_edge = dist1 + dist2;
  // Only blend when the centre is on the side the nearer end bends towards.
  bool centre_below = m - edge_luma < 0.0;
  bool correct = ((nearer_is_1 ? d1 : d2) < 0.0) != centre_below;
  float edge_offset = correct ? 0.5 - nearer / max(length_edge, 1e-6) : 0.0;
  float offset = max(edge_offset, subpixel);
  vec4 fetched = texture(u_colour, (pos + across * (offset * step_across)) / u_viewport);
  o_colour = any(isnan(fetched)) || any(isinf(fetched)) ? centre : fetched;
}
