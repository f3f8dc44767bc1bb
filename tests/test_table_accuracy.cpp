// Accuracy statistics against closed forms, and the checked-in tables against the baselines.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rsaa/case_set.h"
#include "core/rsaa/table_accuracy.h"

namespace rsaa {
namespace {

TEST(ErrorStats, ClosedForms) {
  std::vector<double> e;
  for (int i = 1; i <= 100; ++i) e.push_back(i % 2 ? i / 100.0 : -i / 100.0);
  const ErrorStats s = error_stats(e);
  EXPECT_EQ(s.count, 100u);
  EXPECT_NEAR(s.mean_abs, 0.505, 1e-12);
  EXPECT_NEAR(s.rms, std::sqrt(338350.0 / 1e4 / 100.0), 1e-12);  // sum of i^2 = 338350
  EXPECT_DOUBLE_EQ(s.p95_abs, 0.95);
  EXPECT_DOUBLE_EQ(s.share_over_1_16, 94.0 / 100.0);  // 0.07 .. 1.00
  EXPECT_EQ(error_stats({}).count, 0u);
}

TEST(CaseError, ZeroOffsetErrorIsOneMinusCoverage) {
  for (const CaseRecord& c : generate_cases(builtin_pattern("d3d4x"), 200, 4))
    EXPECT_DOUBLE_EQ(case_error(c, {0, 0}), 1.0 - c.coverage);
}

class CheckedInTableAccuracy : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckedInTableAccuracy, ClearlyBeatsBothBaselinesOnFreshCases) {
  const OffsetTable t =
      read_offset_table(std::string(RSAA_SOURCE_DIR) + "/tables/" + GetParam() + ".json");
  const TableAccuracy a = evaluate_table(t, generate_cases(t.pattern, 40000, 12345));
  for (int k = 0; k < kCaseKindCount; ++k) {
    EXPECT_LT(a.table[k].rms, 0.9 * a.fallback_rule[k].rms) << to_string(CaseKind(k));
    EXPECT_LT(a.table[k].rms, 0.3 * a.zero_offset[k].rms) << to_string(CaseKind(k));
  }
}

INSTANTIATE_TEST_SUITE_P(Tables, CheckedInTableAccuracy,
                         ::testing::Values("d3d4x", "d3d8x", "d3d16x", "custom-gl4x-union", "custom-gl4x-wide",
                                           "custom-gl4x-tall", "custom-gl4x-quad"));

}  // namespace
}  // namespace rsaa
