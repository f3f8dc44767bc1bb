// The RSAA post-process in HLSL (Direct3D conventions), beside the HLSL tables: similarity codes
// -> mask -> offset from the table -> one bilinear fetch of the 1x colour. The same algorithm as
// rsaa_post.glsl and rsaa_common.glsl (which document each step); only the conventions differ.
//
//   float4 RsaaResolve(int2 pixel)         the entry point, for the engine's own pass
//   float4 RsaaPostPS(float4 position : SV_Position) : SV_Target   a full-screen pixel shader
//
// Include a table first (tables/P.hlsl: rsaa_sample_positions, rsaa_offsets, in pixel space with
// +y down, as SV_Position), then define and include:
//   RSAA_SAMPLE_COUNT      subsamples (must equal the table's RSAA_TABLE_SAMPLE_COUNT)
//   RSAA_AUTH              0 none, 1 post-pass authentication (2 is done in the pre-pass: 0 here)
//   RSAA_CODE_BITS         8, 16 or 32: bits of a stored similarity code
//   RSAA_SIMILARITY_DEPTH / RSAA_SIMILARITY_SADP_PLANE   (optional) as in rsaa_common.glsl
//   RSAA_SPLIT_CAP, RSAA_MULTI_SURFACE_NEIGHBOURS, RSAA_SPLIT_CHECK_NEIGHBOURS,
//   RSAA_FETCH_CHECK_NEIGHBOURS, RSAA_MATERIAL_EDGES  (optional) as in rsaa_post.glsl
// Resources (registers overridable by defining RSAA_REGISTER_*):
//   t0 colour (linear), t1 centre normal (uint2: rsaa_encode_normal, 0 = background), t2 centre
//   depth (0 near .. 1 far), t3.. the codes: subsample i in channel i % 4 of texture i / 4, as
//   rsaa_prepass.glsl writes them (up to four textures: t3-t6); with RSAA_MATERIAL_EDGES t7 the
//   centre primitive (uint2: the material in .y); s0 a linear clamp-to-edge sampler; b0 the constants below,
//   with rsaa_inverse_projection such that mul(rsaa_inverse_projection, ndc) is view space
//   (ndc.y up, ndc.z = depth).
#ifndef RSAA_POST_HLSL
#define RSAA_POST_HLSL

#ifndef RSAA_TABLE_SAMPLE_COUNT
#error "include a table (tables/P.hlsl) before rsaa_post.hlsl"
#endif
#if RSAA_TABLE_SAMPLE_COUNT != RSAA_SAMPLE_COUNT
#error "the table is for another sample count than RSAA_SAMPLE_COUNT"
#endif
#ifndef RSAA_AUTH
#define RSAA_AUTH 0
#endif
#ifndef RSAA_CODE_BITS
#define RSAA_CODE_BITS 8
#endif
#define RSAA_CODE_TEXTURES ((RSAA_SAMPLE_COUNT + 3) / 4)
#define RSAA_ALL_SIMILAR ((1u << RSAA_SAMPLE_COUNT) - 1u)

#ifndef RSAA_REGISTER_COLOUR
#define RSAA_REGISTER_COLOUR t0
#endif
#ifndef RSAA_REGISTER_NORMAL
#define RSAA_REGISTER_NORMAL t1
#endif
#ifndef RSAA_REGISTER_DEPTH
#define RSAA_REGISTER_DEPTH t2
#endif
#ifndef RSAA_REGISTER_CODES
#define RSAA_REGISTER_CODES t3
#endif
#ifndef RSAA_REGISTER_MATERIAL
#define RSAA_REGISTER_MATERIAL t7
#endif
#ifndef RSAA_REGISTER_SAMPLER
#define RSAA_REGISTER_SAMPLER s0
#endif
#ifndef RSAA_REGISTER_CONSTANTS
#define RSAA_REGISTER_CONSTANTS b0
#endif

