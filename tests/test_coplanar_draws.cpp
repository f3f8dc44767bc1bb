// Coplanar overlaps between draws: ranks by draw order (runtime/coplanar_draws.h), and the
// rendering they make independent of the units.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>
#include <vector>

#include "runtime/coplanar_draws.h"
#include "runtime/gpu_scene.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/techniques/techniques.h"
#include "tests/gl_test.h"

namespace rsaa {
namespace {

// A quad o + s u + t v, s and t in [s0, s1] x [t0, t1], as its own draw; `flip` takes the other
// diagonal, so that coplanar quads interpolate their depths from different triangles.
void add_quad(Scene& scene, glm::dvec3 o, glm::dvec3 u, glm::dvec3 v, double s0, double s1, double t0, double t1,
              glm::vec3 albedo, bool flip = false) {
  const auto first = std::uint32_t(scene.vertices.size());
  const glm::vec3 normal = glm::normalize(glm::vec3(glm::cross(u, v)));
  for (auto [s, t] : std::initializer_list<std::pair<double, double>>{{s0, t0}, {s1, t0}, {s1, t1}, {s0, t1}}) {
    SceneVertex vertex;
    vertex.position = glm::vec3(o + s * u + t * v);
    vertex.normal = normal;
    vertex.albedo = albedo;
    scene.vertices.push_back(vertex);
  }
  const std::uint32_t index_start = std::uint32_t(scene.indices.size());
  const std::vector<std::uint32_t> corners = flip ? std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3}
                                                  : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
  for (std::uint32_t c : corners) scene.indices.push_back(first + c);
  DrawRange draw;
  draw.first_index = index_start;
  draw.index_count = 6;
  draw.material = std::uint32_t(scene.draws.size());
  scene.draws.push_back(draw);
}

const glm::dvec3 kOrigin{0.0, 0.0, 0.0}, kX{1.0, 0.0, 0.0}, kY{0.0, 1.0, 0.0};
const glm::vec3 kGrey{0.5f};

std::vector<std::uint32_t> ranks_of(const Scene& scene) { return draw_depth_ranks(scene).rank; }

TEST(CoplanarDraws, OverlapsInOnePlaneAreRankedByDrawOrder) {
  Scene two;
  add_quad(two, kOrigin, kX, kY, 0, 2, 0, 2, kGrey);
  add_quad(two, kOrigin, kX, kY, 1, 3, 1, 3, kGrey, true);
  EXPECT_EQ(ranks_of(two), (std::vector<std::uint32_t>{0, 1}));

  // A chain needs one more rank per draw; two draws that overlap only the first share a rank.
  Scene chain;
  for (int k = 0; k < 3; ++k) add_quad(chain, kOrigin, kX, kY, 0.5 * k, 0.5 * k + 2, 0, 2, kGrey);
  EXPECT_EQ(ranks_of(chain), (std::vector<std::uint32_t>{0, 1, 2}));
  Scene fan;
  add_quad(fan, kOrigin, kX, kY, 0, 4, 0, 1, kGrey);
  add_quad(fan, kOrigin, kX, kY, 0, 1, 0, 1, kGrey);
  add_quad(fan, kOrigin, kX, kY, 3, 4, 0, 1, kGrey);
  EXPECT_EQ(ranks_of(fan), (std::vector<std::uint32_t>{0, 1, 1}));
  // The search's bound: stopped after the first pair, the ranks found so far stand.
  const CoplanarRanks bounded = draw_depth_ranks(fan, 1);
  EXPECT_FALSE(bounded.complete);
  EXPECT_EQ(bounded.rank, (std::vector<std::uint32_t>{0, 1, 0}));
  EXPECT_TRUE(draw_depth_ranks(fan).complete);
}

TEST(CoplanarDraws, TouchingParallelAndDegenerateDrawsAreNotRanked) {
  Scene touching;  // flush tiles sharing an edge, and one meeting only at a corner
  add_quad(touching, kOrigin, kX, kY, 0, 1, 0, 1, kGrey);
  add_quad(touching, kOrigin, kX, kY, 1, 2, 0, 1, kGrey);
  add_quad(touching, kOrigin, kX, kY, 2, 3, 1, 2, kGrey);
  EXPECT_EQ(ranks_of(touching), (std::vector<std::uint32_t>{0, 0, 0}));

  Scene parallel;  // a gap of 10^-4 of the extent is a modelled gap, not a tie
  add_quad(parallel, kOrigin, kX, kY, 0, 2, 0, 2, kGrey);
  add_quad(parallel, {0.0, 0.0, 2e-4}, kX, kY, 0, 2, 0, 2, kGrey);
  EXPECT_EQ(ranks_of(parallel), (std::vector<std::uint32_t>{0, 0}));

  Scene tilted;  // 0.01 degrees apart over the overlap
  add_quad(tilted, kOrigin, kX, kY, 0, 2, 0, 2, kGrey);
  add_quad(tilted, kOrigin, kX, {0.0, 1.0, 2e-4}, 0, 2, 0, 2, kGrey);
  EXPECT_EQ(ranks_of(tilted), (std::vector<std::uint32_t>{0, 0}));

  Scene degenerate;
  add_quad(degenerate, kOrigin, kX, kY, 0, 2, 0, 2, kGrey);
  add_quad(degenerate, kOrigin, kX, 2.0 * kX, 0, 2, 0, 2, kGrey);  // zero area
  EXPECT_EQ(ranks_of(degenerate), (std::vector<std::uint32_t>{0, 0}));

  Scene one_draw;  // overlaps inside one draw are left to its triangle order
  add_quad(one_draw, kOrigin, kX, kY, 0, 2, 0, 2, kGrey);
  add_quad(one_draw, kOrigin, kX, kY, 1, 3, 1, 3, kGrey);
  one_draw.draws = {{0, 12, -1}};
  EXPECT_EQ(ranks_of(one_draw), (std::vector<std::uint32_t>{0}));
}

// The same overlap in another plane, away from the origin and at another scale.
TEST(CoplanarDraws, RanksDoNotDependOnTheUnitsOrThePlane) {
  const glm::dvec3 u = glm::normalize(glm::dvec3(0.8, 0.1, -0.3)), v = glm::normalize(glm::cross(u, {0.2, 0.9, 0.4}));
  for (double scale : {1e-3, 1.0, 1e3}) {
    Scene scene;
    const glm::dvec3 o = scale * glm::dvec3(3.7, -1.3, 0.9);
    add_quad(scene, o, scale * u, scale * v, 0, 2, 0, 2, kGrey);
    add_quad(scene, o, scale * u, scale * v, 2, 3, 0, 2, kGrey);  // flush beside the first
    add_quad(scene, o, scale * u, scale * v, 1.5, 2.5, 0.5, 1.5, kGrey, true);  // over both
    EXPECT_EQ(ranks_of(scene), (std::vector<std::uint32_t>{0, 0, 1})) << "scale " << scale;
  }
}

class CoplanarDrawsGl : public test::GlTest {};

// Two coplanar quads of different colours overlapping, tilted to the view, in odd coordinates:
// without ranks the depth test keeps one or the other by rounding (both colours show in the
// overlap); with them the first draw shows in every overlap pixel, at three scales.
TEST_F(CoplanarDrawsGl, TheFirstDrawShowsInTheOverlapAtEveryScale) {
  const glm::dvec3 u = glm::normalize(glm::dvec3(0.83, 0.17, -0.41)), v = glm::normalize(glm::cross(u, {0.3, 0.9, 0.33}));
  const glm::dvec3 o{0.37, -0.21, 0.13};
  const glm::vec3 red{0.8f, 0.05f, 0.05f}, green{0.05f, 0.8f, 0.05f};
  Scene scene;
  add_quad(scene, o, u, v, 0.0, 1.0, 0.0, 1.0, red);
  add_quad(scene, o, u, v, 0.3, 1.3, 0.1, 1.1, green, true);
  rank_coplanar_draws(scene);
  ASSERT_EQ(scene.draws[1].depth_rank, 1u);
  constexpr int kSize = 96;
  const auto render = [&](const Scene& s) {
    const GpuScene gpu(s);
    return render_frame(gpu, choose_camera(s, std::nullopt), technique_options("noaa"), kSize, kSize);
  };
  // The overlap: pixels both quads cover, each drawn alone.
  Scene red_only = scene, green_only = scene;
  red_only.draws = {scene.draws[0]};
  green_only.draws = {scene.draws[1]};
  const Image background_only = [&] {
    Scene none = scene;
    none.draws = {{0, 0, -1}};
    return render(none);
  }();
  const Image a = render(red_only), b = render(green_only);
  std::vector<std::size_t> overlap;
  const auto covered = [&](const Image& image, std::size_t p) {
    return image.pixels[p].r != background_only.pixels[p].r || image.pixels[p].g != background_only.pixels[p].g;
  };
  for (std::size_t p = 0; p < a.pixels.size(); ++p)
    if (covered(a, p) && covered(b, p)) overlap.push_back(p);
  ASSERT_GT(overlap.size(), 1000u);
  const auto green_pixels = [&](const Image& image) {
    int n = 0;
    for (std::size_t p : overlap) n += image.pixels[p].g > image.pixels[p].r;
    return n;
  };
  Scene unranked = scene;
  for (DrawRange& d : unranked.draws) d.depth_rank = 0;
  int unranked_green = 0;
  for (float factor : {1.0f, 1e3f, 1e-3f}) {
    unranked_green += green_pixels(render(scaled_scene(unranked, factor)));
    EXPECT_EQ(green_pixels(render(scaled_scene(scene, factor))), 0) << "scale " << factor;
  }
  EXPECT_GT(unranked_green, 0) << "the test scene does not z-fight without ranks";
}

}  // namespace
}  // namespace rsaa
