#include "core/rsaa/case_set.h"

#include <algorithm>

namespace rsaa {
namespace {

// Cases first .. first + cases.size() - 1 into `cases`.
void fill_cases(const SamplePattern& pattern, std::uint64_t first, std::uint64_t seed, int threads,
                std::vector<CaseRecord>& cases, const ProgressFn& progress) {
  parallel_for(
      cases.size(), 1 << 14, threads,
      [&](std::uint64_t begin, std::uint64_t end) {
        for (std::uint64_t i = begin; i < end; ++i)
          cases[i] = make_case_record(
              draw_line_case(seed, first + i, line_count_of_case(first + i)), pattern);
      },
      progress);
}

}  // namespace

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
  fill_cases(pattern, 0, seed, threads, cases, progress);
  return cases;
}

void for_each_case_block(const SamplePattern& pattern, std::uint64_t count, std::uint64_t seed,
                         int threads, std::uint64_t block,
                         const std::function<void(const std::vector<CaseRecord>&)>& consume,
                         const ProgressFn& progress) {
  block = std::max<std::uint64_t>(block, 1);
  std::vector<CaseRecord> cases;
  for (std::uint64_t first = 0; first < count; first += block) {
    cases.resize(std::min(block, count - first));
    ProgressFn step;
    if (progress)
      step = [&](std::uint64_t done, std::uint64_t) { progress(first + done, count); };
    fill_cases(pattern, first, seed, threads, cases, step);
    consume(cases);
  }
}

}  // namespace rsaa