Texture2D<float4> rsaa_colour : register(RSAA_REGISTER_COLOUR);
Texture2D<uint2> rsaa_centre_normal : register(RSAA_REGISTER_NORMAL);
Texture2D<float> rsaa_centre_depth : register(RSAA_REGISTER_DEPTH);
Texture2D<uint4> rsaa_codes[RSAA_CODE_TEXTURES] : register(RSAA_REGISTER_CODES);
#ifdef RSAA_MATERIAL_EDGES
Texture2D<uint2> rsaa_centre_primitive : register(RSAA_REGISTER_MATERIAL);
#endif
SamplerState rsaa_linear_clamp : register(RSAA_REGISTER_SAMPLER);

cbuffer RsaaConstants : register(RSAA_REGISTER_CONSTANTS) {
  float4x4 rsaa_inverse_projection;
  float2 rsaa_viewport;  // width, height in pixels
  float rsaa_threshold;  // SADP units, or percent of depth (RSAA_SIMILARITY_DEPTH)
};

// ---- normals, codes and similarity (rsaa_common.glsl)
static const float RSAA_NORMAL_SCALE = 16383.0;

float3 RsaaDecodeNormal(uint2 c) {
  float2 xy = float2(c) / RSAA_NORMAL_SCALE - 2.0;
  return float3(xy, sqrt(max(0.0, 1.0 - dot(xy, xy))));
}

bool RsaaIsSurface(uint2 encoded_normal) { return encoded_normal.x != 0u; }

float3 RsaaViewPosition(int2 pixel) {
  float2 uv = (float2(pixel) + 0.5) / rsaa_viewport;
  float4 ndc = float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, rsaa_centre_depth.Load(int3(pixel, 0)), 1.0);
  float4 view = mul(rsaa_inverse_projection, ndc);
  return view.xyz / view.w;
}

float RsaaSadp(float3 r12, float3 n1, float3 n2) {
  float largest = max(abs(r12.x), max(abs(r12.y), abs(r12.z)));
  if (!(largest > 1e-12)) return isnan(largest) ? largest : 0.0;
  float3 u = r12 / largest;
  return (abs(dot(n1, u)) + abs(dot(n2, u))) / length(u);
}

float RsaaDepthDifference(float3 p1, float3 p2) {
  float z1 = abs(p1.z), z2 = abs(p2.z);
  return 100.0 * abs(z1 - z2) / max(min(z1, z2), 1e-20);
}

float RsaaPlaneGap(float3 p1, float3 n1, float3 p2, float3 n2) {
  float d1 = length(p1), d2 = length(p2);
  if (!(d1 > 1e-30 && d2 > 1e-30)) return 0.0;
  float c1 = abs(dot(n1, p2)) / d2;
  float c2 = abs(dot(n2, p1)) / d1;
  if (!(max(c1, c2) >= 0.05)) return 0.0;
  float3 r = p2 - p1;
  return c1 >= c2 ? 100.0 * abs(dot(n1, r)) / (c1 * d2) : 100.0 * abs(dot(n2, r)) / (c2 * d1);
}

#ifndef RSAA_PLANE_GAP_PERCENT
#define RSAA_PLANE_GAP_PERCENT 1.0
#endif

float RsaaSimilarity(float3 p1, float3 n1, float3 p2, float3 n2) {
#if defined(RSAA_SIMILARITY_DEPTH)
  return RsaaDepthDifference(p1, p2);
#elif defined(RSAA_SIMILARITY_SADP_PLANE)
  float gap = RsaaPlaneGap(p1, n1, p2, n2) * (0.4 / RSAA_PLANE_GAP_PERCENT);
  return max(RsaaSadp(p1 - p2, n1, n2), min(gap, 2.0));
#else
  return RsaaSadp(p1 - p2, n1, n2);
#endif
}

#if RSAA_CODE_BITS == 32
static const float RSAA_CODE_SCALE = 1073741824.0;  // 2^30
static const uint RSAA_CODE_MAX = 0xffffffffu;
#else
static const float RSAA_CODE_SCALE = float(1u << (RSAA_CODE_BITS - 1));
static const uint RSAA_CODE_MAX = (1u << RSAA_CODE_BITS) - 1u;
#endif
#ifdef RSAA_MATERIAL_EDGES
static const uint RSAA_CODE_UNSEEN_MATERIAL = RSAA_CODE_MAX - 1u;
static const uint RSAA_CODE_GEOMETRY_MAX = RSAA_CODE_MAX - 2u;
#else
static const uint RSAA_CODE_GEOMETRY_MAX = RSAA_CODE_MAX - 1u;
#endif

