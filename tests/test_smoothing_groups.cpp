// Smoothing groups and facet colours (runtime/smoothing_groups.h): creases are where shading
// normals differ across a shared edge; facets bounded by creases get colours that differ from
// every facet they meet; continuous shading gets none.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "runtime/smoothing_groups.h"

namespace rsaa {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Appends a triangle with its own three vertices (as flat-shading exporters write them).
void add_triangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb, glm::vec3 nc) {
  const auto first = std::uint32_t(scene.vertices.size());
  for (auto [p, n] : {std::pair{a, na}, std::pair{b, nb}, std::pair{c, nc}}) {
    SceneVertex v;
    v.position = p;
    v.normal = n;
    scene.vertices.push_back(v);
  }
  for (std::uint32_t k = 0; k < 3; ++k) scene.indices.push_back(first + k);
}

void add_flat_triangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  add_triangle(scene, a, b, c, n, n, n);
}

// One draw over every triangle.
void one_draw(Scene& scene) {
  DrawRange d;
  d.index_count = std::uint32_t(scene.indices.size());
  scene.draws = {d};
}

// A lat-long sphere, `rings` x `segments` quads, each quad two triangles. Flat: every triangle
// its own vertices and face normal; smooth: shared vertices with the sphere's normal.
Scene sphere(int rings, int segments, bool flat) {
  Scene s;
  const auto at = [&](int i, int j) {
    const double theta = kPi * i / rings, phi = 2 * kPi * (j % segments) / segments;
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
  };
  if (!flat) {
    for (int i = 0; i <= rings; ++i)
      for (int j = 0; j <= segments; ++j) {
        SceneVertex v;
        v.position = at(i, j);
        v.normal = v.position;
        s.vertices.push_back(v);
      }
  }
  const auto index = [&](int i, int j) { return std::uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const int quad[2][3][2] = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}, {{i, j}, {i + 1, j + 1}, {i, j + 1}}};
      for (int k = 0; k < 2; ++k) {
        const auto& t = quad[k];
        if ((i == 0 && k == 1) || (i == rings - 1 && k == 0)) continue;  // degenerate at a pole
        if (flat) {
          add_flat_triangle(s, at(t[0][0], t[0][1]), at(t[1][0], t[1][1]), at(t[2][0], t[2][1]));
        } else {
          for (const auto& c : t) s.indices.push_back(index(c[0], c[1]));
        }
      }
    }
  one_draw(s);
  return s;
}

// Triangles that share a side (by position), as pairs.
std::set<std::pair<std::size_t, std::size_t>> neighbours(const Scene& s) {
  std::map<std::pair<std::vector<float>, std::vector<float>>, std::vector<std::size_t>> sides;
  for (std::size_t t = 0; t < s.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c) {
      const glm::vec3 a = s.vertices[s.indices[3 * t + c]].position, b = s.vertices[s.indices[3 * t + (c + 1) % 3]].position;
      std::vector<float> ka{a.x, a.y, a.z}, kb{b.x, b.y, b.z};
      if (kb < ka) std::swap(ka, kb);
      if (ka != kb) sides[{ka, kb}].push_back(t);
    }
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& [side, ts] : sides)
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) pairs.insert({ts[i], ts[i + 1]});
  return pairs;
}

