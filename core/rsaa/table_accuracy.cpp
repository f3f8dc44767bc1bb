#include "core/rsaa/table_accuracy.h"

#include <algorithm>
#include <cmath>

#include "core/rsaa/bilinear.h"
#include "core/rsaa/fallback.h"

namespace rsaa {

ErrorStats error_stats(std::vector<double> errors) {
  ErrorStats s;
  s.count = errors.size();
  if (errors.empty()) return s;
  double squares = 0.0, absolutes = 0.0;
  std::uint64_t over = 0;
  for (double& e : errors) {
    squares += e * e;
    e = std::abs(e);
    absolutes += e;
    over += e > 1.0 / 16.0;
  }
  const double n = double(errors.size());
  s.rms = std::sqrt(squares / n);
  s.mean_abs = absolutes / n;
  s.share_over_1_16 = double(over) / n;
  // Nearest-rank 95th percentile.
  const std::size_t rank = std::size_t(std::ceil(0.95 * n)) - 1;
  std::nth_element(errors.begin(), errors.begin() + rank, errors.end());
  s.p95_abs = errors[rank];
  return s;
}

const char* to_string(CaseKind kind) {
  switch (kind) {
    case kOneLine: return "one-line";
    case kTwoLine: return "two-line";
    default: return "mix";
  }
}

double case_error(const CaseRecord& c, Vec2 offset) {
  return bilinear_estimate(Neighbourhood3x3::from_binary_code(c.neighbourhood), offset.x,
                           offset.y) -
         c.coverage;
}

TableAccuracy evaluate_table(const OffsetTable& table, const std::vector<CaseRecord>& cases) {
  using Errors = std::array<std::vector<double>, kCaseKindCount>;
  Errors by_table, by_zero, by_fallback;
  std::array<Errors, kOffsetSourceCount> by_source;
  std::vector<Vec2> fallback(table.offsets.size());
  for (std::size_t m = 0; m < fallback.size(); ++m) fallback[m] = fallback_offset(table.pattern, m);

  for (const CaseRecord& c : cases) {
    if (c.mask >= table.offsets.size())
      throw std::invalid_argument("case mask " + std::to_string(c.mask) +
                                  " is outside the table of pattern " + table.pattern.name);
    const int kind = c.line_count == 1 ? kOneLine : kTwoLine;
    const double e = case_error(c, table.offsets[c.mask]);
    const double e_zero = case_error(c, {0.0, 0.0});
    const double e_fallback = case_error(c, fallback[c.mask]);
    auto& source = by_source[static_cast<int>(table.sources[c.mask])];
    for (int k : {kind, int(kMix)}) {
      by_table[k].push_back(e);
      by_zero[k].push_back(e_zero);
      by_fallback[k].push_back(e_fallback);
      source[k].push_back(e);
    }
  }
  TableAccuracy a;
  for (int k = 0; k < kCaseKindCount; ++k) {
    a.table[k] = error_stats(std::move(by_table[k]));
    a.zero_offset[k] = error_stats(std::move(by_zero[k]));
    a.fallback_rule[k] = error_stats(std::move(by_fallback[k]));
    for (int s = 0; s < kOffsetSourceCount; ++s) a.by_source[s][k] = error_stats(std::move(by_source[s][k]));
  }
  return a;
}

}  // namespace rsaa
