#include "trainer/train.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/rsaa/bilinear.h"
#include "core/rsaa/case_set.h"
#include "core/rsaa/fallback.h"
#include "trainer/offset_fit.h"

namespace rsaa {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Offsets are stored rounded to 1e-6 px so that JSON, GLSL and HLSL carry the same decimals.
double round_offset(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

// Sum over a group's cases of (estimate - coverage_i)^2, from its sums.
double squared_error_sum(const MaskCases::Group& g, double estimate) {
  return double(g.count) * estimate * estimate - 2.0 * estimate * g.coverage_sum +
         g.coverage_square_sum;
}

TrainingError training_error(const OffsetTable& table, const std::vector<MaskCases>& masks) {
  std::array<double, kCaseKindCount> table_sum{};
  std::array<std::array<double, kCaseKindCount>, kOffsetSourceCount> source_sum{};
  TrainingError out;
  for (const MaskCases& m : masks) {
    const int source = static_cast<int>(table.sources[m.mask]);
    const Vec2 d = table.offsets[m.mask];
    for (const MaskCases::Group& g : m.groups) {
      const Neighbourhood3x3 n = Neighbourhood3x3::from_binary_code(g.neighbourhood);
      // Cancellation can leave a tiny negative sum where every case is matched exactly.
      const double e2 = std::max(0.0, squared_error_sum(g, bilinear_estimate(n, d.x, d.y)));
      for (int k : {g.line_count == 1 ? int(kOneLine) : int(kTwoLine), int(kMix)}) {
        table_sum[k] += e2;
        source_sum[source][k] += e2;
        out.table[k].count += g.count;
        out.by_source[source][k].count += g.count;
      }
    }
  }
  const auto rms = [](double sum, std::uint64_t n) { return n ? std::sqrt(sum / double(n)) : 0.0; };
  for (int k = 0; k < kCaseKindCount; ++k) {
    out.table[k].rms = rms(table_sum[k], out.table[k].count);
    for (int s = 0; s < kOffsetSourceCount; ++s)
      out.by_source[s][k].rms = rms(source_sum[s][k], out.by_source[s][k].count);
  }
  return out;
}

}  // namespace

void CaseGroups::add(const CaseRecord& c) {
  Sums& s = sums_[(c.mask << 10) | (std::uint64_t(c.line_count - 1) << 9) | c.neighbourhood];
  ++s.count;
  s.coverage_sum += c.coverage;
  s.coverage_square_sum += c.coverage * c.coverage;
}

std::vector<MaskCases> CaseGroups::by_mask() const {
  std::vector<std::pair<std::uint64_t, Sums>> sorted(sums_.begin(), sums_.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<MaskCases> out;
  for (const auto& [key, s] : sorted) {
    const Mask mask = key >> 10;
    const int line_count = int((key >> 9) & 1) + 1;
    if (out.empty() || out.back().mask != mask) out.push_back({mask, {0, 0}, {}});
    out.back().count[line_count - 1] += s.count;
    out.back().groups.push_back({line_count, std::uint16_t(key & 0x1ff), s.count, s.coverage_sum,
                                 s.coverage_square_sum});
  }
  return out;
}

std::vector<MaskCases> group_cases_by_mask(const std::vector<CaseRecord>& cases) {
  CaseGroups groups;
  for (const CaseRecord& c : cases) groups.add(c);
  return groups.by_mask();
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
  s << "rsaa train --pattern " << o.pattern.name;
  if (o.pattern.name.rfind("custom-", 0) == 0) {  // a custom pattern is only reproducible with its positions
    s << " --positions \"";
    for (std::size_t i = 0; i < o.pattern.positions.size(); ++i)
      s << (i ? " " : "") << o.pattern.positions[i].x << "," << o.pattern.positions[i].y;
    s << "\"";
  }
  s << " --cases " << o.cases << " --seed " << o.seed << " --fit " << to_string(o.fit);
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
  stage("generating cases and merging them by mask and neighbourhood");
  CaseGroups groups;
  // Blocks of 2^20 cases (24 MiB): large enough that the threads stay busy, and merged in case
  // order, so the sums do not depend on the thread count.
  for_each_case_block(
      options.pattern, options.cases, options.seed, options.threads, std::uint64_t{1} << 20,
      [&](const std::vector<CaseRecord>& block) {
        for (const CaseRecord& c : block) groups.add(c);
      },
      progress.step);
  report.case_groups = groups.group_count();
  report.generate_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  const std::vector<MaskCases> masks = groups.by_mask();
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

  report.training_error = training_error(table, masks);
  return report;
}

}  // namespace rsaa
