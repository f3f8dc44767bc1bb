// Case sets: the line cases of docs/conventions.md section 2 reduced to what training and
// evaluation use.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/rsaa/line_case.h"
#include "core/util/parallel.h"

namespace rsaa {

struct CaseRecord {
  Mask mask = 0;
  double coverage = 0.0;
  std::uint16_t neighbourhood = 0;  // Neighbourhood3x3::binary_code()
  std::uint8_t line_count = 1;
};

CaseRecord make_case_record(const LineCase& line_case, const SamplePattern& pattern);

// Cases 0 .. count-1 of `seed` (half one-line, half two-line, alternating), generated on
// `threads` threads; identical for any thread count.
std::vector<CaseRecord> generate_cases(const SamplePattern& pattern, std::uint64_t count,
                                       std::uint64_t seed, int threads = 0,
                                       const ProgressFn& progress = nullptr);

// The same cases handed to `consume` in index order, at most `block` at a time (each block
// generated on `threads` threads), so that memory does not grow with `count`.
void for_each_case_block(const SamplePattern& pattern, std::uint64_t count, std::uint64_t seed,
                         int threads, std::uint64_t block,
                         const std::function<void(const std::vector<CaseRecord>&)>& consume,
                         const ProgressFn& progress = nullptr);

}  // namespace rsaa
