// Coverage-based techniques, resolve: replays the pixel's fragment list in primitive order
// (what fragment-shader interlock gives the papers) through the technique's per-pixel update,
// then resolves. The rules are those of the CPU references, which the tests compare against:
//   COVERAGE_DCAA         core/reference/dcaa.cpp (Algorithm 1 merge/discard, per-sample depth resolve)
//                         with DCAA_MAX_SURFACES surfaces (default 4) and the DcaaSettings
//                         uniforms; dynamic coverage's surface rules are this with 2 surfaces
//                         over 16 samples (core/reference/dynamic_coverage.h)
//   COVERAGE_DYNCOV_SEED  core/reference/dynamic_coverage.cpp, the seed rules (two slots, evict the farther)
//
// Bounded work per invocation: llvmpipe ends every loop of a shader invocation once their
// iterations together reach 65535 (LP_MAX_TGSI_LOOP_ITERATIONS, shared by all loops and by the
// pixels shaded together), silently: a long list replayed in one invocation lost its fragments
// and came out as the background. So the first pass resolves the lists of up to SORT_SLOTS
// records, which it sorts locally; a longer list becomes a pending entry (its technique state,
// CoverageListTechnique::render) and the continuation passes (COVERAGE_CONTINUE, fullscreen
// too: long lists come in clusters, which then share SIMD lanes) resume it: each walks at most
// SCAN_PER_PASS records, keeping the SORT_SLOTS smallest primitive orders above the last one
// replayed in a max-heap; a finished walk replays them in order, and another walk starts while
// the pass has rounds left. Any length, bounded per pass.
//
// DCAA_SHADE_SURFACES (dcaa --shade surface, with COVERAGE_SHADING_INPUTS): a surface's colour
// slot holds its merged albedo and s_shading_normal its merged shading normal; the resolve shades
// each surface that shows a coverage sample once, at the view position of its depth plane at the
// pixel centre. A second merge, or a first merge whose shading normals differ beyond the cone,
// shades both surfaces first and merges colours (a zero shading normal marks a slot already
// shaded). DcaaPixel with a DcaaSurfaceShader is the oracle.
#include "coverage_record.glsl"
#ifdef DCAA_SHADE_SURFACES
#include "rsaa_common.glsl"
#include "shading.glsl"
uniform mat4 u_inverse_projection;
uniform vec2 u_viewport;
#endif

layout(r32ui) uniform readonly uimage2D u_heads;
uniform vec3 u_background;  // linear clear colour
out vec4 o_colour;

const int SORT_SLOTS = 32;  // lists up to this length are sorted locally; longer ones are pending
// A continuation pass runs at most ROUNDS_PER_PASS rounds, each a walk of at most SCAN_PER_PASS
// records (1 + log2(SORT_SLOTS) loop iterations a record) and, once a walk ends, the replay of
// SORT_SLOTS records (up to ~400 loop iterations each, in insert_fragment). The pixels shaded
// together share the limit and may be in different rounds: the bound is per round, about
// 2 x (6 x 1024 + 32 x 400) = 38000 of 65535.
const uint SCAN_PER_PASS = 1024u;
const int ROUNDS_PER_PASS = 2;

// Pending entries (long lists), PENDING_UINTS uints each (u_pending_index gives a pixel's
// entry + 1, 0 for none): 0 unused,
// 1 flags (1 started, 2 done), 2 last primitive order replayed, 3 cursor (next record to walk),
// 4 heap size, then the heap's record indices (their keys are the records' orders, read again on
// load), then the technique's state (save_state).
layout(std430, binding = 2) coherent buffer CoveragePendingCounter {
  uint pending_used;
  uint pending_capacity;
  uint pending_active;  // entries not done after a continuation pass
};
layout(std430, binding = 3) coherent buffer CoveragePending { uint coverage_pending[]; };
const uint PENDING_UINTS = 96u;  // CoverageListTechnique::kPendingUints
const uint PENDING_STATE = 5u + uint(SORT_SLOTS);

