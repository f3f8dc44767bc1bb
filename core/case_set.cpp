#include "core/case_set.h"

namespace rsaa {

CaseRecord make_case_record(const LineCase& line_case, const SamplePattern& pattern) {
  CaseRecord r;
  r.mask = line_case.mask(pattern);
  r.coverage = line_case.coverage();
  r.neighbourhood = line_case.neighbourhood().binary_code();
  r.line_count = static_cast<std::uint8_t>(line_case.line_count);
  return r;
}

std::vector<CaseRecord> generate_cases(const SamplePattern& pattern, std::uint64_t count,
                                       std::uint64_t seed, int threads,
                                       const ProgressFn& progress) {
  std::vector<CaseRecord> cases(count);
  parallel_for(
      count, 1 << 14, threads,
      [&](std::uint64_t begin, std::uint64_t end) {
        for (std::uint64_t i = begin; i < end; ++i)
          cases[i] = make_case_record(draw_line_case(seed, i, line_count_of_case(i)), pattern);
      },
      progress);
  return cases;
}

}  // namespace rsaa
