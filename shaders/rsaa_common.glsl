// rsaa shared GLSL: normal compression, the SADP and depth similarity measures, similarity
// codes, and the mask -> offset lookup. Every technique that classifies subsamples includes this
// one file (SMAA-style: configure with defines, then include).
//
// Defines expected before inclusion:
//   RSAA_SAMPLE_COUNT      subsamples per pixel (must equal the table's)
//   RSAA_SIMILARITY_DEPTH  (optional) compare depths instead of SADP
//   RSAA_CODE_BITS         8, 16 or 32: bits of a stored similarity code
//   RSAA_DEPTH_ZERO_TO_ONE (optional) depth buffers follow glClipControl GL_ZERO_TO_ONE
// Conventions: OpenGL window space (+y up); bit i of a mask = subsample i similar to the centre.

#ifndef RSAA_COMMON_GLSL
#define RSAA_COMMON_GLSL

// ---- normals, 2 x 16 bits (the paper's EncodeNormal/DecodeNormal). The sign of z is folded
// into x, y: SADP only uses |dot(n, r)|. (0, 0) is reserved for "no surface" (background).
const float RSAA_NORMAL_SCALE = float((1 << 14) - 1);

uvec2 rsaa_encode_normal(vec3 n) {
  vec2 xy = (n.z < 0.0 ? -n.xy : n.xy);
  return uvec2(floor((xy + 2.0) * RSAA_NORMAL_SCALE));
}

vec3 rsaa_decode_normal(uvec2 c) {
  vec2 xy = vec2(c) / RSAA_NORMAL_SCALE - 2.0;
  return vec3(xy, sqrt(max(0.0, 1.0 - dot(xy, xy))));
}

bool rsaa_is_surface(uvec2 encoded_normal) { return encoded_normal.x != 0u; }