#ifdef COVERAGE_DCAA
uniform float u_cos_normal_threshold;
uniform bool u_per_sample_visibility;  // DcaaSettings::per_sample_visibility
uniform bool u_merge_hidden;           // DcaaSettings::merge_hidden
uniform bool u_merge_disjoint_only;    // DcaaSettings::merge_disjoint_only
uniform bool u_second_merge_into_all;  // DcaaSettings::second_merge_into_all
uniform bool u_second_merge_by_visible;  // DcaaSettings::second_merge_by_visible
uniform float u_merge_colour_tolerance;  // DcaaSettings::merge_colour_tolerance (0: no colour test)
uniform bool u_second_merge_least_change;  // DcaaSettings::second_merge_least_change
uniform int u_coverage_sample_count;
uniform vec2 u_coverage_samples[64];  // pixel space, y down
#ifndef DCAA_MAX_SURFACES
#define DCAA_MAX_SURFACES 4
#endif
const int MAX_SURFACES = DCAA_MAX_SURFACES;

uvec2 s_coverage[MAX_SURFACES + 1];
vec3 s_depth[MAX_SURFACES + 1];
vec3 s_normal[MAX_SURFACES + 1];
vec3 s_colour[MAX_SURFACES + 1];  // the albedo with DCAA_SHADE_SURFACES
#ifdef DCAA_SHADE_SURFACES
vec3 s_shading_normal[MAX_SURFACES + 1];
#endif
int s_count = 0;

int bits(uvec2 m) { return bitCount(m.x) + bitCount(m.y); }
float half_range(vec3 d) { return 0.5 * (abs(d.y) + abs(d.z)); }
bool overlaps(vec3 a, vec3 b) {
  return a.x - half_range(a) <= b.x + half_range(b) && b.x - half_range(b) <= a.x + half_range(a);
}
float overlap_amount(vec3 a, vec3 b) {
  return min(a.x + half_range(a), b.x + half_range(b)) - max(a.x - half_range(a), b.x - half_range(b));
}

#ifdef DCAA_SHADE_SURFACES
bool is_shaded(int i) { return s_shading_normal[i] == vec3(0.0); }
// The scene's shading of slot i's merged inputs at its depth plane's view position.
vec3 shade_slot(int i) {
  vec3 position = rsaa_view_position(gl_FragCoord.xy, s_depth[i].x, u_inverse_projection, u_viewport);
  return shade_surface(s_colour[i], s_shading_normal[i], position, SCENE_SPECULAR_EXPONENT, SCENE_SPECULAR_SCALE);
}
void make_shaded(int i) {
  if (is_shaded(i)) return;
  s_colour[i] = shade_slot(i);
  s_shading_normal[i] = vec3(0.0);
}
#else
void make_shaded(int i) {}
#endif

// merge_surfaces() of core/reference/dcaa.cpp, into slot i from slot j (both shaded or neither):
// the geometry (depth plane, facet normal) weighted by the samples each covers, what is seen
// (colour or albedo, shading normal) by sa : sb (both 0: equally).
void merge_into_weighted(int i, int j, float sa, float sb) {
  float wa = float(bits(s_coverage[i])), wb = float(bits(s_coverage[j]));
  float ka = wa + wb > 0.0 ? wa / (wa + wb) : 0.5, kb = 1.0 - ka;
  float ca = sa + sb > 0.0 ? sa / (sa + sb) : 0.5, cb = 1.0 - ca;
  vec3 n = ka * s_normal[i] + kb * s_normal[j];
  float len = length(n);
  s_normal[i] = len > 1e-6 ? n / len : (wa >= wb ? s_normal[i] : s_normal[j]);
#ifdef DCAA_SHADE_SURFACES
  vec3 m = ca * s_shading_normal[i] + cb * s_shading_normal[j];
  float m_len = length(m);
  s_shading_normal[i] = m_len > 1e-6 ? m / m_len : (sa >= sb ? s_shading_normal[i] : s_shading_normal[j]);
#endif
  s_coverage[i] |= s_coverage[j];
  s_depth[i] = ka * s_depth[i] + kb * s_depth[j];
  s_colour[i] = ca * s_colour[i] + cb * s_colour[j];
}
// Everything weighted by the samples each covers.
void merge_into(int i, int j) { merge_into_weighted(i, j, float(bits(s_coverage[i])), float(bits(s_coverage[j]))); }

