// The trainer end to end: determinism, the masks one line can make, table structure, options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/rsaa/case_set.h"
#include "core/rsaa/table_accuracy.h"
#include "trainer/offset_fit.h"
#include "trainer/train.h"

namespace rsaa {
namespace {

TrainOptions options_for(const std::string& pattern, std::uint64_t cases) {
  TrainOptions o;
  o.pattern = builtin_pattern(pattern);
  o.cases = cases;
  return o;
}

TEST(Trainer, SameSeedGivesIdenticalFilesWhateverTheThreadCount) {
  TrainOptions o = options_for("d3d8x", 30000);
  o.threads = 1;
  const OffsetTable one = train_offset_table(o).table;
  o.threads = 2;
  const OffsetTable two = train_offset_table(o).table;
  o.threads = 5;
  const OffsetTable five = train_offset_table(o).table;
  EXPECT_EQ(offset_table_json(one), offset_table_json(two));
  EXPECT_EQ(offset_table_json(one), offset_table_json(five));
  EXPECT_EQ(offset_table_glsl(one), offset_table_glsl(two));
  EXPECT_EQ(offset_table_hlsl(one), offset_table_hlsl(two));
  o.seed = 2;
  EXPECT_NE(offset_table_json(train_offset_table(o).table), offset_table_json(one));
}

// The streaming path against the way the trainer worked before it: all cases in memory, sorted
// by (mask, line count, neighbourhood, index), summed in that order.
TEST(Trainer, MergingCasesAsTheyArriveEqualsSortingThemAllToTheBit) {
  const SamplePattern p = builtin_pattern("d3d16x");
  const std::vector<CaseRecord> cases = generate_cases(p, 50001, 9);
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  for (std::size_t i = 0; i < cases.size(); ++i)
    keyed.push_back({(cases[i].mask << 10) | (std::uint64_t(cases[i].line_count - 1) << 9) |
                         cases[i].neighbourhood, i});
  std::sort(keyed.begin(), keyed.end());
  std::vector<MaskCases::Group> expected;
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    const CaseRecord& c = cases[keyed[i].second];
    if (i == 0 || keyed[i].first != keyed[i - 1].first)
      expected.push_back({c.line_count, c.neighbourhood, 0, 0.0, 0.0});
    ++expected.back().count;
    expected.back().coverage_sum += c.coverage;
  }
  for (int threads : {1, 3})
    for (std::uint64_t block : {std::uint64_t{1000}, std::uint64_t{1} << 20}) {
      CaseGroups groups;
      for_each_case_block(p, cases.size(), 9, threads, block, [&](const std::vector<CaseRecord>& b) {
        for (const CaseRecord& c : b) groups.add(c);
      });
      std::vector<MaskCases::Group> got;
      for (const MaskCases& m : groups.by_mask())
        for (const MaskCases::Group& g : m.groups) got.push_back(g);
      ASSERT_EQ(got.size(), expected.size());
      for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].line_count, expected[i].line_count);
        EXPECT_EQ(got[i].neighbourhood, expected[i].neighbourhood);
        EXPECT_EQ(got[i].count, expected[i].count);
        EXPECT_EQ(got[i].coverage_sum, expected[i].coverage_sum) << "group " << i;  // bits, not near
      }
    }
}

TEST(Trainer, TrainingErrorFromMergedCasesEqualsTheCaseByCaseRms) {
  const TrainOptions o = options_for("d3d8x", 60000);
  const TrainReport r = train_offset_table(o);
  const TableAccuracy a = evaluate_table(r.table, generate_cases(o.pattern, o.cases, o.seed));
  for (int k = 0; k < kCaseKindCount; ++k) {
    EXPECT_EQ(r.training_error.table[k].count, a.table[k].count);
    EXPECT_NEAR(r.training_error.table[k].rms, a.table[k].rms, 1e-12) << to_string(CaseKind(k));
    for (int s = 0; s < kOffsetSourceCount; ++s) {
      EXPECT_EQ(r.training_error.by_source[s][k].count, a.by_source[s][k].count);
      EXPECT_NEAR(r.training_error.by_source[s][k].rms, a.by_source[s][k].rms, 1e-12);
    }
  }
}