// View-space position of the surface seen at window position `window_xy` with depth-buffer
// value `depth` (the paper's ScreenToWorld, in view space: SADP does not depend on the frame).
// RSAA_DEPTH_ZERO_TO_ONE: glClipControl's GL_ZERO_TO_ONE (NDC z = depth), else OpenGL's default.
vec3 rsaa_view_position(vec2 window_xy, float depth, mat4 inverse_projection, vec2 viewport) {
#ifdef RSAA_DEPTH_ZERO_TO_ONE
  vec4 ndc = vec4(window_xy / viewport * 2.0 - 1.0, depth, 1.0);
#else
  vec4 ndc = vec4(window_xy / viewport * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
#endif
  vec4 view = inverse_projection * ndc;
  return view.xyz / view.w;
}

// ---- similarity measures (0 = same surface; larger = more different)

// SADP (paper eq. 1): |n1 . r| + |n2 . r| over |r|, r from one point to the other. r is first
// scaled by its largest component so that neither tiny nor huge distances under- or overflow.
// Points closer than 1e-12 (any unit) are the same point: 0. Normals are expected to be unit
// vectors; SADP scales with their lengths. A NaN input gives NaN (encoded as "similar").
float rsaa_sadp(vec3 r12, vec3 n1, vec3 n2) {
  float largest = max(abs(r12.x), max(abs(r12.y), abs(r12.z)));
  if (!(largest > 1e-12)) return isnan(largest) ? largest : 0.0;
  vec3 u = r12 / largest;
  return (abs(dot(n1, u)) + abs(dot(n2, u))) / length(u);
}

// Depth alternative: relative view-space depth difference, in percent of the nearer depth.
float rsaa_depth_difference(vec3 p1, vec3 p2) {
  float z1 = abs(p1.z), z2 = abs(p2.z);
  return 100.0 * abs(z1 - z2) / max(min(z1, z2), 1e-20);
}

// Gap between the two surfaces along the view ray, in percent of the depth: the distance from
// one point to the other's plane, measured along that point's view ray (camera at the view-space
// origin: a perspective projection), divided by its distance from the camera. The plane used is
// the one the ray meets least obliquely; when both are nearly edge-on (|n . ray| < 0.05) the gap
// is unknown and 0 is returned. Unlike SADP it does not vanish when both surfaces are seen at a
// grazing angle (a silhouette over a floor), and unlike the raw depth difference it is 0 for two
// points of one plane however steeply that plane recedes.
float rsaa_plane_gap(vec3 p1, vec3 n1, vec3 p2, vec3 n2) {
  float d1 = length(p1), d2 = length(p2);
  if (!(d1 > 1e-30 && d2 > 1e-30)) return 0.0;
  float c1 = abs(dot(n1, p2)) / d2;  // plane 1 seen along the ray through p2
  float c2 = abs(dot(n2, p1)) / d1;
  if (!(max(c1, c2) >= 0.05)) return 0.0;
  vec3 r = p2 - p1;
  return c1 >= c2 ? 100.0 * abs(dot(n1, r)) / (c1 * d2) : 100.0 * abs(dot(n2, r)) / (c2 * d1);
}

// Plane gap (percent) that counts as a different surface with RSAA_SIMILARITY_SADP_PLANE.
#ifndef RSAA_PLANE_GAP_PERCENT
#define RSAA_PLANE_GAP_PERCENT 1.0
#endif

float rsaa_similarity(vec3 p1, vec3 n1, vec3 p2, vec3 n2) {
#if defined(RSAA_SIMILARITY_DEPTH)
  return rsaa_depth_difference(p1, p2);
#elif defined(RSAA_SIMILARITY_SADP_PLANE)
  // SADP or the plane gap, whichever says "more different", in SADP units: a gap of
  // RSAA_PLANE_GAP_PERCENT maps to the paper's threshold 0.4; capped at SADP's maximum, 2.
  float gap = rsaa_plane_gap(p1, n1, p2, n2) * (0.4 / RSAA_PLANE_GAP_PERCENT);
  return max(rsaa_sadp(p1 - p2, n1, n2), min(gap, 2.0));
#else
  return rsaa_sadp(p1 - p2, n1, n2);
#endif
}

// ---- similarity codes: 0 = no surface at the subsample, 1 + round-down(value * scale) else,
// saturating below the codes kept for another surface than any geometric measure can say (the
// paper's dbits compression). The largest code, RSAA_CODE_MAX, is a surface over a background
// centre or another material than the centre's that the outside pixel in the subsample's
// direction shows; with material edges the one below it, RSAA_CODE_UNSEEN_MATERIAL, another
// material that this outside pixel does not show (the post-process's fetch check then knows the
// fetch cannot bring it in). Both decode as the stored value 4 at every width: saturated geometry
// (1.97 at 8 and 16 bits) and another material must not tie, or the k-means split weighs
// "another facet" like a merely large geometric difference.
#ifndef RSAA_CODE_BITS
#define RSAA_CODE_BITS 8
#endif
#if RSAA_CODE_BITS == 32
const float RSAA_CODE_SCALE = float(1u << 30);
const uint RSAA_CODE_MAX = 0xffffffffu;
#else
const float RSAA_CODE_SCALE = float(1u << (RSAA_CODE_BITS - 1));
const uint RSAA_CODE_MAX = (1u << RSAA_CODE_BITS) - 1u;
#endif
#ifdef RSAA_MATERIAL_EDGES
const uint RSAA_CODE_UNSEEN_MATERIAL = RSAA_CODE_MAX - 1u;
const uint RSAA_CODE_GEOMETRY_MAX = RSAA_CODE_MAX - 2u;  // the largest geometric code
#else
const uint RSAA_CODE_GEOMETRY_MAX = RSAA_CODE_MAX - 1u;
#endif

// The code textures of RSAA_SAMPLE_COUNT subsamples, four a texel, and their format as images.
#define RSAA_CODE_TEXTURES ((RSAA_SAMPLE_COUNT + 3) / 4)
#if RSAA_CODE_BITS == 8
#define RSAA_CODE_IMAGE_FORMAT rgba8ui
#elif RSAA_CODE_BITS == 16
#define RSAA_CODE_IMAGE_FORMAT rgba16ui
#else
#define RSAA_CODE_IMAGE_FORMAT rgba32ui
#endif

// What a code stores. SADP lies in [0, 2] and is stored as it is. Depth differences are percent
// of depth and unbounded: stored linearly they would saturate at 2% (8 and 16 bits), every larger
// difference would tie and the k-means split would degenerate into a fixed cut. They are stored
// as log2(1 + v / 0.05%) / 8 instead: about 4% relative resolution at 8 bits near the 0.4%
// threshold, distinct codes up to about 3000%.
#ifdef RSAA_SIMILARITY_DEPTH
float rsaa_code_value(float similarity) { return log2(1.0 + similarity / 0.05) / 8.0; }
float rsaa_similarity_of_code_value(float stored) { return 0.05 * (exp2(8.0 * stored) - 1.0); }
#else
float rsaa_code_value(float similarity) { return similarity; }
float rsaa_similarity_of_code_value(float stored) { return stored; }
#endif

// A NaN similarity (broken normals or positions) encodes as "same surface": the pixel is left
// alone rather than resampled from a guess.
uint rsaa_encode_similarity(float value) {
  if (isnan(value)) return 1u;
  float scaled = rsaa_code_value(clamp(value, 0.0, 4.0e9)) * RSAA_CODE_SCALE;
  return scaled >= float(RSAA_CODE_GEOMETRY_MAX - 1u) ? RSAA_CODE_GEOMETRY_MAX : uint(scaled) + 1u;
}

// A subsample with no surface compares as equal to a background centre and as maximally
// different from a surface centre.
float rsaa_decode_similarity(uint code, bool centre_is_surface) {
  if (code == 0u) return centre_is_surface ? 1.0e9 : 0.0;
  if (code > RSAA_CODE_GEOMETRY_MAX) return rsaa_similarity_of_code_value(4.0);
  return rsaa_similarity_of_code_value(float(code - 1u) / RSAA_CODE_SCALE);
}

#ifdef RSAA_SAMPLE_COUNT
// What rsaa_classify() makes of a pixel's codes, told without decoding each subsample or
// splitting (a decoded similarity grows with its code, so the largest similarity is the largest
// code's, or a code 0's: 1e9 beside a surface centre, 0 beside the background):
// RSAA_CODES_ALL_SIMILAR, RSAA_CODES_EDGE, or RSAA_CODES_EDGE_IF_CENTRE_IS_SURFACE (a code 0
// decides), so that a caller reads the centre's normal only then. Where the split's rounding makes
// a mask all-similar although the largest similarity is above the threshold this says edge: the
// resolve then keeps the colour all the same. The post-process's edge test
// (rsaa_pixel_has_edge()) and the record passes, which list the edge pixels as they make the codes.
#define RSAA_CODES_ALL_SIMILAR 0
#define RSAA_CODES_EDGE 1
#define RSAA_CODES_EDGE_IF_CENTRE_IS_SURFACE 2
int rsaa_codes_edge(uint codes[RSAA_SAMPLE_COUNT], float threshold) {
  uint largest = 0u, smallest = 0xffffffffu;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) largest = max(largest, codes[i]), smallest = min(smallest, codes[i]);
  // A code >= 1 decodes alike whatever the centre shows.
  if (largest > 1u && rsaa_decode_similarity(largest, true) > threshold) return RSAA_CODES_EDGE;
  if (smallest != 0u) return RSAA_CODES_ALL_SIMILAR;
  if (rsaa_decode_similarity(0u, false) > threshold) return RSAA_CODES_EDGE;
  return rsaa_decode_similarity(0u, true) > threshold ? RSAA_CODES_EDGE_IF_CENTRE_IS_SURFACE : RSAA_CODES_ALL_SIMILAR;
}