// colour_difference() of core/reference/dcaa.cpp: the largest channel difference on a
// square-root scale.
float colour_difference(int i, int j) {
  vec3 d = abs(sqrt(max(s_colour[i], vec3(0.0))) - sqrt(max(s_colour[j], vec3(0.0))));
  return max(d.r, max(d.g, d.b));
}
// colours_differ() of core/reference/dcaa.cpp: slots both shaded compare colours, both unshaded
// their albedos (s_colour holds either).
bool colours_differ(int i, int j) {
  if (!(u_merge_colour_tolerance > 0.0)) return false;
#ifdef DCAA_SHADE_SURFACES
  if (is_shaded(i) != is_shaded(j)) return false;
#endif
  return colour_difference(i, j) > u_merge_colour_tolerance;
}

void copy_slot(int to, int from) {
  s_coverage[to] = s_coverage[from];
  s_depth[to] = s_depth[from];
  s_normal[to] = s_normal[from];
  s_colour[to] = s_colour[from];
#ifdef DCAA_SHADE_SURFACES
  s_shading_normal[to] = s_shading_normal[from];
#endif
}

bool covers(int i, int s) {
  return s < 32 ? ((s_coverage[i].x >> uint(s)) & 1u) != 0u : ((s_coverage[i].y >> uint(s - 32)) & 1u) != 0u;
}

// front_counts() of core/reference/dcaa.cpp over slots 0..n-1: per sample, the covering slot with the
// smallest depth at the sample (ties: the earlier slot).
void front_counts(int n, out int counts[MAX_SURFACES + 1]) {
  for (int i = 0; i < MAX_SURFACES + 1; ++i) counts[i] = 0;
  for (int s = 0; s < u_coverage_sample_count; ++s) {
    int front = -1;
    float front_depth = 0.0;
    vec2 p = u_coverage_samples[s];
    for (int i = 0; i < n; ++i) {
      if (!covers(i, s)) continue;
      float z = s_depth[i].x + s_depth[i].y * p.x + s_depth[i].z * p.y;
      if (front < 0 || z < front_depth) {
        front = i;
        front_depth = z;
      }
    }
    if (front >= 0) ++counts[front];
  }
}

