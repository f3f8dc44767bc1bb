#include "runtime/smoothing_groups.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstring>
#include <numeric>

namespace rsaa {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

std::uint32_t float_key(float v) {
  v += 0.0f;  // -0 == +0
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

// Per vertex, an id shared by every vertex at the same position (bit for bit).
std::vector<std::uint32_t> welded_positions(const std::vector<SceneVertex>& vertices) {
  struct Keyed {
    std::uint64_t xy;
    std::uint32_t z, vertex;
  };
  std::vector<Keyed> keyed(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::vec3& p = vertices[i].position;
    keyed[i] = {std::uint64_t(float_key(p.x)) << 32 | float_key(p.y), float_key(p.z), std::uint32_t(i)};
  }
  std::sort(keyed.begin(), keyed.end(),
            [](const Keyed& a, const Keyed& b) { return a.xy != b.xy ? a.xy < b.xy : a.z < b.z; });
  std::vector<std::uint32_t> id(vertices.size(), 0);
  std::uint32_t next = 0;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k > 0 && (keyed[k].xy != keyed[k - 1].xy || keyed[k].z != keyed[k - 1].z)) ++next;
    id[keyed[k].vertex] = next;
  }
  return id;
}

// Triangles on one side compared pair by pair: the first this many (a degenerate fan must not
// make the comparison quadratic).
constexpr std::size_t kMaxPairedSides = 16;

// One triangle's side: the welded ends (a < b) and the vertices that carry the triangle's
// normals there.
struct Side {
  std::uint64_t ends;  // a << 32 | b
  std::uint32_t triangle, vertex_a, vertex_b;
};

// A usable shading normal: finite and not zero.
bool usable(const glm::vec3& n) {
  const double length2 = glm::dot(glm::dvec3(n), glm::dvec3(n));
  return std::isfinite(length2) && length2 > 0.0;
}

const double kSmoothingCosine = std::cos(kSmoothingNormalDegrees * 3.14159265358979323846 / 180.0);

// In double: normals of any finite length compare by direction alone.
bool agree(const glm::vec3& n0, const glm::vec3& n1) {
  const glm::dvec3 a(n0), b(n1);
  return glm::dot(a, b) >= kSmoothingCosine * std::sqrt(glm::dot(a, a)) * std::sqrt(glm::dot(b, b));
}

enum class Join { smooth, crease, unknown };

// How two triangles' normals at the two ends of their shared side compare: a crease where they
// differ at both ends. Where they agree at one end (a shared vertex, or a hard edge that ends in a
// smooth surface) the shading step fades to nothing along the side, and marking it made false
// edges on smooth models (X/fromtruespace_bin32.x -0.99 dB at 640x480, 5-20 degree steps that
// end mid-surface; -0.12 with this rule).
Join shading_across(const std::vector<SceneVertex>& vertices, const Side& p, const Side& q) {
  bool crease = true;
  for (auto [v0, v1] : {std::pair{p.vertex_a, q.vertex_a}, std::pair{p.vertex_b, q.vertex_b}}) {
    const glm::vec3 n0 = vertices[v0].normal, n1 = vertices[v1].normal;
    // A broken model's normals (zero, not finite: a degenerate triangle's) neither join nor part.
    if (!usable(n0) || !usable(n1)) return Join::unknown;
    crease = crease && v0 != v1 && !agree(n0, n1);
  }
  return crease ? Join::crease : Join::smooth;
}

// Per group root: whether all its triangles' usable normals agree with its first one (a flat
// surface shaded flat: a floor, a wall, one facet on its own), and that normal.
struct FlatGroups {
  std::vector<bool> flat;
  std::vector<glm::vec3> normal;
};
FlatGroups flat_groups(const Scene& scene, std::vector<std::uint32_t>& parent) {
  const std::size_t triangles = parent.size();
  enum : std::uint8_t { unseen, flat, curved };
  std::vector<std::uint8_t> state(triangles, unseen);
  std::vector<glm::vec3> normal(triangles);
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const std::uint32_t r = find_root(parent, t);
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint32_t vertex = scene.indices[3 * std::size_t(t) + corner];
      const glm::vec3 n = vertex < scene.vertices.size() ? scene.vertices[vertex].normal : glm::vec3(0.0f);
      if (!usable(n)) {
        state[r] = curved;  // broken normals: nothing to say
      } else if (state[r] == unseen) {
        state[r] = flat;
        normal[r] = n;
      } else if (state[r] == flat && !agree(n, normal[r])) {
        state[r] = curved;
      }
    }
  }
  FlatGroups groups{std::vector<bool>(triangles), std::move(normal)};
  for (std::size_t r = 0; r < triangles; ++r) groups.flat[r] = state[r] == flat;
  return groups;
}

// A hash of a unit normal's direction quantised to about 0.6 degrees.
std::uint32_t normal_hash(const glm::vec3& n) {
  const glm::ivec3 q = glm::ivec3(glm::round(glm::normalize(glm::dvec3(n)) * 96.0)) + 128;
  std::uint32_t h = std::uint32_t(q.x) * 73856093u ^ std::uint32_t(q.y) * 19349663u ^ std::uint32_t(q.z) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return h;
}

}  // namespace