// rsaa_common.glsl's rsaa_decode_similarity: the codes above geometry's (another surface than
// geometry can say) decode as the stored value 4 at every width.
float RsaaDecodeSimilarity(uint code, bool centre_is_surface) {
  if (code == 0u) return centre_is_surface ? 1.0e9 : 0.0;
  float stored = code > RSAA_CODE_GEOMETRY_MAX ? 4.0 : float(code - 1u) / RSAA_CODE_SCALE;
#ifdef RSAA_SIMILARITY_DEPTH
  return 0.05 * (exp2(8.0 * stored) - 1.0);
#else
  return stored;
#endif
}

// rsaa_post.glsl's rsaa_post_material and rsaa_centres_similarity: two materials compare as the
// largest code.
uint RsaaMaterial(int2 pixel) {
#ifdef RSAA_MATERIAL_EDGES
  return rsaa_centre_primitive.Load(int3(pixel, 0)).y;
#else
  return 0u;
#endif
}

float RsaaCentresSimilarity(uint a_material, float3 a_position, float3 a_normal, uint b_material, float3 b_position,
                            float3 b_normal) {
  if (a_material != b_material) return RsaaDecodeSimilarity(RSAA_CODE_MAX, true);
  return RsaaSimilarity(a_position, a_normal, b_position, b_normal);
}

// The step from a pixel to the outside pixel nearest a subsample (core's outside_pixel_towards):
// the position scaled to the unit square's border, rounded half away from zero.
int2 RsaaOutsideStep(float2 sample_position) {
  float scale = max(abs(sample_position.x), abs(sample_position.y));
  if (!(scale > 0.0)) return int2(1, 0);
  float2 s = sample_position / scale;
  return int2(sign(s) * floor(abs(s) + 0.5));
}

#if defined(RSAA_SPLIT_CHECK_NEIGHBOURS) || defined(RSAA_FETCH_CHECK_NEIGHBOURS) || \
    defined(RSAA_MULTI_SURFACE_NEIGHBOURS) || RSAA_AUTH == 1
#define RSAA_READS_OUTSIDE_PIXELS
// rsaa_post.glsl's RsaaOutside: the outside pixel nearest each subsample, read and compared with
// the centre once for every check.
struct RsaaOutside {
  uint centre_material;
  int2 pixel[RSAA_SAMPLE_COUNT];
  uint2 normal[RSAA_SAMPLE_COUNT];
  float3 position[RSAA_SAMPLE_COUNT];
  uint material[RSAA_SAMPLE_COUNT];
  float similarity[RSAA_SAMPLE_COUNT];  // RsaaCentresSimilarity(centre, outside pixel)
};

RsaaOutside RsaaOutsidePixels(int2 pixel, float3 position, float3 normal) {
  RsaaOutside o;
  uint material = RsaaMaterial(pixel);
  o.centre_material = material;
  [unroll] for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    o.pixel[i] = clamp(pixel + RsaaOutsideStep(rsaa_sample_positions[i]), int2(0, 0), int2(rsaa_viewport) - 1);
    o.normal[i] = rsaa_centre_normal.Load(int3(o.pixel[i], 0));
    o.position[i] = RsaaViewPosition(o.pixel[i]);
    o.material[i] = RsaaMaterial(o.pixel[i]);
    o.similarity[i] = RsaaCentresSimilarity(material, position, normal, o.material[i], o.position[i],
                                            RsaaDecodeNormal(o.normal[i]));
  }
  return o;
}
#endif

#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
// rsaa_post.glsl's rsaa_split_check for one subsample k of similarity s that the split calls
// similar: is it dissimilar after all?
bool RsaaSplitCheckDissimilar(uint2 centre_normal, int k, float s, RsaaOutside o) {
  if (!RsaaIsSurface(centre_normal) || !(s > rsaa_threshold) || !RsaaIsSurface(o.normal[k])) return false;
  float t = o.similarity[k];
  return t * 1.5 > s && t < s * 1.5;
}
#endif