TEST(SmoothingGroups, AFlatShadedSphereIsAllFacetsAndNeighbouringFacetsDiffer) {
  const Scene s = sphere(12, 24, true);
  const std::vector<std::uint8_t> colour = facet_colours(s);
  ASSERT_EQ(colour.size(), s.triangle_count());
  std::size_t same_quad = 0, crease_pairs = 0;
  for (const auto& [t, u] : neighbours(s)) {
    ASSERT_NE(colour[t] & kFacetBit, 0) << t;
    EXPECT_NE(colour[t], kFacetBit) << t;  // facets bounded by creases take colours 1..127
    const glm::vec3 nt = s.vertices[s.indices[3 * t]].normal, nu = s.vertices[s.indices[3 * u]].normal;
    const double degrees = std::acos(std::min(1.0, double(glm::dot(nt, nu)))) * 180.0 / kPi;
    if (degrees < 0.5) ++same_quad;  // the two triangles of one planar quad (float rounding apart)
    if (degrees < kSmoothingNormalDegrees - 0.01) {
      EXPECT_EQ(colour[t], colour[u]) << t << ' ' << u;  // one facet (or the facets round a pole)
    } else if (degrees > kSmoothingNormalDegrees + 0.01) {
      EXPECT_NE(colour[t], colour[u]) << t << ' ' << u;  // a crease
      ++crease_pairs;
    }
  }
  EXPECT_GT(same_quad, 200u);  // 24 x 10 planar quads (the poles' are triangles)
  EXPECT_GT(crease_pairs, 500u);
  EXPECT_EQ(facet_colours(s), colour);  // deterministic
}

// Two curved patches of a cylinder (radial normals, 30 degrees each, 3 quads wide) meeting along
// a column of positions, each with its own vertices there; the second patch's normals on that
// column turned by `turn_degrees` (at its lower end only unless `both_ends`). With `two_draws`
// each patch is its own draw.
Scene curved_patches(double turn_degrees, bool two_draws, bool both_ends = true) {
  Scene s;
  const auto at = [](int k) {
    const double phi = 10.0 * k * kPi / 180.0;
    return glm::vec3(float(std::cos(phi)), float(std::sin(phi)), 0.0f);
  };
  const double turn = turn_degrees * kPi / 180.0;
  for (int patch = 0; patch < 2; ++patch) {
    const std::uint32_t first_index = std::uint32_t(s.indices.size());
    const std::uint32_t first = std::uint32_t(s.vertices.size());
    for (int k = 3 * patch; k <= 3 * patch + 3; ++k)
      for (float z : {0.0f, 1.0f}) {
        SceneVertex v;
        v.position = at(k) + glm::vec3(0, 0, z);
        v.normal = at(k);
        if (patch == 1 && k == 3 && (both_ends || z == 0.0f))
          v.normal = glm::vec3(float(std::cos(kPi / 6 + turn)), float(std::sin(kPi / 6 + turn)), 0.0f);
        s.vertices.push_back(v);
      }
    for (std::uint32_t q = 0; q < 3; ++q) {
      const std::uint32_t a = first + 2 * q, b = a + 2, c = a + 3, d = a + 1;
      for (std::uint32_t i : {a, b, c, a, c, d}) s.indices.push_back(i);
    }
    if (two_draws || patch == 1) {
      DrawRange d;
      d.first_index = two_draws ? first_index : 0;
      d.index_count = std::uint32_t(s.indices.size()) - d.first_index;
      s.draws.push_back(d);
    }
  }
  return s;
}

TEST(SmoothingGroups, SmoothShadingMakesNoFacets) {
  // Shared vertices (and a seam of split vertices with equal normals where the sphere closes).
  for (std::uint8_t c : facet_colours(sphere(12, 24, false))) EXPECT_EQ(c, kNotAFacet);
  // Split vertices whose normals agree within a fraction of kSmoothingNormalDegrees.
  for (std::uint8_t c : facet_colours(curved_patches(0.3 * kSmoothingNormalDegrees, false))) EXPECT_EQ(c, kNotAFacet);
  // Turned at one end only (a hard edge ending in a smooth surface): the step fades along the
  // side, no crease.
  for (std::uint8_t c : facet_colours(curved_patches(2.0 * kSmoothingNormalDegrees, false, false))) EXPECT_EQ(c, kNotAFacet);
  // Beyond the tolerance at both ends the column is a crease: two facets of different colours.
  const std::vector<std::uint8_t> creased = facet_colours(curved_patches(2.0 * kSmoothingNormalDegrees, false));
  ASSERT_EQ(creased.size(), 12u);
  for (std::size_t t = 0; t < 12; ++t) {
    EXPECT_NE(creased[t] & kFacetBit, 0) << t;
    EXPECT_EQ(creased[t], creased[t < 6 ? 0 : 6]) << t;
  }
  EXPECT_NE(creased[0], creased[6]);
}

