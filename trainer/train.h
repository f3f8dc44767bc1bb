// The trainer: line cases -> cases grouped by mask -> one fitted offset per mask -> a table.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/rsaa/case_set.h"
#include "core/rsaa/offset_table.h"
#include "core/util/parallel.h"
#include "core/rsaa/sample_pattern.h"
#include "core/rsaa/table_accuracy.h"
#include "trainer/offset_fit.h"

namespace rsaa {

// Which cases a mask's offset is fitted on.
//  ockham: the paper's rule. If a single line produces the mask, its one-line cases only;
//          otherwise its two-line cases.
//  mixed:  all cases of the mask, a one-line case weighted 2(1 - w), a two-line case 2w
//          (w = two_line_weight). With the 50/50 training set, w = 0.5 minimises the expected
//          error on the 50/50 mix; w -> 0 tends to ockham.
enum class FitRule { Ockham, Mixed };
const char* to_string(FitRule rule);

struct TrainOptions {
  SamplePattern pattern;
  std::uint64_t cases = 1000000;
  std::uint64_t seed = 1;
  FitRule fit = FitRule::Mixed;
  double two_line_weight = 0.5;
  int threads = 0;  // 0 = all cores; never changes the result
};

// The command that reproduces a table, written into its header.
std::string train_command(const TrainOptions& options);

struct TrainProgress {
  std::function<void(const std::string& stage)> stage;
  ProgressFn step;
};

// The RMS error of a table on its own training cases, from the merged groups (the cases are not
// kept; `rsaa eval-table` gives the other statistics on a case set).
struct TrainingError {
  struct Rms {
    std::uint64_t count = 0;
    double rms = 0.0;
  };
  std::array<Rms, kCaseKindCount> table{};
  // Cases whose mask entry came from each rule ([source][kind]).
  std::array<std::array<Rms, kCaseKindCount>, kOffsetSourceCount> by_source{};
};

struct TrainReport {
  OffsetTable table;
  // Masks by rule: produced by one line / only by two lines / by no case (fallback).
  std::array<std::uint64_t, 3> masks_by_source{};
  std::uint64_t case_groups = 0;  // distinct (mask, line count, neighbourhood): what memory holds
  double generate_seconds = 0.0;  // generating and merging the cases
  double fit_seconds = 0.0;
  TrainingError training_error;
};

// The cases of one mask merged by (line count, neighbourhood): count and coverage sums per group.
struct MaskCases {
  Mask mask = 0;
  std::uint64_t count[2] = {0, 0};  // one-line, two-line cases
  struct Group {
    int line_count;
    std::uint16_t neighbourhood;
    std::uint64_t count;
    double coverage_sum;
    double coverage_square_sum;  // for the training error without the cases
  };
  std::vector<Group> groups;
};

// Cases merged into groups as they arrive: memory grows with the number of distinct (mask, line
// count, neighbourhood), not with the number of cases. A group's sums run in the order its cases
// are added, so adding them in case-index order gives the same bits whatever thread count made
// them.
class CaseGroups {
 public:
  void add(const CaseRecord& c);
  std::size_t group_count() const { return sums_.size(); }
  // Sorted by mask; each mask's groups sorted by (line count, neighbourhood).
  std::vector<MaskCases> by_mask() const;

 private:
  struct Sums {
    std::uint64_t count = 0;
    double coverage_sum = 0.0, coverage_square_sum = 0.0;
  };
  std::unordered_map<std::uint64_t, Sums> sums_;  // key: mask << 10 | (line count - 1) << 9 | code
};

// CaseGroups of `cases` added in order.
std::vector<MaskCases> group_cases_by_mask(const std::vector<CaseRecord>& cases);

// The weight of one one-line case and of one two-line case of this mask in its fit.
std::array<double, 2> case_weights(const MaskCases& mask_cases, const TrainOptions& options);

// The fit's input: one FitCase per group, weight = case weight x count, coverage = group mean.
// Minimising over these equals minimising over the individual cases (tested).
std::vector<FitCase> grouped_fit_cases(const MaskCases& mask_cases, const TrainOptions& options);

// Throws std::invalid_argument for bad options (no cases, weight outside [0, 1], pattern too big).
TrainReport train_offset_table(const TrainOptions& options, const TrainProgress& progress = {});

}  // namespace rsaa
