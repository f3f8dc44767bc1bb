#include "trainer/train.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/case_set.h"
#include "core/fallback.h"
#include "trainer/offset_fit.h"

namespace rsaa {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Offsets are stored rounded to 1e-6 px so that JSON, GLSL and HLSL carry the same decimals.
double round_offset(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

}  // namespace

std::vector<MaskCases> group_cases_by_mask(const std::vector<CaseRecord>& cases) {
  // Sort (key, index) pairs: the index breaks ties, so sums run in case order whatever the
  // thread count that made the cases.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseRecord& c = cases[i];
    keyed[i] = {(c.mask << 10) | (std::uint64_t(c.line_count - 1) << 9) | c.neighbourhood,
                std::uint32_t(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<MaskCases> out;
  for (std::size_t i = 0; i < keyed.size();) {
    const CaseRecord& first = cases[keyed[i].second];
    if (out.empty() || out.back().mask != first.mask) out.push_back({first.mask, {0, 0}, {}});
    MaskCases::Group g{first.line_count, first.neighbourhood, 0, 0.0};
    std::size_t j = i;
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) {
      ++g.count;
      g.coverage_sum += cases[keyed[j].second].coverage;
    }
    out.back().count[g.line_count - 1] += g.count;
    out.back().groups.push_back(g);
    i = j;
  }
  return out;
}

std::array<double, 2> case_weights(const MaskCases& m, const TrainOptions& options) {
  if (options.fit == FitRule::Ockham) {
    const bool one_line_explains = m.count[0] > 0;
    return {one_line_explains ? 1.0 : 0.0, one_line_explains ? 0.0 : 1.0};
  }
  const std::array<double, 2> w = {2.0 * (1.0 - options.two_line_weight),
                                   2.0 * options.two_line_weight};
  // A weight that leaves the mask no case (w = 0 or 1, only the other kind present) falls back
  // to the kind it has, as ockham would.
  if ((m.count[0] == 0 || w[0] == 0.0) && (m.count[1] == 0 || w[1] == 0.0))
    return {m.count[0] > 0 ? 1.0 : 0.0, m.count[0] > 0 ? 0.0 : 1.0};
  return w;
}

std::vector<FitCase> grouped_fit_cases(const MaskCases& m, const TrainOptions& options) {
  const std::array<double, 2> weight = case_weights(m, options);
  std::vector<FitCase> out;
  for (const auto& g : m.groups) {
    const double w = weight[g.line_count - 1];
    if (w > 0.0)
      out.push_back({Neighbourhood3x3::from_binary_code(g.neighbourhood),
                     g.coverage_sum / double(g.count), w * double(g.count)});
  }
  return out;
}

const char* to_string(FitRule rule) { return rule == FitRule::Ockham ? "ockham" : "mixed"; }

std::string train_command(const TrainOptions& o) {
  std::ostringstream s;
  s << "rsaa train --pattern " << o.pattern.name << " --cases " << o.cases << " --seed " << o.seed
    << " --fit " << to_string(o.fit);
  if (o.fit == FitRule::Mixed) s << " --two-line-weight " << o.two_line_weight;
  return s.str();
}

TrainReport train_offset_table(const TrainOptions& options, const TrainProgress& progress) {
  if (options.cases == 0) throw std::invalid_argument("--cases must be at least 1");
  if (options.cases > (std::uint64_t{1} << 32))
    throw std::invalid_argument("--cases must be at most 2^32");
  if (!(options.two_line_weight >= 0.0 && options.two_line_weight <= 1.0))
    throw std::invalid_argument("--two-line-weight must be within [0, 1]");

  TrainReport report;
  report.table = fallback_table(options.pattern);  // throws for patterns too big for a table
  OffsetTable& table = report.table;
  const auto stage = [&](const char* name) {
    if (progress.stage) progress.stage(name);
  };

  auto start = std::chrono::steady_clock::now();
  stage("generating cases");
  const std::vector<CaseRecord> cases =
      generate_cases(options.pattern, options.cases, options.seed, options.threads, progress.step);
  report.generate_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  stage("grouping cases by mask");
  const std::vector<MaskCases> masks = group_cases_by_mask(cases);
  const Mask all_similar = options.pattern.all_similar();
  std::vector<Vec2> fitted(masks.size());
  stage("fitting offsets");
  parallel_for(
      masks.size(), 1, options.threads,
      [&](std::uint64_t begin, std::uint64_t end) {
        for (std::uint64_t k = begin; k < end; ++k)
          if (masks[k].mask != all_similar) fitted[k] = fit_offset(grouped_fit_cases(masks[k], options)).offset;
      },
      progress.step);
  report.fit_seconds = seconds_since(start);

  for (std::size_t k = 0; k < masks.size(); ++k) {
    const MaskCases& m = masks[k];
    const OffsetSource source = m.count[0] > 0 ? OffsetSource::OneLine : OffsetSource::TwoLine;
    table.sources[m.mask] = source;
    table.cases_per_mask[m.mask] = m.count[0] + m.count[1];
    // The all-similar mask stays (0, 0): the post-process leaves pixels without an edge alone.
    table.offsets[m.mask] = m.mask == all_similar
                                ? Vec2{0.0, 0.0}
                                : Vec2{round_offset(fitted[k].x), round_offset(fitted[k].y)};
  }
  for (std::size_t m = 0; m < table.offsets.size(); ++m) {
    if (table.sources[m] == OffsetSource::Fallback)
      table.offsets[m] = {round_offset(table.offsets[m].x), round_offset(table.offsets[m].y)};
    ++report.masks_by_source[static_cast<int>(table.sources[m])];
  }

  table.training = {
      {"command", train_command(options)},
      {"cases", options.cases},
      {"seed", options.seed},
      {"fit", to_string(options.fit)},
      {"case_distribution", "docs/conventions.md section 2; even case indices one-line, odd two-line"},
      {"masks_one_line", report.masks_by_source[0]},
      {"masks_two_line", report.masks_by_source[1]},
      {"masks_fallback", report.masks_by_source[2]},
      {"offset_rounding_px", 1e-6},
  };
  if (options.fit == FitRule::Mixed) table.training["two_line_weight"] = options.two_line_weight;

  stage("measuring the table on its training cases");
  report.training_accuracy = evaluate_table(table, cases);
  return report;
}

}  // namespace rsaa