void insert_fragment(CoverageRecord r) {
  // The fragment goes into the spare slot MAX_SURFACES (or s_count) first.
  int in_slot = s_count;
  s_coverage[in_slot] = r.coverage;
  s_depth[in_slot] = r.depth;
  s_normal[in_slot] = decode_unit_vector(r.normal);
  s_colour[in_slot] = r.colour;
#ifdef DCAA_SHADE_SURFACES
  s_shading_normal[in_slot] = r.shading_normal;
#endif
  int best = -1;
  float best_dot = 0.0, best_overlap = 0.0;
  for (int i = 0; i < s_count; ++i) {
    float d = dot(s_normal[i], s_normal[in_slot]);
    if (!(d > u_cos_normal_threshold) || !overlaps(s_depth[i], s_depth[in_slot])) continue;
    if (u_merge_disjoint_only && any(notEqual(s_coverage[i] & s_coverage[in_slot], uvec2(0u)))) continue;
    if (colours_differ(i, in_slot)) continue;
    float ov = overlap_amount(s_depth[i], s_depth[in_slot]);
    if (best < 0 || d > best_dot || (d == best_dot && ov > best_overlap)) {
      best = i;
      best_dot = d;
      best_overlap = ov;
    }
  }
  if (best >= 0) {
#ifdef DCAA_SHADE_SURFACES
    // A shaded slot has a zero shading normal: shaded or not alike, both are shaded first.
    if (!(dot(s_shading_normal[best], s_shading_normal[in_slot]) > u_cos_normal_threshold)) {
      make_shaded(best);
      make_shaded(in_slot);
    }
#endif
    merge_into(best, in_slot);
    return;
  }
  if (s_count < MAX_SURFACES) {
    ++s_count;
    return;
  }
  // Second merge attempt over the 4 surfaces and the fragment (slot 4): coarse depth resolve.
  const int n = MAX_SURFACES + 1;
  // Front to back by depth at the centre, ties in slot order (a stable sort, by rank).
  int front_to_back[n];
  for (int i = 0; i < n; ++i) {
    int rank = 0;
    for (int j = 0; j < n; ++j)
      if (s_depth[j].x < s_depth[i].x || (s_depth[j].x == s_depth[i].x && j < i)) ++rank;
    front_to_back[rank] = i;
  }
  int smallest = -1, smallest_visible = 0;
  int counts[MAX_SURFACES + 1];
  if (u_per_sample_visibility) {
    front_counts(n, counts);
    for (int k = n - 1; k >= 0; --k) {  // back to front: ties go to the farther
      int i = front_to_back[k];
      if (smallest < 0 || counts[i] < smallest_visible) {
        smallest = i;
        smallest_visible = counts[i];
      }
    }
  } else {  // the coarse depth resolve, the front-most excluded
    uvec2 closer = uvec2(0u);
    for (int k = 0; k < n; ++k) {
      int i = front_to_back[k];
      int visible = bits(s_coverage[i] & ~closer);
      closer |= s_coverage[i];
      if (k > 0 && (smallest < 0 || visible <= smallest_visible)) {
        smallest = i;
        smallest_visible = visible;
      }
    }
  }
  if (u_second_merge_least_change && u_per_sample_visibility) {
    // least_change() of core/reference/dcaa.cpp: the drop or merge that changes the colours of
    // the samples shown least (dropping the least visible costs its samples).
    int into = -1;
    float best_cost = float(smallest_visible), best_per = 1.0;  // a fraction, as on the CPU
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        if (!overlaps(s_depth[i], s_depth[j])) continue;
        float si = float(counts[i]), sj = float(counts[j]);
        float cost = 2.0 * si * sj * colour_difference(i, j), per = max(si + sj, 1.0);
        if (cost * best_per < best_cost * per) {
          smallest = j;
          into = i;
          best_cost = cost;
          best_per = per;
        }
      }
    if (into >= 0) {
      make_shaded(into);
      make_shaded(smallest);
      merge_into_weighted(into, smallest, float(counts[into]), float(counts[smallest]));
    }
    for (int i = smallest; i < n - 1; ++i) copy_slot(i, i + 1);
    return;
  }
  int target = -1;
  float target_overlap = 0.0;
  for (int i = 0; i < n && (u_merge_hidden || smallest_visible > 0); ++i) {
    if (i == smallest || !overlaps(s_depth[i], s_depth[smallest])) continue;
    float ov = overlap_amount(s_depth[i], s_depth[smallest]);
    if (u_second_merge_into_all) {
      make_shaded(smallest);
      make_shaded(i);
      merge_into(i, smallest);
      target = i;
    } else if (target < 0 || ov > target_overlap) {
      target = i;
      target_overlap = ov;
    }
  }
  if (target >= 0 && !u_second_merge_into_all) {
    make_shaded(target);
    make_shaded(smallest);
    if (u_second_merge_by_visible && u_per_sample_visibility)
      merge_into_weighted(target, smallest, float(counts[target]), float(counts[smallest]));
    else
      merge_into(target, smallest);
  }
  for (int i = smallest; i < n - 1; ++i) copy_slot(i, i + 1);  // remove it, keep the order
}

