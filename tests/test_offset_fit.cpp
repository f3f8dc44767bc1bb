// The Ceres fit against brute force, and merged cases against individual ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/rsaa/case_set.h"
#include "trainer/offset_fit.h"
#include "trainer/train.h"

namespace rsaa {
namespace {

class OffsetFitTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    options_ = new TrainOptions;
    options_->pattern = builtin_pattern("d3d8x");
    cases_ = new std::vector<CaseRecord>(generate_cases(options_->pattern, 60000, 11));
    masks_ = new std::vector<MaskCases>(group_cases_by_mask(*cases_));
  }
  static void TearDownTestSuite() {
    delete options_;
    delete cases_;
    delete masks_;
  }

  // Masks with enough cases to be meaningful: the most frequent few of each kind.
  static std::vector<const MaskCases*> sample_masks() {
    std::vector<const MaskCases*> one_line, two_line;
    for (const MaskCases& m : *masks_) {
      if (m.mask == options_->pattern.all_similar()) continue;
      (m.count[0] > 0 ? one_line : two_line).push_back(&m);
    }
    const auto by_count = [](const MaskCases* a, const MaskCases* b) {
      return a->count[0] + a->count[1] > b->count[0] + b->count[1];
    };
    std::sort(one_line.begin(), one_line.end(), by_count);
    std::sort(two_line.begin(), two_line.end(), by_count);
    std::vector<const MaskCases*> out(one_line.begin(), one_line.begin() + 4);
    out.insert(out.end(), two_line.begin(), two_line.begin() + 3);
    out.push_back(two_line.back());  // a rare mask, few cases
    return out;
  }

  static TrainOptions* options_;
  static std::vector<CaseRecord>* cases_;
  static std::vector<MaskCases>* masks_;
};

TrainOptions* OffsetFitTest::options_ = nullptr;
std::vector<CaseRecord>* OffsetFitTest::cases_ = nullptr;
std::vector<MaskCases>* OffsetFitTest::masks_ = nullptr;

TEST_F(OffsetFitTest, CeresEqualsDenseGridSearch) {
  for (FitRule rule : {FitRule::Mixed, FitRule::Ockham}) {
    TrainOptions options = *options_;
    options.fit = rule;
    for (const MaskCases* m : sample_masks()) {
      const std::vector<FitCase> fit_cases = grouped_fit_cases(*m, options);
      const OffsetFit ceres = fit_offset(fit_cases);
      const OffsetFit grid = grid_search_offset(fit_cases);
      std::printf("mask %3llu: %zu neighbourhood groups, Ceres (%.5f, %.5f), grid (%.5f, %.5f)\n",
                  static_cast<unsigned long long>(m->mask), fit_cases.size(), ceres.offset.x,
                  ceres.offset.y, grid.offset.x, grid.offset.y);
      EXPECT_LE(ceres.cost, grid.cost + 1e-9 * (1.0 + grid.cost)) << "mask " << m->mask;
      // With few distinct neighbourhoods the minimum can be a whole curve of offsets (zero
      // cost); there only the cost can be compared.
      if (fit_cases.size() < 3) continue;
      EXPECT_NEAR(ceres.offset.x, grid.offset.x, 1e-3) << "mask " << m->mask;
      EXPECT_NEAR(ceres.offset.y, grid.offset.y, 1e-3) << "mask " << m->mask;
      EXPECT_LE(std::abs(ceres.offset.x), 1.0);
      EXPECT_LE(std::abs(ceres.offset.y), 1.0);
    }
  }
}

TEST_F(OffsetFitTest, MergedCasesGiveTheSameOffsetAsIndividualCases) {
  for (const MaskCases* m : sample_masks()) {
    const std::array<double, 2> weight = case_weights(*m, *options_);
    std::vector<FitCase> individual;
    for (const CaseRecord& c : *cases_)
      if (c.mask == m->mask && weight[c.line_count - 1] > 0.0)
        individual.push_back({Neighbourhood3x3::from_binary_code(c.neighbourhood), c.coverage,
                              weight[c.line_count - 1]});
    const OffsetFit a = fit_offset(individual);
    const OffsetFit b = fit_offset(grouped_fit_cases(*m, *options_));
    EXPECT_NEAR(a.offset.x, b.offset.x, 1e-6) << "mask " << m->mask;
    EXPECT_NEAR(a.offset.y, b.offset.y, 1e-6) << "mask " << m->mask;
  }
}

TEST(OffsetFit, ExactlyRepresentableCoverageIsRecovered) {
  // Two cases sharing an offset that reproduces both exactly: right neighbour black with
  // coverage 0.7 (needs fx (1 - fy) = 0.3) and the lower neighbour black with coverage 0.9
  // (needs (1 - fx) fy = 0.1) -> fx = 0.3 + ..., solved by the fit to zero cost.
  Neighbourhood3x3 right = Neighbourhood3x3::from_binary_code(0x1ff & ~(1u << 5));
  Neighbourhood3x3 below = Neighbourhood3x3::from_binary_code(0x1ff & ~(1u << 7));
  const std::vector<FitCase> cases = {{right, 0.7, 1.0}, {below, 0.9, 1.0}};
  const OffsetFit fit = fit_offset(cases);
  EXPECT_NEAR(fit.cost, 0.0, 1e-12);
  const double fx = fit.offset.x, fy = fit.offset.y;
  EXPECT_NEAR(fx * (1 - fy), 0.3, 1e-6);
  EXPECT_NEAR((1 - fx) * fy, 0.1, 1e-6);
}

TEST(OffsetFit, WeightsAreTheDocumentedRules) {
  MaskCases both;
  both.count[0] = 10;
  both.count[1] = 5;
  MaskCases two_only;
  two_only.count[1] = 5;
  TrainOptions o;
  o.fit = FitRule::Ockham;
  EXPECT_EQ(case_weights(both, o), (std::array<double, 2>{1.0, 0.0}));
  EXPECT_EQ(case_weights(two_only, o), (std::array<double, 2>{0.0, 1.0}));
  o.fit = FitRule::Mixed;
  o.two_line_weight = 0.25;
  EXPECT_EQ(case_weights(both, o), (std::array<double, 2>{1.5, 0.5}));
  o.two_line_weight = 0.0;
  EXPECT_EQ(case_weights(two_only, o), (std::array<double, 2>{0.0, 1.0}));
}

}  // namespace
}  // namespace rsaa