// Every mask one line can make: lines just beside each line through two of the points
// (subsamples and centre), turned and shifted a little either way.
std::set<Mask> one_line_masks_by_enumeration(const SamplePattern& p) {
  std::vector<Vec2> points = p.positions;
  points.push_back({0.0, 0.0});
  std::set<Mask> masks = {p.all_similar()};
  for (std::size_t a = 0; a < points.size(); ++a)
    for (std::size_t b = a + 1; b < points.size(); ++b) {
      const Vec2 d = points[b] - points[a];
      const double angle = std::atan2(d.y, d.x);
      const Vec2 normal{-d.y / length(d), d.x / length(d)};
      for (const Vec2 pivot : {points[a], points[b], 0.5 * (points[a] + points[b])})
        for (double turn : {-1e-6, 0.0, 1e-6})
          for (double shift : {-1e-7, 1e-7}) {
            LineCase c;
            c.lines[0] = {pivot + shift * normal, angle + turn};
            if (c.lines[0].side({0, 0}) != 0.0) masks.insert(c.mask(p));
          }
    }
  return masks;
}

TEST(Trainer, OneLineMasksAreExactlyThoseOneLineCanMake) {
  const SamplePattern p = builtin_pattern("d3d8x");
  const std::set<Mask> expected = one_line_masks_by_enumeration(p);
  // 9 points in general position allow C(9,2) + 1 = 37 splits; the centre lies on the segment
  // between subsamples 0 (1,-3) and 1 (-1,3), which removes two.
  EXPECT_EQ(expected.size(), 35u);
  std::set<Mask> found;
  for (const CaseRecord& c : generate_cases(p, 1000000, 1))
    if (c.line_count == 1) found.insert(c.mask);
  EXPECT_EQ(found, expected);
}

TEST(Trainer, TableStructure) {
  const TrainOptions o = options_for("d3d8x", 40000);
  const TrainReport r = train_offset_table(o);
  const OffsetTable& t = r.table;
  ASSERT_EQ(t.offsets.size(), 256u);
  EXPECT_EQ(t.offsets[255], (Vec2{0.0, 0.0}));
  std::uint64_t total = 0;
  for (std::size_t m = 0; m < 256; ++m) {
    total += t.cases_per_mask[m];
    EXPECT_EQ(t.sources[m] == OffsetSource::Fallback, t.cases_per_mask[m] == 0) << m;
    EXPECT_LE(std::abs(t.offsets[m].x), 1.0);
    EXPECT_LE(std::abs(t.offsets[m].y), 1.0);
    EXPECT_EQ(std::round(t.offsets[m].x * 1e6) / 1e6, t.offsets[m].x);
  }
  EXPECT_EQ(total, 40000u);
  EXPECT_EQ(r.masks_by_source[0] + r.masks_by_source[1] + r.masks_by_source[2], 256u);
  EXPECT_EQ(t.training.at("command"),
            "rsaa train --pattern d3d8x --cases 40000 --seed 1 --fit mixed --two-line-weight 0.5");
}

TEST(Trainer, SixteenSamplesFitsOnlyReachedMasks) {
  const TrainReport r = train_offset_table(options_for("d3d16x", 20000));
  EXPECT_EQ(r.table.offsets.size(), 65536u);
  EXPECT_GT(r.masks_by_source[2], 60000u);  // most masks are never reached: fallback
  EXPECT_GT(r.masks_by_source[0] + r.masks_by_source[1], 100u);
}

TEST(Trainer, RejectsBadOptions) {
  TrainOptions o = options_for("d3d4x", 0);
  EXPECT_THROW(train_offset_table(o), std::invalid_argument);
  o.cases = 100;
  o.two_line_weight = 1.5;
  EXPECT_THROW(train_offset_table(o), std::invalid_argument);
  o.two_line_weight = std::nan("");
  EXPECT_THROW(train_offset_table(o), std::invalid_argument);
  o.two_line_weight = 0.5;
  std::vector<Vec2> seventeen;
  for (int i = 0; i < 17; ++i) seventeen.push_back({-0.4 + 0.05 * i, 0.03 * (i % 5)});
  o.pattern = pattern_from_positions("custom-17", seventeen);  // more samples than a table takes
  EXPECT_THROW(train_offset_table(o), std::invalid_argument);
}

