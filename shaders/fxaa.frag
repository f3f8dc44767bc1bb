// An FXAA-style luminance-edge post-process (after T. Lottes' FXAA 3.11 quality path, written
// here from its description): the baseline a user would otherwise pick. One colour sample per
// pixel, no geometry: find a local luma edge, walk along it to both ends, and move the fetch
// across the edge by how far the pixel is from the nearer end; also soften sub-pixel aliasing.
//
// Cost (llvmpipe, where every pixel of an 8-wide vector runs every instruction of both sides of
// a branch, and a loop's body at least once): the luma comes from the main pass (an R16F target,
// fxaa_luma.glsl), read four texels a gather, as FXAA 3.11 reads luma from alpha with gathers;
// the 3x3 neighbourhood is four gathers, the first step along the edge is in it, and the walk
// reads two steps a gather, one side an iteration (a loop costs every pixel at least one pass).
// The colour is read twice, by texelFetch: the pixel and its neighbour across the edge, blended
// as the bilinear fetch between them would.
//
// Behind an edge pass (fxaa_edges.frag): it runs only where the local contrast may change the
// pixel; the kept pixels are the colour image copied as it is.
#include "fxaa_edge.glsl"

uniform sampler2D u_colour;  // linear RGBA16F, clamp to edge
uniform sampler2D u_luma;    // fxaa_luma of u_colour, R16F, clamp to edge
uniform vec2 u_viewport;
layout(location = 0) out vec4 o_colour;

const float kSubpixel = 0.75;           // strength of the sub-pixel softening
const float kReach = 17.0;              // pixels walked each way at most

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 texel = 1.0 / u_viewport;
  vec2 corner = vec2(pixel) * texel;  // the pixel's lower left corner
  vec4 centre = texelFetch(u_colour, pixel, 0);
  // A gather at a corner returns its four texels as (i0, j1), (i1, j1), (i1, j0), (i0, j0).
  vec4 lower_left = textureGather(u_luma, corner, 0);                          // w, m, s, sw
  vec4 upper_right = textureGather(u_luma, corner + texel, 0);                 // n, ne, e, m
  float nw = textureGather(u_luma, corner + vec2(0.0, texel.y), 0).x;          // nw, n, m, w
  float se = textureGather(u_luma, corner + vec2(texel.x, 0.0), 0).z;          // m, e, se, s
  float m = lower_left.y, w = lower_left.x, s = lower_left.z, sw = lower_left.w;
  float n = upper_right.x, ne = upper_right.y, e = upper_right.z;
  // Low local contrast: the pixel is kept (offset 0 below; the edge pass leaves such pixels out,
  // but a pixel of a SIMD batch that has others to do still runs).
  bool keep;
  float contrast = fxaa_contrast(m, n, s, e, w, keep);
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
  bool first_side = g1 >= g2;  // the edge is towards l1
  float gradient = 0.25 * max(g1, g2);
  float edge_luma = 0.5 * (m + (first_side ? l1 : l2));
  ivec2 across = (is_horizontal ? ivec2(0, 1) : ivec2(1, 0)) * (first_side ? -1 : 1);
  // Walk both ways along the edge until the mean luma of the pixel pair straddling it (what a
  // bilinear fetch half way between them returns) no longer matches the edge. The first step
  // each way is in the neighbourhood.
  float pair1 = is_horizontal ? w + (first_side ? sw : nw) : s + (first_side ? sw : se);
  float pair2 = is_horizontal ? e + (first_side ? se : ne) : n + (first_side ? nw : ne);
  // (side 1, side 2): the luma difference at the end found, the distance walked, whether done.
  vec2 d = 0.5 * vec2(pair1, pair2) - edge_luma;
  vec2 dist = vec2(1.0);
  bvec2 done = bvec2(keep || abs(d.x) >= gradient, keep || abs(d.y) >= gradient);
  // Then a gather at the corner between the next two steps, on the edge line, holds both
  // steps' pairs; each iteration walks the side that has come less far, up to kReach pixels
  // (no counter: the loop ends when every pixel of the vector is done).
  vec2 edge_corner = (vec2(pixel) + vec2(max(across, ivec2(0)))) * texel;
  vec2 along = (is_horizontal ? vec2(1.0, 0.0) : vec2(0.0, 1.0)) * texel;
  while (!all(done)) {
    bool side1 = !done.x && (done.y || dist.x <= dist.y);
    float k = side1 ? dist.x : dist.y;  // the gather holds the steps k + 1 and k + 2
    vec4 g = textureGather(u_luma, edge_corner + along * (side1 ? -(k + 1.0) : k + 2.0), 0);
    // The two pairs' sums, at the lower and the upper coordinate along the edge.
    vec2 pairs = is_horizontal ? g.xy + g.wz : g.zx + g.wy;
    vec2 step_d = 0.5 * (side1 ? pairs.yx : pairs) - edge_luma;  // nearer step, farther step
    bool hit = abs(step_d.x) >= gradient;
    bool ended = hit || abs(step_d.y) >= gradient || k + 2.0 >= kReach;
    bvec2 which = bvec2(side1, !side1);
    d = mix(d, vec2(hit ? step_d.x : step_d.y), which);
    dist = mix(dist, vec2(k + (hit ? 1.0 : 2.0)), which);
    done = bvec2(done.x || (side1 && ended), done.y || (!side1 && ended));
  }
  float d1 = d.x, d2 = d.y, dist1 = dist.x, dist2 = dist.y;
  bool nearer_is_1 = dist1 < dist2;
  float nearer = min(dist1, dist2);
  float length_edge = dist1 + dist2;
  // Only blend when the centre is on the side the nearer end bends towards.
  bool centre_below = m - edge_luma < 0.0;
  bool correct = ((nearer_is_1 ? d1 : d2) < 0.0) != centre_below;
  float edge_offset = correct ? 0.5 - nearer / length_edge : 0.0;
  float offset = keep ? 0.0 : max(edge_offset, subpixel);
  vec4 beyond = texelFetch(u_colour, clamp(pixel + across, ivec2(0), ivec2(u_viewport) - 1), 0);
  vec4 blended = mix(centre, beyond, offset);
  // A NaN or infinite neighbour never spreads: the pixel keeps its own colour.
  o_colour = any(isnan(blended)) || any(isinf(blended)) ? centre : blended;
}