#ifdef RSAA_FETCH_CHECK_NEIGHBOURS
// rsaa_post.glsl's rsaa_fetch_check: 0.5 when no dissimilar subsample finds a like surface in the
// outside pixel in its direction, else 1; with material edges a subsample on another material is
// matched exactly when its code says that pixel shows it (other_material.x, not .y), one on the
// centre's material never by a pixel of another material.
float RsaaFetchCheck(uint2 centre_normal, float similarity[RSAA_SAMPLE_COUNT], uint mask, uint2 other_material,
                     RsaaOutside o) {
  bool centre_is_surface = RsaaIsSurface(centre_normal);
  bool matched = false;
  [unroll] for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    if ((mask & (1u << i)) != 0u) continue;
    bool q_is_surface = RsaaIsSurface(o.normal[i]);
    float s = similarity[i], t = o.similarity[i];
    if (!centre_is_surface || s >= 1.0e9 || !q_is_surface)
      matched = matched || (centre_is_surface ? (s >= 1.0e9 && !q_is_surface) : q_is_surface);
#ifdef RSAA_MATERIAL_EDGES
    else if (((other_material.x | other_material.y) & (1u << i)) != 0u)
      matched = matched || (other_material.x & (1u << i)) != 0u;
    else if (o.material[i] != o.centre_material)
      continue;
#endif
    else
      matched = matched || (t * 3.0 > s && t < s * 3.0);
  }
  return matched ? 1.0 : 0.5;
}
#endif

#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
// rsaa_post.glsl's rsaa_centres_differ (the two centres' similarity given) and rsaa_multi_surface.
bool RsaaCentresDiffer(int2 pixel, uint2 normal, int2 other, uint2 other_normal, float similarity) {
  if (all(other == pixel)) return false;
  bool a = RsaaIsSurface(normal), b = RsaaIsSurface(other_normal);
  if (a != b) return true;
  if (!a) return false;
  return similarity > rsaa_threshold;
}

bool RsaaMultiSurface(int2 pixel, uint2 centre_normal, float4 colour, uint mask, RsaaOutside o, out float4 resolved) {
  resolved = colour;
  if (any(isnan(colour)) || any(isinf(colour))) return false;
  uint outside = 0u;
  int first = -1;
  [unroll] for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    bool differs = (mask & (1u << i)) == 0u &&
                   RsaaCentresDiffer(pixel, centre_normal, o.pixel[i], o.normal[i], o.similarity[i]);
    if (differs) outside |= 1u << i;
    if (differs && first < 0) first = i;
  }
  if (first < 0) return false;
  int2 first_pixel = o.pixel[first];
  uint2 first_normal = o.normal[first];
  float3 first_position = o.position[first], first_decoded = RsaaDecodeNormal(first_normal);
  bool three = false;
  [unroll] for (int j = 0; j < RSAA_SAMPLE_COUNT; ++j) {
    if ((outside & (1u << j)) == 0u || j == first) continue;
    float t = RsaaCentresSimilarity(o.material[first], first_position, first_decoded, o.material[j], o.position[j],
                                    RsaaDecodeNormal(o.normal[j]));
    three = three || RsaaCentresDiffer(first_pixel, first_normal, o.pixel[j], o.normal[j], t);
  }
  if (!three) return false;
  float3 sum = float3(0.0, 0.0, 0.0);
  [unroll] for (int k = 0; k < RSAA_SAMPLE_COUNT; ++k) {
    float3 c = colour.rgb;
    if ((outside & (1u << k)) != 0u) {
      float3 fetched = rsaa_colour.Load(int3(o.pixel[k], 0)).rgb;
      if (!any(isnan(fetched)) && !any(isinf(fetched))) c = fetched;
    }
    sum += c;
  }
  resolved = float4(sum / float(RSAA_SAMPLE_COUNT), colour.a);
  return true;
}
#endif