// ---- classification (paper section 2.2): one k-means step. Returns the similarity mask, or
// the all-similar mask when no subsample exceeds the threshold.
uint rsaa_classify(float similarity[RSAA_SAMPLE_COUNT], float threshold, out float split) {
  float maxsim = 0.0;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) maxsim = max(maxsim, similarity[i]);
  uint all = (1u << RSAA_SAMPLE_COUNT) - 1u;
  split = maxsim;
  if (!(maxsim > threshold)) return all;
  split = 0.5 * maxsim + 0.5 * threshold;
#ifdef RSAA_SPLIT_CAP
  // Capped split (ours, RsaaSettings::split_cap): a subsample more than RSAA_SPLIT_CAP x the
  // threshold away from the centre's surface is dissimilar however far the farthest one is, so a
  // third surface between the centre's and a very different one (the background, 1e9) is not
  // counted as the centre's. RSAA_SPLIT_CAP >= 1.
  split = min(split, RSAA_SPLIT_CAP * threshold);
#endif
  uint mask = 0u;
  for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i)
    if (similarity[i] <= split) mask |= 1u << i;
  return mask;
}
#endif  // RSAA_SAMPLE_COUNT

// ---- coverage masks of triangles from the half-plane LUT (DCAA, dynamic coverage). The table
// is built by core/reference/halfplane_lut.cpp, which documents the parametrisation: an edge is n.p = d
// with n the unit normal towards the covered side, p in pixel space (centre (0, 0), y down).
// The LUT texture is RG32UI: x = distance bin, y = angle bin; .x bits 0-31, .y bits 32-63.
const float RSAA_TWO_PI = 6.283185307179586;
const float RSAA_PIXEL_RADIUS = 0.7071067811865476;

uvec2 rsaa_half_plane_mask(usampler2D lut, vec2 n, float d) {
  if (isnan(d) || any(isnan(n))) return uvec2(0u);
  if (d <= -RSAA_PIXEL_RADIUS) return uvec2(0xffffffffu);
  if (d >= RSAA_PIXEL_RADIUS) return uvec2(0u);
  ivec2 bins = textureSize(lut, 0);
  float turns = atan(n.y, n.x) / RSAA_TWO_PI;
  turns -= floor(turns);
  int a = int(floor(turns * float(bins.y) + 0.5)) % bins.y;
  int k = min(bins.x - 1, int((d + RSAA_PIXEL_RADIUS) / (2.0 * RSAA_PIXEL_RADIUS) * float(bins.x)));
  return texelFetch(lut, ivec2(k, a), 0).xy;
}

// Samples inside the triangle a, b, c (pixel space relative to the pixel centre): the AND of its
// edges' inner half-planes; 0 for a degenerate triangle.
uvec2 rsaa_triangle_coverage(usampler2D lut, vec2 a, vec2 b, vec2 c) {
  vec2 ab = b - a, ac = c - a;
  float area2 = ab.x * ac.y - ab.y * ac.x;
  if (!(area2 != 0.0)) return uvec2(0u);
  float o = area2 > 0.0 ? 1.0 : -1.0;
  vec2 p[3] = vec2[3](a, b, c);
  uvec2 mask = uvec2(0xffffffffu);
  for (int i = 0; i < 3; ++i) {
    vec2 e = p[(i + 1) % 3] - p[i];
    vec2 n = o * vec2(-e.y, e.x) / length(e);
    mask &= rsaa_half_plane_mask(lut, n, dot(n, p[i]));
  }
  return mask;
}

#endif  // RSAA_COMMON_GLSL