// A surface's state in a pending entry: coverage, depth plane, normal, colour (or albedo) and,
// shading surfaces, the shading normal, as exact floats (the replay goes on where it stopped).
#ifdef DCAA_SHADE_SURFACES
#define DCAA_SURFACE_UINTS 14
#else
#define DCAA_SURFACE_UINTS 11
#endif
const uint SURFACE_UINTS = uint(DCAA_SURFACE_UINTS);
#if 1 + DCAA_SURFACE_UINTS * DCAA_MAX_SURFACES + 5 + 32 > 96
#error "DCAA_MAX_SURFACES: too many surfaces for a pending entry"
#endif
void save_state(uint b) {
  coverage_pending[b] = uint(s_count);
  for (int i = 0; i < s_count; ++i) {
    uint o = b + 1u + SURFACE_UINTS * uint(i);
    coverage_pending[o + 0u] = s_coverage[i].x;
    coverage_pending[o + 1u] = s_coverage[i].y;
    for (int c = 0; c < 3; ++c) {
      coverage_pending[o + 2u + uint(c)] = floatBitsToUint(s_depth[i][c]);
      coverage_pending[o + 5u + uint(c)] = floatBitsToUint(s_normal[i][c]);
      coverage_pending[o + 8u + uint(c)] = floatBitsToUint(s_colour[i][c]);
#ifdef DCAA_SHADE_SURFACES
      coverage_pending[o + 11u + uint(c)] = floatBitsToUint(s_shading_normal[i][c]);
#endif
    }
  }
}
void load_state(uint b) {
  s_count = int(coverage_pending[b]);
  for (int i = 0; i < s_count; ++i) {
    uint o = b + 1u + SURFACE_UINTS * uint(i);
    s_coverage[i] = uvec2(coverage_pending[o + 0u], coverage_pending[o + 1u]);
    for (int c = 0; c < 3; ++c) {
      s_depth[i][c] = uintBitsToFloat(coverage_pending[o + 2u + uint(c)]);
      s_normal[i][c] = uintBitsToFloat(coverage_pending[o + 5u + uint(c)]);
      s_colour[i][c] = uintBitsToFloat(coverage_pending[o + 8u + uint(c)]);
#ifdef DCAA_SHADE_SURFACES
      s_shading_normal[i][c] = uintBitsToFloat(coverage_pending[o + 11u + uint(c)]);
#endif
    }
  }
}

// The surface's colour at the resolve: its fragments' merged colour, or shaded once.
vec3 surface_colour(int i) {
#ifdef DCAA_SHADE_SURFACES
  if (!is_shaded(i)) return shade_slot(i);
#endif
  return s_colour[i];
}

vec3 resolve_pixel() {
  int counts[MAX_SURFACES + 1];
  front_counts(s_count, counts);
  int covered = 0;
  float n = float(u_coverage_sample_count);
  vec3 c = vec3(0.0);
  for (int i = 0; i < s_count; ++i) {
    if (counts[i] == 0) continue;  // hidden: not shaded
    c += float(counts[i]) / n * surface_colour(i);
    covered += counts[i];
  }
  return c + float(u_coverage_sample_count - covered) / n * u_background;
}
#endif  // COVERAGE_DCAA

#ifdef COVERAGE_DYNCOV_SEED
vec3 slot_colour[2];
float slot_depth[2];
uint slot_mask[2];

// seed_closer() of core/reference/dynamic_coverage.h: closer beyond float rounding (2^-20).
bool closer(float a, float b) { return b - a > 9.5367431640625e-7; }

void insert_fragment(CoverageRecord r) {
  uint incoming = r.coverage.x & 0xffffu;
  float id = r.depth.x;
  if (incoming == 0u) return;
  if (!(closer(id, slot_depth[0]) || closer(id, slot_depth[1]))) return;
  int slot = closer(slot_depth[0], slot_depth[1]) ? 1 : 0;
  slot_colour[slot] = r.colour;
  slot_depth[slot] = id;
  slot_mask[slot] = incoming;
}