// ---- the post-process (rsaa_post.glsl)
float4 RsaaResolve(int2 pixel) {
  uint codes[RSAA_SAMPLE_COUNT];
  bool any_different = false, any_uncovered = false;
  uint2 other_material = uint2(0u, 0u);  // rsaa_pixel_mask's: another material shown outside, not shown
  [unroll] for (int i = 0; i < RSAA_SAMPLE_COUNT; ++i) {
    codes[i] = rsaa_codes[i / 4].Load(int3(pixel, 0))[i % 4];
    any_different = any_different || codes[i] > 1u;
    any_uncovered = any_uncovered || codes[i] == 0u;
#ifdef RSAA_MATERIAL_EDGES
    if (codes[i] == RSAA_CODE_MAX) other_material.x |= 1u << i;
    if (codes[i] == RSAA_CODE_UNSEEN_MATERIAL) other_material.y |= 1u << i;
#endif
  }
  float4 colour = rsaa_colour.Load(int3(pixel, 0));
  if (!any_different && !any_uncovered) return colour;
  uint2 centre_normal = rsaa_centre_normal.Load(int3(pixel, 0));
  bool centre_is_surface = RsaaIsSurface(centre_normal);
  if (!any_different && !centre_is_surface) return colour;

  // Classification (paper section 2.2): one k-means step.
  float similarity[RSAA_SAMPLE_COUNT];
  float maxsim = 0.0;
  [unroll] for (int j = 0; j < RSAA_SAMPLE_COUNT; ++j) {
    similarity[j] = RsaaDecodeSimilarity(codes[j], centre_is_surface);
    maxsim = max(maxsim, similarity[j]);
  }
  if (!(maxsim > rsaa_threshold)) return colour;
  float split = 0.5 * maxsim + 0.5 * rsaa_threshold;
#ifdef RSAA_SPLIT_CAP
  split = min(split, RSAA_SPLIT_CAP * rsaa_threshold);
#endif
#ifdef RSAA_READS_OUTSIDE_PIXELS
  RsaaOutside o = RsaaOutsidePixels(pixel, RsaaViewPosition(pixel), RsaaDecodeNormal(centre_normal));
#endif
  uint mask = 0u;
  int representative = 0;  // Listing 3: the dissimilar subsample farthest from the centre
  float farthest = -1.0;
  [unroll] for (int k = 0; k < RSAA_SAMPLE_COUNT; ++k) {
    float d = dot(rsaa_sample_positions[k], rsaa_sample_positions[k]);
    bool similar = similarity[k] <= split;
#ifdef RSAA_SPLIT_CHECK_NEIGHBOURS
    if (similar && RsaaSplitCheckDissimilar(centre_normal, k, similarity[k], o)) similar = false;
#endif
    if (similar) mask |= 1u << k;
    else if (d >= farthest) { representative = k; farthest = d; }
  }
  float2 offset = rsaa_offsets[mask];
#ifdef RSAA_FETCH_CHECK_NEIGHBOURS
  offset *= RsaaFetchCheck(centre_normal, similarity, mask, other_material, o);
#endif
#ifdef RSAA_MULTI_SURFACE_NEIGHBOURS
  // A mask the table leaves alone (offset 0, as every mask of an all-zero table) stays alone.
  float4 resolved;
  if (any(offset != float2(0.0, 0.0)) && RsaaMultiSurface(pixel, centre_normal, colour, mask, o, resolved))
    return resolved;
#endif
#if RSAA_AUTH == 1
  if (centre_is_surface && RsaaIsSurface(o.normal[representative])) {
    float to_outside = o.similarity[representative];
    if (to_outside - similarity[representative] > similarity[representative]) offset *= 0.5;
  }
#endif
  if (all(offset == float2(0.0, 0.0))) return colour;
  float4 fetched = rsaa_colour.SampleLevel(rsaa_linear_clamp, (float2(pixel) + 0.5 + offset) / rsaa_viewport, 0.0);
  return any(isnan(fetched)) || any(isinf(fetched)) ? colour : fetched;
}

float4 RsaaPostPS(float4 position : SV_Position) : SV_Target {
  return RsaaResolve(int2(position.xy));
}

#endif  // RSAA_POST_HLSL
