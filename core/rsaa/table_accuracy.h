// Accuracy of an offset table on a case set (docs/conventions.md section 2): case error = estimate
// at the table's offset - exact coverage, summarised per case kind, per source rule, and beside two
// baselines on the same cases (zero offset = no anti-aliasing; the fallback rule everywhere).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/rsaa/case_set.h"
#include "core/rsaa/offset_table.h"

namespace rsaa {

struct ErrorStats {
  std::uint64_t count = 0;
  double rms = 0.0;
  double mean_abs = 0.0;
  double p95_abs = 0.0;         // 95th percentile of |error|
  double share_over_1_16 = 0.0;  // fraction of cases with |error| > 1/16
};

ErrorStats error_stats(std::vector<double> errors);

// Case subsets reported: one-line cases, two-line cases, and all (the 50/50 mix).
enum CaseKind { kOneLine = 0, kTwoLine = 1, kMix = 2, kCaseKindCount = 3 };
const char* to_string(CaseKind kind);  // "one-line", "two-line", "mix"

struct TableAccuracy {
  std::array<ErrorStats, kCaseKindCount> table{};
  std::array<ErrorStats, kCaseKindCount> zero_offset{};
  std::array<ErrorStats, kCaseKindCount> fallback_rule{};
  // Table errors of the cases whose mask entry came from each rule ([source][kind]).
  std::array<std::array<ErrorStats, kCaseKindCount>, kOffsetSourceCount> by_source{};
};

// The estimate of one case at an offset, and its error against the exact coverage.
double case_error(const CaseRecord& c, Vec2 offset);

TableAccuracy evaluate_table(const OffsetTable& table, const std::vector<CaseRecord>& cases);

}  // namespace rsaa