// A flat surface shaded flat is a facet although no crease bounds it: a floor differs from the
// smooth objects standing on it (whose silhouettes SADP misses at grazing angles).
TEST(SmoothingGroups, AFlatSurfaceIsAFacetOfItsOwn) {
  Scene floor;
  const glm::vec3 up{0, 1, 0};
  add_triangle(floor, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, up, up, up);
  add_triangle(floor, {0, 0, 0}, {1, 0, 1}, {1, 0, 0}, up, up, up);
  one_draw(floor);
  const std::vector<std::uint8_t> colour = facet_colours(floor);
  EXPECT_NE(colour[0] & kFacetBit, 0);
  EXPECT_EQ(colour[0], colour[1]);
  // The same floor's tiles in two draws: the colour is the normal's, so their materials differ
  // as the draws' do.
  Scene tiles = floor;
  for (SceneVertex& v : floor.vertices) v.position.x += 1.0f;
  tiles.vertices.insert(tiles.vertices.end(), floor.vertices.begin(), floor.vertices.end());
  for (std::uint32_t i = 0; i < 6; ++i) tiles.indices.push_back(6 + i);
  tiles.draws = {DrawRange{0, 6}, DrawRange{6, 6}};
  const std::vector<std::uint8_t> two = facet_colours(tiles);
  EXPECT_EQ(two, std::vector<std::uint8_t>(4, colour[0]));
}

// A flat face whose edge normals continue into a smooth bevel (a rounded box's side), and a flat
// floor: shading is continuous, so no facet and no material edge, although the face's own
// triangles have three equal normals.
TEST(SmoothingGroups, AFlatFaceContinuedByASmoothBevelIsNotAFacet) {
  Scene box;
  const glm::vec3 up{0, 1, 0}, side{1, 0, 0}, half = glm::normalize(glm::vec3(1, 1, 0));
  // The top face (normals up), then a bevel strip from its edge x = 1 down to the side: the
  // bevel's normals turn from up (at the shared edge) to `side`.
  add_triangle(box, {0, 1, 0}, {1, 1, 1}, {1, 1, 0}, up, up, up);
  add_triangle(box, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}, up, up, up);
  add_triangle(box, {1, 1, 0}, {1, 1, 1}, {1.2f, 0.8f, 1}, up, up, half);
  add_triangle(box, {1, 1, 0}, {1.2f, 0.8f, 1}, {1.2f, 0.8f, 0}, up, half, half);
  add_triangle(box, {1.2f, 0.8f, 0}, {1.2f, 0.8f, 1}, {1.2f, 0, 1}, half, half, side);
  one_draw(box);
  for (std::uint8_t c : facet_colours(box)) EXPECT_EQ(c, kNotAFacet);
}

// Groups never span draws (a draw's material already tells it from the others): a crease
// between two draws colours nothing. Broken normals make no creases and no flat groups.
TEST(SmoothingGroups, DrawsAndBrokenNormalsMakeNoFacets) {
  for (std::uint8_t c : facet_colours(curved_patches(2.0 * kSmoothingNormalDegrees, true))) EXPECT_EQ(c, kNotAFacet);

  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const glm::vec3 broken : {glm::vec3(0.0f), glm::vec3(nan)}) {
    Scene s = sphere(6, 8, true);
    for (SceneVertex& v : s.vertices) v.normal = broken;
    for (std::uint8_t c : facet_colours(s)) EXPECT_EQ(c, kNotAFacet);
  }
  EXPECT_TRUE(facet_colours(Scene{}).empty());
  // Indices or draws out of range (a scene made by hand, not a loader): no facets from them, no
  // read outside the arrays.
  Scene wrong = sphere(4, 4, true);
  wrong.indices[4] = std::uint32_t(wrong.vertices.size());
  wrong.draws.push_back(DrawRange{std::uint32_t(wrong.indices.size()), 3});
  EXPECT_EQ(facet_colours(wrong)[1], kNotAFacet);
}

}  // namespace
}  // namespace rsaa
