// The CPU references of DCAA and dynamic coverage: the merge/evict rules on hand-made fragment
// sequences, the seed's worked example, and the extremes (more surfaces than slots, one depth
// for everything, zero coverage, NaN).
#include <gtest/gtest.h>

#include <cmath>

#include "core/reference/dcaa.h"
#include "core/reference/scene_shading.h"
#include "core/reference/dynamic_coverage.h"
#include "core/reference/halfplane_lut.h"

namespace rsaa {
namespace {

constexpr float kPi = 3.14159265f;

CoverageFragment fragment(std::uint32_t order, Mask coverage, float depth, float normal_angle, Rgb colour,
                          float ddx = 0.0f) {
  CoverageFragment f;
  f.order = order;
  f.coverage = coverage;
  f.depth = {depth, ddx, 0.0f};
  f.normal = {std::sin(normal_angle), 0.0f, std::cos(normal_angle)};
  f.colour = colour;
  return f;
}

bool finite(Rgb c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// ---- DCAA: merge rules -------------------------------------------------------------------

TEST(Dcaa, AlignedOverlappingFragmentsMergeWeightedByCoverage) {
  DcaaPixel pixel;
  EXPECT_EQ(pixel.insert(fragment(0, 0x00000000FFFFFFFFull, 0.5f, 0.0f, {1, 0, 0}, 0.01f)), DcaaEvent::Stored);
  // 16 bits, a normal pi/20 away (inside the pi/16 cone), depth intervals overlapping.
  EXPECT_EQ(pixel.insert(fragment(1, 0x0000FFFF00000000ull, 0.505f, kPi / 20, {0, 0, 1}, 0.01f)), DcaaEvent::Merged);
  ASSERT_EQ(pixel.surfaces().size(), 1u);
  const DcaaSurface& s = pixel.surfaces()[0];
  EXPECT_EQ(s.coverage, 0x0000FFFFFFFFFFFFull);
  EXPECT_NEAR(s.colour.r, 32.0f / 48.0f, 1e-6f);
  EXPECT_NEAR(s.colour.b, 16.0f / 48.0f, 1e-6f);
  EXPECT_NEAR(s.depth.at_centre, (32 * 0.5f + 16 * 0.505f) / 48.0f, 1e-6f);
  EXPECT_NEAR(dot(s.normal, s.normal), 1.0f, 1e-6f);
}

TEST(Dcaa, NormalsBeyondTheConeOrSeparateDepthsStayApart) {
  DcaaPixel pixel;
  pixel.insert(fragment(0, 0xFFull, 0.5f, 0.0f, {1, 0, 0}, 0.01f));
  EXPECT_EQ(pixel.insert(fragment(1, 0xFF00ull, 0.5f, kPi / 12, {0, 1, 0}, 0.01f)), DcaaEvent::Stored);  // pi/12 > pi/16
  EXPECT_EQ(pixel.insert(fragment(2, 0xFF0000ull, 0.6f, 0.0f, {0, 0, 1}, 0.01f)), DcaaEvent::Stored);   // 0.6 - 0.5 > extents
  EXPECT_EQ(pixel.surfaces().size(), 3u);
}

TEST(Dcaa, BestCandidateHasTheClosestNormal) {
  DcaaPixel pixel;
  pixel.insert(fragment(0, 0xFull, 0.5f, 0.0f, {1, 0, 0}, 0.05f));
  pixel.insert(fragment(1, 0xF0ull, 0.5f, kPi / 8, {0, 1, 0}, 0.05f));
  EXPECT_EQ(pixel.insert(fragment(2, 0xF00ull, 0.5f, kPi / 8 - 0.01f, {0, 0, 1}, 0.05f)), DcaaEvent::Merged);
  EXPECT_EQ(pixel.surfaces()[0].coverage, 0xFull);
  EXPECT_EQ(pixel.surfaces()[1].coverage, 0xFF0ull);
}

// Four surfaces at clearly separate depths with normals far apart: the list is full.
DcaaPixel full_pixel(DcaaSettings settings = {}) {
  DcaaPixel pixel(settings);
  pixel.insert(fragment(0, 0x0000'0000'0000'FFFFull, 0.1f, 0.0f, {1, 0, 0}));       // front-most, 16 bits
  pixel.insert(fragment(1, 0x0000'0000'FFFF'0000ull, 0.3f, 0.5f, {0, 1, 0}));       // 16 visible
  pixel.insert(fragment(2, 0x0000'00FF'0000'0000ull, 0.5f, 1.0f, {0, 0, 1}, 0.6f));  // 8 visible, wide depth range
  pixel.insert(fragment(3, 0xFFFF'FF00'0000'0000ull, 0.7f, 1.5f, {1, 1, 0}));       // 24 visible
  return pixel;
}

TEST(Dcaa, FullListMergesTheSmallestVisibleSurfaceIntoAnOverlappingOne) {
  DcaaPixel pixel = full_pixel();
  ASSERT_EQ(pixel.surfaces().size(), 4u);
  // A fifth fragment in front of all: it is the front-most, so the smallest visible is surface
  // 2 (8 bits), whose depth interval [0.2, 0.8] touches surfaces 1 and 3: merged, not lost,
  // into both, as Algorithm 1 writes it (lines 13-17).
  const CoverageFragment fifth = fragment(4, 0xFull, 0.05f, 2.0f, {1, 1, 1});
  EXPECT_EQ(pixel.insert(fifth), DcaaEvent::SecondMerge);
  ASSERT_EQ(pixel.surfaces().size(), 4u);
  EXPECT_EQ(pixel.surfaces()[1].coverage, 0x0000'00FF'FFFF'0000ull);  // surface 1 took surface 2
  EXPECT_EQ(pixel.surfaces()[2].coverage, 0xFFFF'FFFF'0000'0000ull);  // and so did surface 3
  // Merging into the best overlapping surface only (second_merge_into_all = false): surface 1,
  // whose interval overlaps surface 2's most; surface 3 is left as it was.
  DcaaSettings single;
  single.second_merge_into_all = false;
  DcaaPixel one = full_pixel(single);
  one.insert(fifth);
  EXPECT_EQ(one.surfaces()[1].coverage, 0x0000'00FF'FFFF'0000ull);
  EXPECT_EQ(one.surfaces()[2].coverage, 0xFFFF'FF00'0000'0000ull);
  EXPECT_EQ(pixel.surfaces().back().coverage, fifth.coverage);          // the fragment got a slot
  Mask all = 0;
  for (const DcaaSurface& s : pixel.surfaces()) all |= s.coverage;
  EXPECT_EQ(all, ~Mask{0});  // no coverage lost
}

TEST(Dcaa, FullListDropsTheSmallestWhenNothingOverlapsButNeverTheFrontMost) {
  DcaaPixel pixel;
  pixel.insert(fragment(0, 0x1ull, 0.1f, 0.0f, {1, 0, 0}));             // front-most, 1 bit only
  pixel.insert(fragment(1, 0xFFFF'0000ull, 0.3f, 0.5f, {0, 1, 0}));
  pixel.insert(fragment(2, 0xFF'0000'0000ull, 0.5f, 1.0f, {0, 0, 1}));  // 8 bits: the smallest non-front
  pixel.insert(fragment(3, 0xFFFF'FF00'0000'0000ull, 0.7f, 1.5f, {1, 1, 0}));
  EXPECT_EQ(pixel.insert(fragment(4, 0xFFF0ull, 0.9f, 2.0f, {1, 1, 1})), DcaaEvent::Discarded);
  ASSERT_EQ(pixel.surfaces().size(), 4u);
  EXPECT_EQ(pixel.surfaces()[0].coverage, 0x1ull);  // the front-most stays, though smallest
  for (const DcaaSurface& s : pixel.surfaces()) EXPECT_NE(s.coverage, 0xFF'0000'0000ull);
  EXPECT_EQ(pixel.surfaces()[3].coverage, 0xFFF0ull);
  // When the incoming fragment is the smallest visible (hidden behind the others) it is dropped.
  const auto before = pixel.surfaces();
  EXPECT_EQ(pixel.insert(fragment(5, 0xFFFF'0000ull, 0.95f, 2.5f, {1, 1, 1})), DcaaEvent::Discarded);
  ASSERT_EQ(pixel.surfaces().size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel.surfaces()[i].coverage, before[i].coverage);
}

TEST(Dcaa, MoreSurfacesThanSlotsAllAtOneDepth) {
  DcaaPixel pixel;
  Mask all = 0;
  for (int i = 0; i < 20; ++i) {
    const Mask m = Mask{0x7} << (3 * i);
    all |= m;
    pixel.insert(fragment(i, m, 0.5f, 0.3f * i, {float(i % 2), float(i % 3) / 2, 1}));
  }
  ASSERT_EQ(pixel.surfaces().size(), 4u);
  Mask kept = 0;
  for (const DcaaSurface& s : pixel.surfaces()) kept |= s.coverage;
  EXPECT_EQ(kept, all);  // everything overlaps in depth, so everything is merged, nothing dropped
  const Rgb c = pixel.resolve(dcaa_coverage_pattern(), {0, 0, 0});
  EXPECT_TRUE(finite(c));
}

// Shading surfaces once (dcaa --shade surface): a shader that reads the albedo's red channel
// and the shading normal's x shows what was merged and when it was shaded.
TEST(Dcaa, ShadesSurfacesOnceFromMergedAttributes) {
  const SamplePattern pattern = dcaa_coverage_pattern();
  const DcaaSurfaceShader shader = [](const DcaaSurface& s) { return Rgb{s.albedo.r, s.shading_normal.x, 0.0f}; };
  const auto with_inputs = [](CoverageFragment f, float albedo, float normal_x) {
    f.colour = {};
    f.albedo = {albedo, 0.0f, 0.0f};
    f.shading_normal = normalized({normal_x, 0.0f, 1.0f});
    return f;
  };
  // Two triangles of one surface (aligned facets, disjoint coverage: first merge), 48 and 16
  // samples, albedos within the colour tolerance, shading normals 5.7 degrees apart: albedo weighted 3:1, shading normals averaged and
  // renormalised, shaded once. 22.6 degrees apart (beyond the pi/16 cone: a bevel's normals),
  // each is shaded and the colours are merged.
  for (float x : {0.05f, 0.2f}) {
    DcaaPixel pixel(dcaa_settings("surface"), &pattern, shader);
    pixel.insert(with_inputs(fragment(0, 0x0000'FFFF'FFFF'FFFFull, 0.5f, 0.0f, {}), 0.8f, x));
    EXPECT_EQ(pixel.insert(with_inputs(fragment(1, 0xFFFF'0000'0000'0000ull, 0.5f, 0.0f, {}), 0.76f, -x)),
              DcaaEvent::Merged);
    ASSERT_EQ(pixel.surfaces().size(), 1u);
    const Normal3 a = normalized({x, 0, 1}), b = normalized({-x, 0, 1});
    const Normal3 mean = normalized({0.75f * a.x + 0.25f * b.x, 0.0f, 0.75f * a.z + 0.25f * b.z});
    const bool once = x < 0.1f;
    const Rgb c = pixel.resolve(pattern, {0, 0, 1});
    EXPECT_NEAR(c.r, 0.79f, 1e-6f) << x;
    EXPECT_NEAR(c.g, once ? mean.x : 0.75f * a.x + 0.25f * b.x, 1e-6f) << x;
    EXPECT_EQ(pixel.shading_invocations(pattern), once ? 1 : 2) << x;
  }

  // Five surfaces at different angles in four slots: the second merge shades both surfaces
  // first and merges their colours (a mean normal would light neither); a hidden surface is
  // never shaded.
  DcaaPixel full(dcaa_settings("surface"), &pattern, shader);
  for (int i = 0; i < 4; ++i)
    full.insert(with_inputs(fragment(i, Mask{0xFFFF} << (16 * i), 0.5f, 0.5f * float(i), {}), 0.2f * float(i + 1),
                            0.3f * float(i)));
  EXPECT_EQ(full.insert(with_inputs(fragment(4, 0xFFull, 0.45f, 2.5f, {}), 1.0f, -0.5f)), DcaaEvent::SecondMerge);
  int shaded = 0;
  for (const DcaaSurface& s : full.surfaces()) shaded += s.shaded;
  EXPECT_EQ(shaded, 1);
  EXPECT_EQ(full.shading_invocations(pattern), 2 + 3);  // two at the merge, three at the resolve
}

TEST(Dcaa, IgnoresEmptyAndNonFiniteFragments) {
  DcaaPixel pixel;
  EXPECT_EQ(pixel.insert(fragment(0, 0, 0.5f, 0, {1, 1, 1})), DcaaEvent::Ignored);
  EXPECT_EQ(pixel.insert(fragment(1, 1, std::nanf(""), 0, {1, 1, 1})), DcaaEvent::Ignored);
  EXPECT_EQ(pixel.insert(fragment(2, 1, 0.5f, 0, {std::numeric_limits<float>::infinity(), 0, 0})), DcaaEvent::Ignored);
  CoverageFragment bad_normal = fragment(3, 0xFF, 0.5f, 0, {0.5f, 0.5f, 0.5f});
  bad_normal.normal = {std::nanf(""), 0, 0};
  EXPECT_EQ(pixel.insert(bad_normal), DcaaEvent::Stored);
  EXPECT_TRUE(finite(pixel.resolve(dcaa_coverage_pattern(), {0, 0, 0})));
  // Coverage 0 everywhere: the background.
  const Rgb empty = DcaaPixel().resolve(dcaa_coverage_pattern(), {0.2f, 0.3f, 0.4f});
  EXPECT_FLOAT_EQ(empty.g, 0.3f);
}

TEST(Dcaa, ResolveTestsDepthPerSample) {
  // Two full surfaces whose planes cross at x = 0: each is in front on one half of the pixel.
  const SamplePattern pattern = dcaa_coverage_pattern();
  DcaaSettings settings;
  settings.cos_normal_threshold = 2.0f;  // never merge
  DcaaPixel pixel(settings);
  pixel.insert(fragment(0, ~Mask{0}, 0.5f, 0.0f, {1, 0, 0}, 0.1f));
  pixel.insert(fragment(1, ~Mask{0}, 0.5f, 0.0f, {0, 0, 1}, -0.1f));
  const std::vector<int> counts = pixel.visible_counts(pattern);
  EXPECT_EQ(counts[0], 32);  // red is nearer where x < 0
  EXPECT_EQ(counts[1], 32);
  const Rgb c = pixel.resolve(pattern, {0, 1, 0});
  EXPECT_FLOAT_EQ(c.r, 0.5f);
  EXPECT_FLOAT_EQ(c.g, 0.0f);
}

// Two planes crossing at x = 0 (the wall's face in front where x < 0, a top face in front where
// x > 0), each made of two coplanar parts of different colours, one on each side: only the dark
// parts are visible (the house's plinth flush with a pale slab, AC14-FZK-Haus). Merged across
// colours (the paper; no colour test), each plane gets one mean colour and the hidden parts' light
// shows on half the samples; the surface rules keep the parts apart.
TEST(Dcaa, CoplanarPartsOfDifferentColoursStayApart) {
  const SamplePattern pattern = dcaa_coverage_pattern();
  Mask left = 0;
  for (int s = 0; s < pattern.size(); ++s)
    if (pattern.positions[s].x < 0) left |= Mask{1} << s;
  const Mask right = ~left;
  const Rgb dark{0.1f, 0.1f, 0.1f}, pale{0.6f, 0.6f, 0.6f}, brown{0.38f, 0.38f, 0.34f};
  const auto resolve = [&](const DcaaSettings& settings, std::vector<DcaaEvent>* events) {
    DcaaPixel pixel(settings, &pattern);
    for (const CoverageFragment& f : {fragment(0, left, 0.5f, 0.0f, dark, 0.01f),    // wall, visible
                                      fragment(1, left, 0.5f, 0.6f, pale, -0.01f),   // top, hidden
                                      fragment(2, right, 0.5f, 0.0f, brown, 0.01f),  // wall, hidden
                                      fragment(3, right, 0.5f, 0.6f, dark, -0.01f)})  // top, visible
      events->push_back(pixel.insert(f));
    return pixel.resolve(pattern, {1, 1, 1});
  };
  DcaaSettings across = dcaa_settings("surface");
  across.merge_colour_tolerance = 0.0f;
  std::vector<DcaaEvent> merged, kept;
  const Rgb blended = resolve(across, &merged);
  EXPECT_EQ(merged[2], DcaaEvent::Merged);
  EXPECT_GT(blended.r, 0.2f);  // half the samples show a mean with a hidden part
  const Rgb apart = resolve(dcaa_settings("surface"), &kept);
  EXPECT_EQ(kept[2], DcaaEvent::Stored);
  EXPECT_EQ(kept[3], DcaaEvent::Stored);
  EXPECT_NEAR(apart.r, 0.1f, 1e-5f);
  EXPECT_NEAR(apart.b, 0.1f, 1e-5f);
  // One surface's triangles, shaded at the same pixel centre, still merge.
  DcaaPixel smooth(dcaa_settings("surface"), &pattern);
  smooth.insert(fragment(0, left, 0.5f, 0.0f, {0.50f, 0.40f, 0.30f}, 0.01f));
  EXPECT_EQ(smooth.insert(fragment(1, right, 0.5f, 0.0f, {0.51f, 0.41f, 0.30f}, 0.01f)), DcaaEvent::Merged);
}

// Two slots full (dynamic coverage's surface rules): a near surface showing 12 of 16 samples, a
// floor just behind it covering all 16 (its depth interval overlaps the near one's) and showing
// 4, then a third surface in front of 2 of those 4. The floor shows the fewest and goes into the
// near surface. Weighted by coverage (16 against 12), the floor's light would take over the
// merged colour although it shows 2 samples; weighted by the samples each shows, the resolve is
// the per-sample answer exactly: 12 dark, 2 floor, 2 third.
TEST(Dcaa, SecondMergeWeightsBySamplesShown) {
  const SamplePattern& pattern = dynamic_coverage_pattern();
  const Rgb dark{0.1f, 0.1f, 0.1f}, floor_colour{0.8f, 0.8f, 0.8f}, third{0.4f, 0.4f, 0.4f};
  // DCAA's rule for full slots (the least visible goes into the most overlapping surface); dynamic
  // coverage's least-change rule weights its merges by samples shown too.
  DcaaSettings least_visible = dynamic_coverage_surface_settings();
  least_visible.second_merge_least_change = false;
  const auto resolve = [&](const DcaaSettings& settings) {
    DcaaPixel pixel(settings, &pattern);
    pixel.insert(fragment(0, 0x0FFF, 0.300f, 0.0f, dark, 0.02f));
    pixel.insert(fragment(1, 0xFFFF, 0.305f, 0.6f, floor_colour, 0.02f));
    EXPECT_EQ(pixel.insert(fragment(2, 0x3000, 0.2f, 1.2f, third)), DcaaEvent::SecondMerge);
    return pixel.resolve(pattern, {0, 0, 0});
  };
  const float exact = (12 * 0.1f + 2 * 0.8f + 2 * 0.4f) / 16;
  EXPECT_NEAR(resolve(least_visible).r, exact, 1e-5f);
  EXPECT_NEAR(resolve(dynamic_coverage_surface_settings()).r, exact, 1e-5f);
  DcaaSettings by_coverage = least_visible;
  by_coverage.second_merge_by_visible = false;
  EXPECT_GT(resolve(by_coverage).r, exact + 0.2f);
}

// ---- The worked example of the dynamic coverage seed --------------------------------------
//
// The seed gives the colours each method outputs for one pixel, not its geometry. These
// triangles (pixel space) and colours reproduce every triple: purple (217, 210, 233) in front
// covers the centre, green (217, 233, 212) behind, white background; display values averaged
// as the seed does. Areas: purple 0.532, green visible 0.327, background 0.141.
const Vec2 kPurple[3] = {{-1.815, -1.616}, {1.635, 1.394}, {-0.483, 0.684}};
const Vec2 kGreen[3] = {{0.396, -1.498}, {1.644, -1.422}, {-0.824, 1.528}};
const Rgb kPurpleColour{217, 210, 233}, kGreenColour{217, 233, 212}, kWhite{255, 255, 255};

bool inside(const Vec2 (&t)[3], Vec2 p) {
  const double o = cross(t[1] - t[0], t[2] - t[0]);
  for (int e = 0; e < 3; ++e)
    if (!(o * cross(t[(e + 1) % 3] - t[e], p - t[e]) > 0)) return false;
  return true;
}

// The seed's multisample pseudo-code: per sample, the nearest covering triangle (purple is
// nearer), else the clear colour.
Rgb multisample(const std::vector<Vec2>& samples) {
  Rgb sum;
  for (Vec2 p : samples) {
    const Rgb c = inside(kPurple, p) ? kPurpleColour : inside(kGreen, p) ? kGreenColour : kWhite;
    sum.r += c.r, sum.g += c.g, sum.b += c.b;
  }
  const float n = float(samples.size());
  return {sum.r / n, sum.g / n, sum.b / n};
}

void expect_display(Rgb c, int r, int g, int b) {
  EXPECT_EQ(std::lround(c.r), r);
  EXPECT_EQ(std::lround(c.g), g);
  EXPECT_EQ(std::lround(c.b), b);
}

CoverageFragment triangle_fragment(const HalfPlaneLut& lut, const Vec2 (&t)[3], std::uint32_t order, float depth, Rgb c) {
  CoverageFragment f;
  f.order = order;
  f.coverage = lut.triangle_coverage(t[0], t[1], t[2]);
  f.depth = {depth, 0, 0};
  f.colour = c;
  return f;
}

TEST(WorkedExample, NoAaSupersampleAndMultisampleTriples) {
  expect_display(multisample({{0, 0}}), 217, 210, 233);                                                   // no AA
  expect_display(multisample({{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}}), 217, 216, 228);  // 4x SSAA grid
  expect_display(multisample(builtin_pattern("d3d4x").positions), 227, 227, 233);                           // 4x MSAA
}

TEST(WorkedExample, DynamicCoverageTripleInEitherOrder) {
  const HalfPlaneLut lut(builtin_pattern("d3d16x"));
  const CoverageFragment purple = triangle_fragment(lut, kPurple, 1, 0.3f, kPurpleColour);
  const CoverageFragment green = triangle_fragment(lut, kGreen, 0, 0.6f, kGreenColour);
  EXPECT_EQ(similar_count(purple.coverage), 8);
  EXPECT_EQ(similar_count(green.coverage & ~purple.coverage), 5);
  for (bool green_first : {true, false}) {
    DynamicCoveragePixel pixel(kWhite, DynamicCoverageRules::Seed);
    pixel.insert(green_first ? green : purple);
    pixel.insert(green_first ? purple : green);
    expect_display(pixel.resolve(), 217, 219, 225);
  }
}

TEST(WorkedExample, DcaaIsCloseToTheCorrectValue) {
  // The seed's "theoretically correct" (221, 223, 228) is for its own geometry; ours has
  // slightly different areas: exact value 0.532 P + 0.327 G + 0.141 W = (222.4, 223.9, 229.2).
  const HalfPlaneLut lut(dcaa_coverage_pattern());
  DcaaPixel pixel;
  pixel.insert(triangle_fragment(lut, kGreen, 0, 0.6f, kGreenColour));
  pixel.insert(triangle_fragment(lut, kPurple, 1, 0.3f, kPurpleColour));
  const Rgb c = pixel.resolve(lut.pattern(), kWhite);
  EXPECT_NEAR(c.r, 222.4, 1.5);
  EXPECT_NEAR(c.g, 223.9, 1.5);
  EXPECT_NEAR(c.b, 229.2, 1.5);
}

// ---- Dynamic coverage: evict rules -----------------------------------------------------

TEST(DynamicCoverage, EvictsTheFartherSlot) {
  DynamicCoveragePixel p({0, 0, 0}, DynamicCoverageRules::Seed);
  EXPECT_TRUE(p.insert(fragment(0, 0x00FF, 0.5f, 0, {1, 0, 0})));  // both slots at 1: slot 0
  EXPECT_EQ(p.mask[0], 0x00FF);
  EXPECT_TRUE(p.insert(fragment(1, 0x0FF0, 0.7f, 0, {0, 1, 0})));  // slot 1 (at 1) is farther
  EXPECT_EQ(p.mask[1], 0x0FF0);
  EXPECT_FALSE(p.insert(fragment(2, 0xFFFF, 0.9f, 0, {0, 0, 1})));  // behind both: dropped
  EXPECT_TRUE(p.insert(fragment(3, 0xF000, 0.6f, 0, {0, 0, 1})));   // closer than slot 1: evicts it
  EXPECT_EQ(p.mask[1], 0xF000);
  EXPECT_FLOAT_EQ(p.depth[1], 0.6f);
  // Resolve: nearer (slot 0) with its 8 bits, slot 1 with its 4 bits not under slot 0; TCC 12.
  const Rgb c = p.resolve();
  EXPECT_FLOAT_EQ(c.r, 8.0f / 12.0f);
  EXPECT_FLOAT_EQ(c.b, 4.0f / 12.0f);
}

TEST(DynamicCoverage, TiesZeroCoverageAndNonFiniteInput) {
  DynamicCoveragePixel p({0.5f, 0.5f, 0.5f}, DynamicCoverageRules::Seed);
  EXPECT_FALSE(p.insert(fragment(0, 0, 0.2f, 0, {1, 0, 0})));            // no coverage sample: ignored
  EXPECT_FALSE(p.insert(fragment(1, 0xFF, std::nanf(""), 0, {1, 0, 0})));
  EXPECT_FALSE(p.insert(fragment(2, 0xFF, 0.2f, 0, {std::nanf(""), 0, 0})));
  EXPECT_TRUE(p.insert(fragment(3, 0xFF, 0.4f, 0, {1, 0, 0})));
  EXPECT_TRUE(p.insert(fragment(4, 0xFF00, 0.4f, 0, {0, 1, 0})));         // ties slot 1 at 1.0: closer
  EXPECT_FALSE(p.insert(fragment(5, 0xFFFF, 0.4f, 0, {0, 0, 1})));        // equal to both: not closer
  EXPECT_TRUE(finite(p.resolve()));
  // Equal slot depths: the seed's else-branch picks slot 1 as "nearer" in the resolve.
  const Rgb c = p.resolve();
  EXPECT_FLOAT_EQ(c.r + c.g, 1.0f);
  // TCC = 0 cannot arise from insert(); forced, the nearer colour is output.
  p.mask[0] = p.mask[1] = 0;
  EXPECT_TRUE(finite(p.resolve()));
  // Many overlaps with equal coverage: the last two that were closer than a slot win.
  DynamicCoveragePixel many({0, 0, 0}, DynamicCoverageRules::Seed);
  for (int i = 0; i < 10; ++i) many.insert(fragment(i, 0x0F0F, 0.9f - 0.05f * i, 0, {float(i), 0, 0}));
  EXPECT_FLOAT_EQ(std::max(many.colour[0].r, many.colour[1].r), 9.0f);
  EXPECT_FLOAT_EQ(std::min(many.colour[0].r, many.colour[1].r), 8.0f);
}

// Depths that differ by float rounding only are ties in all three comparisons: the third
// triangle of a surface whose first two hold both slots, at depths a few float steps apart in
// either order, is dropped (the literal float comparison would evict one of them, and which one
// depends on those last bits); the resolve takes slot 1 as the nearer, as on exact ties. A
// difference beyond the bound still counts.
TEST(DynamicCoverage, DepthsWithinFloatRoundingAreTies) {
  const float d = 0.93f, step = std::nextafter(d, 1.0f) - d;  // 2^-24 near 0.93
  ASSERT_LT(4.0f * step, kSeedDepthTie);
  for (float second : {d + 3.0f * step, d - 3.0f * step}) {
    DynamicCoveragePixel p({1, 1, 1}, DynamicCoverageRules::Seed);
    EXPECT_TRUE(p.insert(fragment(0, 0x00FF, d, 0, {1, 0, 0})));       // slot 0
    EXPECT_TRUE(p.insert(fragment(1, 0x0FF0, second, 0, {0, 1, 0})));  // slot 1 (at 1: farther)
    EXPECT_FALSE(p.insert(fragment(2, 0xF000, d + step, 0, {0, 0, 1})));
    EXPECT_FALSE(p.insert(fragment(3, 0xF000, d - step, 0, {0, 0, 1})));
    EXPECT_EQ(p.mask[0], 0x00FF);
    EXPECT_EQ(p.mask[1], 0x0FF0);
    // Nearer: slot 1 with its 8 samples, slot 0 with the 4 of its 8 slot 1 does not cover; TCC 12.
    const Rgb c = p.resolve();
    EXPECT_FLOAT_EQ(c.g, 8.0f / 12.0f);
    EXPECT_FLOAT_EQ(c.r, 4.0f / 12.0f);
  }
  // Beyond the bound: closer than slot 1, which is the farther and is evicted.
  DynamicCoveragePixel p({1, 1, 1}, DynamicCoverageRules::Seed);
  p.insert(fragment(0, 0x00FF, d, 0, {1, 0, 0}));
  p.insert(fragment(1, 0x0FF0, d + 2.0f * kSeedDepthTie, 0, {0, 1, 0}));
  EXPECT_TRUE(p.insert(fragment(2, 0xF000, d + 0.5f * kSeedDepthTie, 0, {0, 0, 1})));
  EXPECT_EQ(p.mask[1], 0xF000);
  EXPECT_FLOAT_EQ(p.resolve().r, 8.0f / 12.0f);  // slot 0 is the nearer beyond the bound
}

// ---- Dynamic coverage: surface rules -----------------------------------------------------

TEST(DynamicCoverageSurface, TwoTrianglesOfOneSurfaceShareASlotAndTheBackgroundStays) {
  // A tessellated surface: three triangles of one plane (same normal, continuous depth) cover
  // 12 of 16 samples; the seed rules lose the background and stretch the last two triangles over
  // all 16 samples, the surface rules keep one merged slot and the background on the other 4.
  const Rgb grey{0.5f, 0.5f, 0.5f}, black{0, 0, 0};
  const CoverageFragment a = fragment(0, 0x000F, 0.50f, 0, grey, 0.01f), b = fragment(1, 0x00F0, 0.50f, 0, grey, 0.01f),
                         c = fragment(2, 0x0F00, 0.50f, 0, grey, 0.01f);
  DynamicCoveragePixel surface(black, DynamicCoverageRules::Surface), seed(black, DynamicCoverageRules::Seed);
  for (const CoverageFragment& f : {a, b, c}) surface.insert(f), seed.insert(f);
  ASSERT_EQ(surface.surfaces().size(), 1u);
  EXPECT_EQ(surface.surfaces()[0].coverage, 0x0FFFu);
  EXPECT_FLOAT_EQ(surface.resolve().r, 0.5f * 12.0f / 16.0f);  // the exact coverage-weighted value
  EXPECT_FLOAT_EQ(seed.resolve().r, 0.5f);                     // background lost
}

TEST(DynamicCoverageSurface, DifferentSurfacesTakeTheEmptySlotsThenTheLeastVisibleGoes) {
  const Rgb black{0, 0, 0};
  DynamicCoveragePixel p(black, DynamicCoverageRules::Surface);
  EXPECT_TRUE(p.insert(fragment(0, 0x00FF, 0.3f, 0.0f, {1, 0, 0})));       // front, 8 samples
  EXPECT_TRUE(p.insert(fragment(1, 0x3FF0, 0.6f, 1.0f, {0, 1, 0})));       // behind: 6 visible
  ASSERT_EQ(p.surfaces().size(), 2u);
  // A third surface far behind both with 2 visible samples: the least visible, nothing overlaps
  // its depth: dropped.
  EXPECT_TRUE(p.insert(fragment(2, 0xC00F, 0.9f, 0.5f, {0, 0, 1})));
  ASSERT_EQ(p.surfaces().size(), 2u);
  // Resolve: front 8/16 red, the back surface's 6 samples not under it green, 2 background.
  EXPECT_FLOAT_EQ(p.resolve().b, 0.0f);
  EXPECT_FLOAT_EQ(p.resolve().r, 0.5f);
  EXPECT_FLOAT_EQ(p.resolve().g, 6.0f / 16.0f);
  // A one-sample fragment in front of both: counted per sample it shows 1 sample against the
  // back surface's 5, so it is the one that goes (DCAA's coarse rule never drops the front-most).
  EXPECT_TRUE(p.insert(fragment(3, 0x0100, 0.1f, 2.0f, {0, 0, 1})));
  ASSERT_EQ(p.surfaces().size(), 2u);
  EXPECT_FLOAT_EQ(p.resolve().b, 0.0f);
  EXPECT_FLOAT_EQ(p.resolve().r, 0.5f);
  EXPECT_FLOAT_EQ(p.resolve().g, 6.0f / 16.0f);
}

TEST(DynamicCoverageSurface, AHiddenFragmentDrawnFirstGivesWayAndACreaseMergesIntoItsNeighbour) {
  const Rgb black{0, 0, 0};
  DynamicCoveragePixel p(black, DynamicCoverageRules::Surface);
  p.insert(fragment(0, 0x0FFF, 0.9f, 0.0f, {0, 0, 1}));                 // hidden by what follows
  p.insert(fragment(1, 0x00FF, 0.2f, 0.0f, {1, 0, 0}, 0.02f));           // front surface
  p.insert(fragment(2, 0x0F00, 0.2f, 0.6f, {0, 1, 0}, 0.02f));           // a crease: normal 34 deg apart
  // Full: the hidden blue one has no visible sample left and goes; the crease's two facets stay.
  ASSERT_EQ(p.surfaces().size(), 2u);
  EXPECT_FLOAT_EQ(p.resolve().b, 0.0f);
  EXPECT_FLOAT_EQ(p.resolve().r, 0.5f);
  EXPECT_FLOAT_EQ(p.resolve().g, 0.25f);
  // A third facet of the crease (its own normal, nearly the red facet's colour) covering 2 more
  // samples: merged into the red one instead of dropped, so its samples stay covered (no
  // background dot).
  p.insert(fragment(3, 0x3000, 0.2f, -0.6f, {0.9f, 0.05f, 0}, 0.02f));
  ASSERT_EQ(p.surfaces().size(), 2u);
  EXPECT_EQ(p.surfaces()[0].coverage | p.surfaces()[1].coverage, 0x3FFFu);
  EXPECT_EQ(p.surfaces()[0].coverage, 0x30FFu);
}

// The least-change rule (DcaaSettings::second_merge_least_change, dynamic coverage's default),
// found on a character model (X/BCN_Epileptic.X): the far side of a limb, two facets whose normals
// differ beyond the first merge's cone, fills both slots around the front surface's first small
// fragment. Removing the least visible candidate dropped that fragment (3 samples shown against
// 6 and 7), and its samples showed the far side; merging the two far facets changes no colour,
// so the front keeps its slot and its later fragments merge into it.
TEST(DynamicCoverageSurface, TwoFacetsOfOneHiddenSurfaceShareASlotRatherThanPushOutTheFront) {
  const Rgb black{0, 0, 0}, front{0.06f, 0.06f, 0.06f}, back{0.42f, 0.42f, 0.42f};
  const auto resolve = [&](const DcaaSettings& settings) {
    DcaaPixel pixel(settings, &dynamic_coverage_pattern());
    pixel.insert(fragment(0, 0x0007, 0.30f, 0.00f, front, 0.002f));  // front, 3 samples
    pixel.insert(fragment(1, 0x00FF, 0.50f, 0.20f, back, 0.002f));   // far side, facet 1
    pixel.insert(fragment(2, 0xFF00, 0.50f, -0.20f, back, 0.002f));  // far side, facet 2 (23 deg)
    pixel.insert(fragment(3, 0xFFF8, 0.30f, 0.05f, front, 0.002f));  // the rest of the front
    return pixel.resolve(dynamic_coverage_pattern(), black);
  };
  EXPECT_NEAR(resolve(dynamic_coverage_surface_settings()).r, front.r, 1e-6f);
  DcaaSettings least_visible = dynamic_coverage_surface_settings();
  least_visible.second_merge_least_change = false;
  EXPECT_NEAR(resolve(least_visible).r, (13 * front.r + 3 * back.r) / 16, 1e-6f);
  // The rule needs per-sample visibility.
  DcaaSettings coarse = least_visible;
  coarse.per_sample_visibility = false, coarse.second_merge_least_change = true;
  EXPECT_THROW(DcaaPixel(coarse, &dynamic_coverage_pattern()), std::invalid_argument);
}

TEST(DynamicCoverageSurface, ZeroCoverageNonFiniteAndEmpty) {
  const Rgb clear{0.25f, 0.5f, 0.75f};
  DynamicCoveragePixel p(clear, DynamicCoverageRules::Surface);
  EXPECT_FLOAT_EQ(p.resolve().b, 0.75f);                                          // no fragment: the background
  EXPECT_FALSE(p.insert(fragment(0, 0x10000, 0.2f, 0, {1, 0, 0})));              // covers none of the 16 samples
  EXPECT_FALSE(p.insert(fragment(1, 0xFF, std::nanf(""), 0, {1, 0, 0})));
  EXPECT_FALSE(p.insert(fragment(2, 0xFF, 0.2f, 0, {0, std::nanf(""), 0})));
  EXPECT_TRUE(p.surfaces().empty());
  // Everything at one depth with one normal, in two colours: one surface per colour (fragments of
  // one surface agree in colour), the colours averaged by coverage.
  for (int i = 0; i < 16; ++i) p.insert(fragment(3 + i, Mask(1) << i, 0.5f, 0, {float(i % 2), 0, 0}));
  ASSERT_EQ(p.surfaces().size(), 2u);
  EXPECT_NEAR(p.resolve().r, 0.5f, 1e-6f);
  EXPECT_TRUE(finite(p.resolve()));
  EXPECT_THROW(dynamic_coverage_rules("evict"), std::invalid_argument);
}

TEST(WorkedExample, DynamicCoverageSurfaceRulesKeepTheBackground) {
  // The seed's example under the surface rules: the purple and green triangles are different
  // surfaces (different depths), so both keep a slot and the 3 samples neither covers show the
  // white background: 8 purple + 5 green + 3 white over 16, closer to the area-weighted value
  // (222.4, 223.9, 229.2) than the seed's (217, 219, 225).
  const HalfPlaneLut lut(builtin_pattern("d3d16x"));
  DynamicCoveragePixel pixel(kWhite, DynamicCoverageRules::Surface);
  pixel.insert(triangle_fragment(lut, kGreen, 0, 0.6f, kGreenColour));
  pixel.insert(triangle_fragment(lut, kPurple, 1, 0.3f, kPurpleColour));
  const Rgb c = pixel.resolve();
  EXPECT_NEAR(c.r, (8 * kPurpleColour.r + 5 * kGreenColour.r + 3 * kWhite.r) / 16, 1e-3);
  EXPECT_NEAR(c.g, (8 * kPurpleColour.g + 5 * kGreenColour.g + 3 * kWhite.g) / 16, 1e-3);
  EXPECT_NEAR(c.b, (8 * kPurpleColour.b + 5 * kGreenColour.b + 3 * kWhite.b) / 16, 1e-3);
}


TEST(DynamicCoverageSurface, APlaneCrossingAnotherWinsTheSamplesWhereItIsInFront) {
  // A fin on a body: the body at depth 0.5 covers all 16 samples; the fin's plane is in front on
  // the left (x < -1/6) and, extrapolated to the centre, behind (0.55). It covers the samples
  // left of x = -0.2. Per sample the fin shows on all of them; the seed orders the two slots by
  // their depth at the centre and gives every sample to the body.
  const SamplePattern& pattern = dynamic_coverage_pattern();
  Mask left = 0;
  for (int s = 0; s < pattern.size(); ++s)
    if (pattern.positions[s].x < -0.2) left |= Mask(1) << s;
  ASSERT_GT(similar_count(left), 0);
  const CoverageFragment body = fragment(0, 0xFFFF, 0.5f, 0.0f, {1, 0, 0});
  const CoverageFragment fin = fragment(1, left, 0.55f, 1.2f, {0, 1, 0}, 0.3f);
  DynamicCoveragePixel surface({0, 0, 0}, DynamicCoverageRules::Surface), seed({0, 0, 0}, DynamicCoverageRules::Seed);
  for (const CoverageFragment& f : {body, fin}) surface.insert(f), seed.insert(f);
  EXPECT_FLOAT_EQ(surface.resolve().g, float(similar_count(left)) / 16.0f);
  EXPECT_FLOAT_EQ(seed.resolve().g, 0.0f);
}

TEST(DynamicCoverageSurface, AHiddenSurfaceIsDroppedNotBlendedIntoAVisibleOne) {
  // Both slots full with visible surfaces; a third one, behind the front slot everywhere it
  // covers but overlapping its depth interval (the far side of a thin fin), shows no sample.
  // DCAA's paper rule merges it into the front slot (its colour bleeds in); the surface rules
  // drop it.
  const auto run = [](DcaaSettings settings) {
    DcaaPixel p(settings, &dynamic_coverage_pattern());
    p.insert(fragment(0, 0x00FF, 0.50f, 0.0f, {1, 0, 0}, 0.02f));
    p.insert(fragment(1, 0xFF00, 0.80f, 1.0f, {0, 1, 0}));
    p.insert(fragment(2, 0x000F, 0.51f, kPi, {0, 0, 1}, 0.02f));  // facing away, 0.01 behind
    return p.resolve(dynamic_coverage_pattern(), {0, 0, 0});
  };
  DcaaSettings paper;
  paper.max_surfaces = 2;
  EXPECT_GT(run(paper).b, 0.0f);
  EXPECT_FLOAT_EQ(run(dynamic_coverage_surface_settings()).b, 0.0f);
  EXPECT_FLOAT_EQ(run(dynamic_coverage_surface_settings()).r, 0.5f);
  EXPECT_THROW(DcaaPixel{dynamic_coverage_surface_settings()}, std::invalid_argument);  // needs the samples
}


TEST(DynamicCoverageSurface, CrossingLayersAtASmallAngleStayApart) {
  // Two planes 6 degrees apart crossing at the pixel centre, both covering all 16 samples: the
  // normal and depth tests alone call them one surface (DCAA merges them and the crossing line
  // is lost); they cover the same samples, so the surface rules keep two slots and the resolve
  // gives each the samples where it is in front.
  const CoverageFragment a = fragment(0, 0xFFFF, 0.5f, 0.0f, {1, 0, 0}, 0.01f);
  const CoverageFragment b = fragment(1, 0xFFFF, 0.5f, 0.1f, {0, 1, 0}, -0.01f);
  DcaaSettings paper;
  paper.max_surfaces = 2;
  DcaaPixel merged(paper);
  for (const CoverageFragment& f : {a, b}) merged.insert(f);
  EXPECT_EQ(merged.surfaces().size(), 1u);
  DynamicCoveragePixel p({0, 0, 0}, DynamicCoverageRules::Surface);
  for (const CoverageFragment& f : {a, b}) p.insert(f);
  ASSERT_EQ(p.surfaces().size(), 2u);
  int right = 0;  // samples at x > 0, where b (falling with x) is in front
  for (const Vec2& s : dynamic_coverage_pattern().positions) right += s.x > 0;
  EXPECT_FLOAT_EQ(p.resolve().g, float(right) / 16.0f);
}

}  // namespace
}  // namespace rsaa