std::vector<std::uint8_t> facet_colours(const Scene& scene) {
  const std::size_t triangles = scene.triangle_count();
  std::vector<std::uint8_t> colour(triangles, kNotAFacet);
  if (triangles == 0) return colour;
  const std::vector<std::uint32_t> weld = welded_positions(scene.vertices);
  std::vector<std::uint32_t> parent(triangles);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> creases;  // triangle pairs

  std::vector<Side> sides;
  for (const DrawRange& draw : scene.draws) {
    // Groups never span draws: a draw's material already tells it from the others.
    const std::uint32_t first = draw.first_index / 3, count = draw.index_count / 3;
    if (std::uint64_t(first) + count > triangles) continue;  // not this scene's (GL refuses it too)
    sides.clear();
    sides.reserve(std::size_t(count) * 3);
    for (std::uint32_t t = first; t < first + count; ++t) {
      const std::uint32_t* corners = &scene.indices[3 * std::size_t(t)];
      if (std::max({corners[0], corners[1], corners[2]}) >= scene.vertices.size()) continue;
      for (int corner = 0; corner < 3; ++corner) {
        std::uint32_t v0 = corners[corner], v1 = corners[(corner + 1) % 3];
        if (weld[v0] == weld[v1]) continue;  // a degenerate side
        if (weld[v0] > weld[v1]) std::swap(v0, v1);
        sides.push_back({std::uint64_t(weld[v0]) << 32 | weld[v1], t, v0, v1});
      }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
      return x.ends != y.ends ? x.ends < y.ends : x.triangle < y.triangle;
    });
    for (std::size_t run = 0, end = 0; run < sides.size(); run = end) {
      while (end < sides.size() && sides[end].ends == sides[run].ends) ++end;
      // Every pair on a side (three or more triangles on one side: a fin on a floor).
      const std::size_t last = std::min(end, run + kMaxPairedSides);
      for (std::size_t i = run; i < last; ++i)
        for (std::size_t j = i + 1; j < last; ++j) {
          const Side& p = sides[i];
          const Side& q = sides[j];
          if (p.triangle == q.triangle) continue;
          const Join join = shading_across(scene.vertices, p, q);
          if (join == Join::smooth)
            parent[find_root(parent, p.triangle)] = find_root(parent, q.triangle);
          else if (join == Join::crease)
            creases.emplace_back(p.triangle, q.triangle);
        }
    }
  }
  sides = {};  // freed before the colouring

  // Groups and the groups they meet across creases (both ways, by root).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> meets;
  meets.reserve(creases.size() * 2);
  for (const auto& [s, t] : creases) {
    const std::uint32_t r = find_root(parent, s), u = find_root(parent, t);
    if (r == u) continue;  // a group meeting itself across a crease: nothing to tell apart
    meets.emplace_back(r, u);
    meets.emplace_back(u, r);
  }
  std::sort(meets.begin(), meets.end());
  meets.erase(std::unique(meets.begin(), meets.end()), meets.end());
  const FlatGroups flat = flat_groups(scene, parent);

  // Colours 1..127, greedy over the facets in the order of their first triangle: the first colour
  // that no facet met across a crease has, from a start that is a flat facet's normal's (a hash)
  // or a curved facet's group's. A flat facet that meets none takes its normal's colour: flat
  // parts of one plane in two draws (a floor's tiles of two materials) then differ exactly as
  // their draws' materials do, and coplanar pieces of one face that share no welded side (a
  // T-junction) match; facets that do not meet otherwise (a front facet over a back facet at a
  // silhouette, a wall through a floor) differ 126 times in 127.
  constexpr int kColours = 127, kNoColour = -2;
  std::vector<std::int16_t> group_colour(triangles, -1);
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const std::uint32_t r = find_root(parent, t);
    if (group_colour[r] == -1) {
      const auto range = std::equal_range(meets.begin(), meets.end(), std::make_pair(r, 0u),
                                          [](const auto& x, const auto& y) { return x.first < y.first; });
      if (range.first == range.second && !flat.flat[r]) {
        group_colour[r] = kNoColour;  // curved, shading continuous all round: not a facet
      } else {
        std::bitset<kColours> used;
        for (auto it = range.first; it != range.second; ++it)
          if (group_colour[it->second] > 0) used.set(std::size_t(group_colour[it->second] - 1));
        std::uint32_t start = r * 2654435761u;
        start ^= start >> 16;
        if (flat.flat[r]) start = normal_hash(flat.normal[r]);
        int c = 0;
        while (c < kColours && used.test((start + std::uint32_t(c)) % kColours)) ++c;
        group_colour[r] = std::int16_t(1 + (start + std::uint32_t(c < kColours ? c : 0)) % kColours);
      }
    }
    if (group_colour[r] >= 0) colour[t] = std::uint8_t(kFacetBit | group_colour[r]);
  }
  return colour;
}

}  // namespace rsaa
