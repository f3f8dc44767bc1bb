#include "runtime/coplanar_draws.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include <glm/glm.hpp>

namespace rsaa {
namespace {

using Vec = glm::dvec3;

struct Plane {
  Vec normal;  // unit, its largest component positive
  double offset = 0.0;
  int dropped_axis = 0;  // the normal's largest component: the triangle is projected along it
};

bool plane_of(const std::array<Vec, 3>& p, Plane* plane) {
  Vec n = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double length = glm::length(n);
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  n /= length;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  if (n[axis] < 0.0) n = -n;
  *plane = {n, glm::dot(n, p[0]), axis};
  return true;
}

// Separating-axis test of two coplanar triangles projected along `axis`: they overlap when every
// edge normal sees their intervals share more than `tolerance` (so touching is not overlapping).
bool overlap(const std::array<Vec, 3>& a, const std::array<Vec, 3>& b, int axis, double tolerance) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::array<glm::dvec2, 3> pa, pb;
  for (int k = 0; k < 3; ++k) pa[k] = {a[k][u], a[k][v]}, pb[k] = {b[k][u], b[k][v]};
  for (const auto* tri : {&pa, &pb}) {
    for (int e = 0; e < 3; ++e) {
      const glm::dvec2 edge = (*tri)[(e + 1) % 3] - (*tri)[e];
      const double length = glm::length(edge);
      if (!(length > 0.0)) continue;
      const glm::dvec2 normal{-edge.y / length, edge.x / length};
      double lo_a = 1e300, hi_a = -1e300, lo_b = 1e300, hi_b = -1e300;
      for (int k = 0; k < 3; ++k) {
        lo_a = std::min(lo_a, glm::dot(normal, pa[k])), hi_a = std::max(hi_a, glm::dot(normal, pa[k]));
        lo_b = std::min(lo_b, glm::dot(normal, pb[k])), hi_b = std::max(hi_b, glm::dot(normal, pb[k]));
      }
      if (std::min(hi_a, hi_b) - std::max(lo_a, lo_b) <= tolerance) return false;
    }
  }
  return true;
}

struct CellKey {
  std::array<std::int64_t, 4> q;
  bool operator==(const CellKey& o) const { return q == o.q; }
};
struct CellHash {
  std::size_t operator()(const CellKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::int64_t x : k.q) h = (h ^ std::uint64_t(x)) * 0xff51afd7ed558ccdull, h ^= h >> 32;
    return std::size_t(h);
  }
};

}  // namespace

CoplanarRanks draw_depth_ranks(const Scene& scene, std::uint64_t max_pair_tests) {
  CoplanarRanks out;
  out.rank.assign(scene.draws.size(), 0u);
  if (scene.draws.size() < 2) return out;
  const glm::vec3 lo = scene.bounds_min(), hi = scene.bounds_max();
  const double extent = std::max({double(hi.x - lo.x), double(hi.y - lo.y), double(hi.z - lo.z)});
  if (!(extent > 0.0) || !std::isfinite(extent)) return out;
  const double distance_tolerance = kCoplanarDistanceTolerance * extent;
  const double overlap_tolerance = kCoplanarOverlapTolerance * extent;
  // Cells far wider than the tolerances; a plane is looked up in every cell its tolerance
  // interval reaches (one in most dimensions, two near a cell's border).
  const double normal_cell = 1e-3, offset_cell = 1e-4 * extent;

  struct Entry {
    std::uint32_t draw, triangle;
    Plane plane;
  };
  std::unordered_map<CellKey, std::vector<Entry>, CellHash> cells;
  std::unordered_set<std::uint64_t> overlapping;  // (earlier draw, later draw) pairs found
  const auto corners = [&](std::uint32_t t) {
    std::array<Vec, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = Vec(scene.vertices[scene.indices[3 * std::size_t(t) + k]].position);
    return p;
  };

  for (std::uint32_t d = 0; d < scene.draws.size(); ++d) {
    const DrawRange& draw = scene.draws[d];
    for (std::uint32_t t = draw.first_index / 3; t < (draw.first_index + draw.index_count) / 3; ++t) {
      const std::array<Vec, 3> p = corners(t);
      Plane plane;
      if (!plane_of(p, &plane)) continue;
      const std::array<double, 4> value{plane.normal.x, plane.normal.y, plane.normal.z, plane.offset};
      const std::array<double, 4> cell{normal_cell, normal_cell, normal_cell, offset_cell};
      const std::array<double, 4> tolerance{kCoplanarNormalTolerance, kCoplanarNormalTolerance,
                                            kCoplanarNormalTolerance, distance_tolerance};
      std::array<std::int64_t, 4> first, last, home;
      for (int k = 0; k < 4; ++k) {
        first[k] = std::int64_t(std::floor((value[k] - tolerance[k]) / cell[k]));
        last[k] = std::int64_t(std::floor((value[k] + tolerance[k]) / cell[k]));
        home[k] = std::int64_t(std::floor(value[k] / cell[k]));
      }
      const Vec box_lo = glm::min(p[0], glm::min(p[1], p[2])), box_hi = glm::max(p[0], glm::max(p[1], p[2]));
      CellKey key;
      for (key.q[0] = first[0]; key.q[0] <= last[0]; ++key.q[0])
        for (key.q[1] = first[1]; key.q[1] <= last[1]; ++key.q[1])
          for (key.q[2] = first[2]; key.q[2] <= last[2]; ++key.q[2])
            for (key.q[3] = first[3]; key.q[3] <= last[3]; ++key.q[3]) {
              const auto found = cells.find(key);
              if (found == cells.end()) continue;
              for (const Entry& e : found->second) {
                if (e.draw == d) continue;
                const std::uint64_t pair = (std::uint64_t(e.draw) << 32) | d;
                if (overlapping.count(pair)) continue;
                if (++out.pair_tests > max_pair_tests) {
                  out.complete = false;
                  return out;
                }
                if (glm::length(e.plane.normal - plane.normal) >= kCoplanarNormalTolerance ||
                    std::abs(e.plane.offset - plane.offset) >= distance_tolerance)
                  continue;
                const std::array<Vec, 3> q = corners(e.triangle);
                const Vec q_lo = glm::min(q[0], glm::min(q[1], q[2])), q_hi = glm::max(q[0], glm::max(q[1], q[2]));
                if (glm::any(glm::lessThan(glm::min(box_hi, q_hi) - glm::max(box_lo, q_lo), Vec(-distance_tolerance))))
                  continue;
                if (!overlap(p, q, plane.dropped_axis, overlap_tolerance)) continue;
                overlapping.insert(pair);
                out.rank[d] = std::max(out.rank[d], out.rank[e.draw] + 1);
              }
            }
      cells[CellKey{home}].push_back({d, t, plane});
    }
  }
  return out;
}

void rank_coplanar_draws(Scene& scene) {
  const CoplanarRanks ranks = draw_depth_ranks(scene);
  if (!ranks.complete)
    std::fprintf(stderr,
                 "rsaa: warning: '%s': coplanar overlaps between draws searched for the first %llu triangle "
                 "pairs only; surfaces of later draws flush with earlier ones may z-fight\n",
                 scene.name.c_str(), static_cast<unsigned long long>(kCoplanarPairTests));
  for (std::size_t d = 0; d < scene.draws.size(); ++d) scene.draws[d].depth_rank = ranks.rank[d];
}

}  // namespace rsaa