void save_state(uint b) {
  for (int i = 0; i < 2; ++i) {
    uint o = b + 5u * uint(i);
    for (int c = 0; c < 3; ++c) coverage_pending[o + uint(c)] = floatBitsToUint(slot_colour[i][c]);
    coverage_pending[o + 3u] = floatBitsToUint(slot_depth[i]);
    coverage_pending[o + 4u] = slot_mask[i];
  }
}
void load_state(uint b) {
  for (int i = 0; i < 2; ++i) {
    uint o = b + 5u * uint(i);
    for (int c = 0; c < 3; ++c) slot_colour[i][c] = uintBitsToFloat(coverage_pending[o + uint(c)]);
    slot_depth[i] = uintBitsToFloat(coverage_pending[o + 3u]);
    slot_mask[i] = coverage_pending[o + 4u];
  }
}

vec3 resolve_pixel() {
  int near = closer(slot_depth[0], slot_depth[1]) ? 0 : 1, far = 1 - near;
  float total = float(bitCount(slot_mask[0] | slot_mask[1]));
  if (total == 0.0) return slot_colour[near];
  return (float(bitCount(slot_mask[near])) * slot_colour[near] +
          float(bitCount(slot_mask[far] & ~slot_mask[near])) * slot_colour[far]) / total;
}
#endif  // COVERAGE_DYNCOV_SEED

// The continuation passes' selection: a max-heap of the SORT_SLOTS smallest keys offered.
uint h_keys[SORT_SLOTS], h_indices[SORT_SLOTS];
int h_size = 0;

// Puts (key, index) into the heap of `size` entries at `root`, moving larger children up.
void sift_down(int root, int size, uint key, uint index) {
  int i = root;
  for (;;) {  // at most log2(SORT_SLOTS) iterations
    int c = 2 * i + 1;
    if (c >= size) break;
    if (c + 1 < size && h_keys[c + 1] > h_keys[c]) ++c;
    if (h_keys[c] <= key) break;
    h_keys[i] = h_keys[c];
    h_indices[i] = h_indices[c];
    i = c;
  }
  h_keys[i] = key;
  h_indices[i] = index;
}

void heap_offer(uint key, uint index) {
  if (h_size < SORT_SLOTS) {
    int i = h_size++;
    while (i > 0 && h_keys[(i - 1) / 2] < key) {
      h_keys[i] = h_keys[(i - 1) / 2];
      h_indices[i] = h_indices[(i - 1) / 2];
      i = (i - 1) / 2;
    }
    h_keys[i] = key;
    h_indices[i] = index;
  } else if (key < h_keys[0]) {
    sift_down(0, SORT_SLOTS, key, index);
  }
}

// Sorts the heap ascending in place.
void heap_sort() {
  for (int end = h_size - 1; end > 0; --end) {
    uint key = h_keys[end], index = h_indices[end];
    h_keys[end] = h_keys[0];
    h_indices[end] = h_indices[0];
    sift_down(0, end, key, index);
  }
}

void init_state() {
#ifdef COVERAGE_DYNCOV_SEED
  slot_colour[0] = slot_colour[1] = u_background;
  slot_depth[0] = slot_depth[1] = 1.0;
  slot_mask[0] = slot_mask[1] = 0xffffu;
#endif
}

