// One fragment of the per-pixel lists of the coverage-based techniques (DCAA, dynamic coverage):
// uints in a shader storage buffer, linked from an R32UI head image (0xffffffff ends a list):
//   next, primitive order, coverage (2 words; 1 with COVERAGE_NARROW, at most 32 samples),
//   depth at the centre (float), depth slopes (encode_slopes), facet normal (octahedral),
//   colour (3 halves in 2 words) | with COVERAGE_SHADING_INPUTS (dcaa --shade surface): albedo
//   (3 halves in 2 words) and shading normal (octahedral).
// 36 B for DCAA (40 B shading surfaces), 32 B for dynamic coverage. Colour and albedo keep half
// floats: in one word (11/11/10 or 10/10/10 bits of square roots) they cost 0.13 dB on the
// default scene and 0.9 dB on the edges and interpenetrating scenes against 64x SSAA, whose
// images lie within a fraction of an 8-bit step of the reference. The C++ side
// (runtime/coverage_lists.cpp, CoverageFragmentLists::record_bytes) reads the same layout back.
#ifndef RSAA_COVERAGE_RECORD_GLSL
#define RSAA_COVERAGE_RECORD_GLSL

#ifdef COVERAGE_NARROW
const uint RECORD_DEPTH = 3u;
#else
const uint RECORD_DEPTH = 4u;
#endif
#ifdef COVERAGE_SHADING_INPUTS
const uint COVERAGE_RECORD_UINTS = RECORD_DEPTH + 6u;
#else
const uint COVERAGE_RECORD_UINTS = RECORD_DEPTH + 5u;
#endif
const uint COVERAGE_LIST_END = 0xffffffffu;

layout(std430, binding = 0) coherent buffer CoverageCounter {
  uint coverage_records_used;
  uint coverage_record_capacity;
};
layout(std430, binding = 1) coherent buffer CoverageRecords { uint coverage_records[]; };

struct CoverageRecord {
  uint next;
  uint order;      // primitive submission order
  uvec2 coverage;  // bits 0-31, 32-63
  vec3 depth;      // window depth at the pixel centre, d/dx, d/dy (pixel space, y down)
  uint normal;     // octahedral, 2 x snorm16
  vec3 colour;     // linear; the albedo with COVERAGE_SHADING_INPUTS
#ifdef COVERAGE_SHADING_INPUTS
  vec3 shading_normal;
#endif
};

// Octahedral encoding of a unit vector in 2 x 16 bits.
uint encode_unit_vector(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return packSnorm2x16(e);
}

vec3 decode_unit_vector(uint code) {
  vec2 e = unpackSnorm2x16(code);
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return normalize(n);
}

// The depth plane's slopes (d/dx, d/dy) in 32 bits: two 12-bit signed mantissas in units of
// 2^(e - 11) with e the exponent of the larger slope (8 bits, biased by 128; 0: both zero). A
// sample's depth moves by at most 2^-12 of the larger slope, far below the depth differences the
// merge tests and the resolve compare; the centre depth stays a full float.
uint encode_slopes(vec2 s) {
  float m = max(abs(s.x), abs(s.y));
  if (!(m >= 1e-30)) return 0u;  // zero (or too small to matter at any depth)
  int e;
  frexp(m, e);  // m = f 2^e, f in [0.5, 1): |s| < 2^e
  ivec2 q = clamp(ivec2(round(ldexp(s, ivec2(11 - e)))), ivec2(-2047), ivec2(2047));
  return (uint(q.x) & 0xfffu) | (uint(q.y) & 0xfffu) << 12 | uint(clamp(e + 128, 1, 255)) << 24;
}
vec2 decode_slopes(uint code) {
  int e = int(code >> 24);
  if (e == 0) return vec2(0.0);
  ivec2 q = ivec2(bitfieldExtract(int(code), 0, 12), bitfieldExtract(int(code), 12, 12));
  return ldexp(vec2(q), ivec2(e - 128 - 11));
}

void coverage_store(uint i, CoverageRecord r) {
  uint b = i * COVERAGE_RECORD_UINTS;
  coverage_records[b + 0u] = r.next;
  coverage_records[b + 1u] = r.order;
  coverage_records[b + 2u] = r.coverage.x;
#ifndef COVERAGE_NARROW
  coverage_records[b + 3u] = r.coverage.y;
#endif
  b += RECORD_DEPTH;
  coverage_records[b + 0u] = floatBitsToUint(r.depth.x);
  coverage_records[b + 1u] = encode_slopes(r.depth.yz);
  coverage_records[b + 2u] = r.normal;
#ifdef COVERAGE_SHADING_INPUTS
  coverage_records[b + 3u] = packHalf2x16(r.colour.rg);
  coverage_records[b + 4u] = packHalf2x16(vec2(r.colour.b, 0.0));
  coverage_records[b + 5u] = encode_unit_vector(r.shading_normal);
#else
  coverage_records[b + 3u] = packHalf2x16(r.colour.rg);
  coverage_records[b + 4u] = packHalf2x16(vec2(r.colour.b, 0.0));
#endif
}

CoverageRecord coverage_load(uint i) {
  uint b = i * COVERAGE_RECORD_UINTS;
  CoverageRecord r;
  r.next = coverage_records[b + 0u];
  r.order = coverage_records[b + 1u];
#ifdef COVERAGE_NARROW
  r.coverage = uvec2(coverage_records[b + 2u], 0u);
#else
  r.coverage = uvec2(coverage_records[b + 2u], coverage_records[b + 3u]);
#endif
  b += RECORD_DEPTH;
  r.depth = vec3(uintBitsToFloat(coverage_records[b + 0u]), decode_slopes(coverage_records[b + 1u]));
  r.normal = coverage_records[b + 2u];
#ifdef COVERAGE_SHADING_INPUTS
  r.colour = vec3(unpackHalf2x16(coverage_records[b + 3u]), unpackHalf2x16(coverage_records[b + 4u]).x);
  r.shading_normal = decode_unit_vector(coverage_records[b + 5u]);
#else
  r.colour = vec3(unpackHalf2x16(coverage_records[b + 3u]), unpackHalf2x16(coverage_records[b + 4u]).x);
#endif
  return r;
}

#endif  // RSAA_COVERAGE_RECORD_GLSL