TEST(Trainer, MixedFitTradesALittleOneLineErrorForLessTwoLineError) {
  // The measurement behind the default fit (README): held-out cases, seed 2.
  TrainOptions o = options_for("d3d8x", 200000);
  const auto held_out = generate_cases(o.pattern, 200000, 2);
  o.fit = FitRule::Ockham;
  const TableAccuracy ockham = evaluate_table(train_offset_table(o).table, held_out);
  o.fit = FitRule::Mixed;
  const TableAccuracy mixed = evaluate_table(train_offset_table(o).table, held_out);
  EXPECT_LT(mixed.table[kTwoLine].rms, 0.95 * ockham.table[kTwoLine].rms);
  EXPECT_LT(mixed.table[kMix].rms, ockham.table[kMix].rms);
  EXPECT_GE(mixed.table[kOneLine].rms, ockham.table[kOneLine].rms);
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

TEST(TrainerExtremes, LineExactlyThroughASubsampleLeavesItDissimilar) {
  const SamplePattern p = builtin_pattern("d3d8x");
  for (int s = 0; s < p.size(); ++s) {
    LineCase c;
    c.lines[0] = {p.positions[s], 0.3};  // through subsample s, not through the centre
    ASSERT_NE(c.lines[0].side({0, 0}), 0.0);
    EXPECT_FALSE(is_similar(c.mask(p), s)) << "a point on the line belongs to no cell";
  }
}

TEST(TrainerExtremes, CoincidentAndNearlyParallelLines) {
  LineCase one;
  one.lines[0] = {{0.2, 0.1}, 1.0};
  LineCase twice = one;
  twice.line_count = 2;
  twice.lines[1] = one.lines[0];
  EXPECT_NEAR(twice.coverage(), one.coverage(), 1e-15);
  EXPECT_EQ(twice.mask(builtin_pattern("d3d8x")), one.mask(builtin_pattern("d3d8x")));
  for (double d : {1e-3, 1e-9, 1e-15}) {
    LineCase wedge;
    wedge.line_count = 2;
    wedge.lines[0] = {{0.3, 0.0}, d};
    wedge.lines[1] = {{-0.3, 0.0}, M_PI - d};  // crossing far outside the pixel
    const double c = wedge.coverage();
    EXPECT_TRUE(std::isfinite(c));
    EXPECT_GE(c, 0.0);
    EXPECT_LE(c, 1.0);
  }
}

TEST(TrainerExtremes, AMaskWithOneCaseGetsAFiniteBoundedOffset) {
  const FitCase only{Neighbourhood3x3::from_binary_code(0x1ff & ~(1u << 5)), 0.7, 1.0};
  const OffsetFit fit = fit_offset({only});
  EXPECT_TRUE(is_finite(fit.offset));
  EXPECT_LE(std::abs(fit.offset.x), 1.0);
  EXPECT_LE(std::abs(fit.offset.y), 1.0);
  EXPECT_NEAR(fit.cost, 0.0, 1e-12);  // one case can be matched exactly
  EXPECT_TRUE(is_finite(fit_offset({}).offset));  // no case at all: (0, 0), no crash
}

TEST(TrainerExtremes, FloatEstimatesAgreeWithDouble) {
  // The GL post-process works in float; the trainer in double.
  const OffsetTable t = train_offset_table(options_for("d3d8x", 20000)).table;
  double worst = 0.0;
  for (const CaseRecord& c : generate_cases(t.pattern, 100000, 77)) {
    const Neighbourhood3x3 n = Neighbourhood3x3::from_binary_code(c.neighbourhood);
    const Vec2 d = t.offsets[c.mask];
    const float fx = float(d.x), fy = float(d.y);
    const float as_float =
        bilinear_in_cell<float>(n, bilinear_cell_of(fx), bilinear_cell_of(fy), fx, fy);
    worst = std::max(worst, std::abs(double(as_float) - bilinear_estimate(n, d.x, d.y)));
  }
  EXPECT_LT(worst, 1e-6);
}

}  // namespace
}  // namespace rsaa