#ifdef COVERAGE_CONTINUE
layout(r32ui) uniform readonly uimage2D u_pending_index;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint entry = imageLoad(u_pending_index, pixel).x;
  if (entry == 0u) discard;
  uint b = (entry - 1u) * PENDING_UINTS;
  uint flags = coverage_pending[b + 1u];
  if ((flags & 2u) != 0u) discard;
  uint head = imageLoad(u_heads, pixel).x;
  uint capacity = coverage_record_capacity;
  uint last = coverage_pending[b + 2u], cursor = coverage_pending[b + 3u];
  bool started = (flags & 1u) != 0u;
  h_size = int(coverage_pending[b + 4u]);
  for (int k = 0; k < h_size; ++k) {
    h_indices[k] = coverage_pending[b + 5u + uint(k)];
    h_keys[k] = coverage_records[h_indices[k] * COVERAGE_RECORD_UINTS + 1u];
  }
  load_state(b + PENDING_STATE);
  bool done = false;
  for (int round = 0; round < ROUNDS_PER_PASS; ++round) {
    for (uint walked = 0u; walked < SCAN_PER_PASS && cursor != COVERAGE_LIST_END && cursor < capacity; ++walked) {
      uint key = coverage_records[cursor * COVERAGE_RECORD_UINTS + 1u];
      if (!started || key > last) heap_offer(key, cursor);
      cursor = coverage_records[cursor * COVERAGE_RECORD_UINTS];
    }
    if (cursor != COVERAGE_LIST_END && cursor < capacity) break;  // the walk goes on next pass
    // A whole walk: its heap holds the next records in primitive order.
    heap_sort();
    for (int k = 0; k < h_size; ++k) insert_fragment(coverage_load(h_indices[k]));
    if (h_size > 0) {
      last = h_keys[h_size - 1];
      started = true;
    }
    done = h_size < SORT_SLOTS;  // fewer than asked for: none are left
    h_size = 0;
    cursor = head;
    if (done) break;
  }
  if (done) {
    coverage_pending[b + 1u] = 2u;
    o_colour = vec4(resolve_pixel(), 1.0);
    return;
  }
  coverage_pending[b + 1u] = started ? 1u : 0u;
  coverage_pending[b + 2u] = last;
  coverage_pending[b + 3u] = cursor;
  coverage_pending[b + 4u] = uint(h_size);
  for (int k = 0; k < h_size; ++k) coverage_pending[b + 5u + uint(k)] = h_indices[k];
  save_state(b + PENDING_STATE);
  atomicAdd(pending_active, 1u);
  discard;
}

#else
layout(r32ui) uniform writeonly uimage2D u_pending_index;  // cleared to 0; entry + 1

void main() {
  init_state();
  uint head = imageLoad(u_heads, ivec2(gl_FragCoord.xy)).x;
  uint capacity = coverage_record_capacity;
  // Gather up to SORT_SLOTS records and sort them by primitive order.
  uint keys[SORT_SLOTS], indices[SORT_SLOTS];
  int n = 0;
  bool longer = false;
  for (uint i = head; i != COVERAGE_LIST_END && i < capacity; i = coverage_records[i * COVERAGE_RECORD_UINTS]) {
    if (n == SORT_SLOTS) {
      longer = true;
      break;
    }
    uint key = coverage_records[i * COVERAGE_RECORD_UINTS + 1u];
    int k = n++;
    for (; k > 0 && keys[k - 1] > key; --k) {
      keys[k] = keys[k - 1];
      indices[k] = indices[k - 1];
    }
    keys[k] = key;
    indices[k] = i;
  }
  if (longer) {
    // A long list: a pending entry for the continuation passes, which write this pixel (if the
    // entries overflow, the host grows them and draws this pass again).
    uint e = atomicAdd(pending_used, 1u);
    if (e < pending_capacity) {
      uint b = e * PENDING_UINTS;
      imageStore(u_pending_index, ivec2(gl_FragCoord.xy), uvec4(e + 1u));
      coverage_pending[b + 1u] = 0u;
      coverage_pending[b + 2u] = 0u;
      coverage_pending[b + 3u] = head;
      coverage_pending[b + 4u] = 0u;
      save_state(b + PENDING_STATE);
    }
    discard;
  }
  for (int k = 0; k < n; ++k) insert_fragment(coverage_load(indices[k]));
  o_colour = vec4(resolve_pixel(), 1.0);
}
#endif
