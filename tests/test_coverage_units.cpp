// Why dynamic coverage's seed rules changed with the scene's units, and that the tie bound
// (kSeedDepthTie) is what removed it: the GL fragment lists of the default scene at 640x480,
// unscaled and scaled by 10^3 and 10^-3, replayed side by side on the CPU with the seed's
// comparisons taken literally in float. Prints the breakdown the README's *Units* paragraph
// quotes (build/tests/test_coverage_units).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/reference/dynamic_coverage.h"
#include "image/image_io.h"
#include "image/image_metrics.h"
#include "runtime/coverage_lists.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/technique_registry.h"
#include "runtime/technique_testing.h"
#include "tests/gl_test.h"

namespace rsaa {
namespace {

class CoverageUnits : public test::GlTest {};

using Lists = std::vector<std::vector<CoverageFragment>>;

Lists seed_lists(const Scene& scene, int width, int height, Rgb* background) {
  const GpuScene gpu(scene);
  const View view = make_view(choose_camera(scene, std::nullopt), width, height);
  TechniqueOptions o = technique_options("dyncov");
  o.rules = "seed";
  auto t = make_technique(o, width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  t->render(gpu, view, output.get());
  const glm::vec3 b = gpu.background();
  *background = {b.r, b.g, b.b};
  return coverage_lists_of(*t)->read_back();
}

// The seed's update and resolve with its comparisons literally in float (`<`), as the seed rules
// were before the tie bound.
struct LiteralSeed {
  Rgb colour[2];
  float depth[2] = {1.0f, 1.0f};
  unsigned mask[2] = {0xFFFF, 0xFFFF};
  explicit LiteralSeed(Rgb clear) : colour{clear, clear} {}
  void insert(const CoverageFragment& f) {
    const unsigned incoming = unsigned(f.coverage & 0xFFFF);
    if (!incoming || !(f.depth.at_centre < depth[0] || f.depth.at_centre < depth[1])) return;
    const int slot = depth[0] < depth[1] ? 1 : 0;
    colour[slot] = f.colour, depth[slot] = f.depth.at_centre, mask[slot] = incoming;
  }
  Rgb resolve() const {
    const int near = depth[0] < depth[1] ? 0 : 1, far = 1 - near;
    const float total = float(__builtin_popcount(mask[0] | mask[1]));
    const float wn = float(__builtin_popcount(mask[near])) / total;
    const float wf = float(__builtin_popcount(mask[far] & ~mask[near])) / total;
    return {wn * colour[near].r + wf * colour[far].r, wn * colour[near].g + wf * colour[far].g,
            wn * colour[near].b + wf * colour[far].b};
  }
};

// The first comparison whose outcome differs between two replays of the same fragments (same
// order and masks, other depths): which one, and how far apart the depths compared were.
struct Flip {
  int kind = -1;  // 0 incoming against a slot, 1 which slot to evict, 2 the resolve's nearer
  double gap = 0.0;
};
Flip first_flip(const std::vector<CoverageFragment>& a, const std::vector<CoverageFragment>& b) {
  float da[2] = {1, 1}, db[2] = {1, 1};
  const auto gap = [](double x0, double y0, double x1, double y1) {
    return std::max(std::abs(x0 - y0), std::abs(x1 - y1));
  };
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (!(a[j].coverage & 0xFFFF)) continue;
    const float ia = a[j].depth.at_centre, ib = b[j].depth.at_centre;
    for (int k = 0; k < 2; ++k)
      if ((ia < da[k]) != (ib < db[k])) return {0, gap(ia, da[k], ib, db[k])};
    if (!(ia < da[0] || ia < da[1])) continue;
    const int sa = da[0] < da[1] ? 1 : 0, sb = db[0] < db[1] ? 1 : 0;
    if (sa != sb) return {1, gap(da[0], da[1], db[0], db[1])};
    da[sa] = ia, db[sb] = ib;
  }
  if ((da[0] < da[1]) != (db[0] < db[1])) return {2, gap(da[0], da[1], db[0], db[1])};
  return {};
}

bool same_fragments(const std::vector<CoverageFragment>& a, const std::vector<CoverageFragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t j = 0; j < a.size(); ++j)
    if (a[j].order != b[j].order || a[j].coverage != b[j].coverage) return false;
  return true;
}

TEST_F(CoverageUnits, TheSeedRulesChangedWithTheUnitsOnlyAtFloatTies) {
  const int width = 640, height = 480;
  const Scene scene = load_scene("builtin:default");
  Rgb background;
  const Lists unscaled = seed_lists(scene, width, height, &background);
  for (float factor : {1e3f, 1e-3f}) {
    const Lists scaled = seed_lists(scaled_scene(scene, factor), width, height, &background);
    Image literal[2] = {Image(width, height), Image(width, height)}, tied[2] = {Image(width, height), Image(width, height)};
    int changed = 0, other_fragments = 0, colour_only = 0, flips[3] = {0, 0, 0};
    double widest_gap = 0.0;
    for (int i = 0; i < width * height; ++i) {
      const std::vector<CoverageFragment>* lists[2] = {&unscaled[i], &scaled[i]};
      for (int s = 0; s < 2; ++s) {
        LiteralSeed l(background);
        DynamicCoveragePixel t(background, DynamicCoverageRules::Seed);
        for (const CoverageFragment& f : *lists[s]) l.insert(f), t.insert(f);
        literal[s].pixels[i] = l.resolve();
        tied[s].pixels[i] = t.resolve();
      }
      const Rgb x = literal[0].pixels[i], y = literal[1].pixels[i];
      if (std::abs(x.r - y.r) + std::abs(x.g - y.g) + std::abs(x.b - y.b) <= 1e-3f) continue;
      ++changed;
      if (!same_fragments(unscaled[i], scaled[i])) {
        ++other_fragments;
        continue;
      }
      const Flip f = first_flip(unscaled[i], scaled[i]);
      if (f.kind < 0) {
        ++colour_only;  // the same decisions; the colours shaded at the other scale differ
        continue;
      }
      ++flips[f.kind];
      widest_gap = std::max(widest_gap, f.gap);
    }
    // How far one fragment's depth moves between the scales, in float steps of [0.5, 1).
    std::vector<double> moves;
    for (int i = 0; i < width * height; ++i)
      if (same_fragments(unscaled[i], scaled[i]))
        for (std::size_t j = 0; j < unscaled[i].size(); ++j)
          moves.push_back(std::abs(double(unscaled[i][j].depth.at_centre) - scaled[i][j].depth.at_centre) / 0x1p-24);
    std::sort(moves.begin(), moves.end());
    const auto quantile = [&](double q) { return moves[std::size_t(q * double(moves.size() - 1))]; };
    std::printf("scale %g: a fragment's depth moves by at most %.0f / %.0f / %.0f float steps (2^-24) for "
                "99%% / 99.9%% / 99.99%% of %zu fragments\n",
                double(factor), quantile(0.99), quantile(0.999), quantile(0.9999), moves.size());
    EXPECT_LE(quantile(0.999) * 0x1p-24, double(kSeedDepthTie));
    const double literal_psnr = compare_images(to_display(literal[1]), to_display(literal[0])).psnr_db;
    const double tied_psnr = compare_images(to_display(tied[1]), to_display(tied[0])).psnr_db;
    std::printf("scale %g: %d pixels changed with the literal comparisons: %d with other fragments or masks, "
                "%d only by colour, first differing decision: incoming against a slot %d, which slot to evict %d, "
                "the resolve's nearer %d, between depths at most %.3g apart; PSNR literal %.2f dB, with ties %.2f\n",
                double(factor), changed, other_fragments, colour_only, flips[0], flips[1], flips[2], widest_gap,
                literal_psnr, tied_psnr);
    // The cause: the decisions that flipped compared depths float cannot tell apart.
    EXPECT_LT(widest_gap, double(kSeedDepthTie));
    EXPECT_LT(other_fragments + colour_only, changed / 20);
    // The cure: with the tie bound the scaled image is the unscaled one to 60 dB.
    EXPECT_LT(literal_psnr, 50.0);
    EXPECT_GE(tied_psnr, 60.0);
  }
}

}  // namespace
}  // namespace rsaa
