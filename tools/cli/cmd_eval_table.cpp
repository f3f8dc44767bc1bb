// rsaa eval-table: accuracy of a table on fresh line cases, beside two baselines.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/case_set.h"
#include "core/table_accuracy.h"
#include "tools/cli/commands.h"
#include "tools/cli/progress.h"

namespace rsaa::cli {
namespace {

struct EvalArgs {
  std::string file;
  std::uint64_t cases = 1000000;
  std::uint64_t seed = 2;
  bool json = false;
  int threads = 0;
};

nlohmann::json stats_json(const ErrorStats& s) {
  return {{"cases", s.count},     {"rms", s.rms},
          {"mean_abs", s.mean_abs}, {"p95_abs", s.p95_abs},
          {"share_over_1_16", s.share_over_1_16}};
}

void print_row(const char* label, const ErrorStats& s) {
  if (s.count == 0) {
    std::printf("    %-26s %9s %9s %9s %9s\n", label, "-", "-", "-", "-");
    return;
  }
  std::printf("    %-26s %9.5f %9.5f %9.5f %8.2f%%\n", label, s.rms, s.mean_abs, s.p95_abs,
              100.0 * s.share_over_1_16);
}

int run_eval(const EvalArgs& a) {
  const OffsetTable table = read_offset_table(a.file);
  const auto seed_it = table.training.find("seed");
  if (seed_it != table.training.end() && seed_it->is_number_unsigned() &&
      seed_it->get<std::uint64_t>() == a.seed)
    std::fprintf(stderr,
                 "rsaa eval-table: warning: --seed %llu is the table's training seed: these are "
                 "its training cases, not fresh ones\n",
                 static_cast<unsigned long long>(a.seed));
  ProgressPrinter printer(a.json);
  printer.stage("generating " + std::to_string(a.cases) + " cases");
  const auto cases = generate_cases(table.pattern, a.cases, a.seed, a.threads,
                                    [&](std::uint64_t d, std::uint64_t t) { printer.step(d, t); });
  const TableAccuracy acc = evaluate_table(table, cases);

  if (a.json) {
    nlohmann::json out = {{"table", a.file},
                          {"pattern", table.pattern.name},
                          {"cases", a.cases},
                          {"seed", a.seed},
                          {"training", table.training}};
    for (int k = 0; k < kCaseKindCount; ++k) {
      out["results"][to_string(CaseKind(k))] = {
          {"table", stats_json(acc.table[k])},
          {"zero_offset", stats_json(acc.zero_offset[k])},
          {"fallback_rule", stats_json(acc.fallback_rule[k])}};
      for (int s = 0; s < 3; ++s)
        out["by_source"][to_string(OffsetSource(s))][to_string(CaseKind(k))] =
            stats_json(acc.by_source[s][k]);
    }
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }

  const auto command = table.training.find("command");
  std::printf("table %s: pattern %s, made by: %s\n", a.file.c_str(), table.pattern.name.c_str(),
              command != table.training.end() && command->is_string()
                  ? command->get<std::string>().c_str()
                  : "(unknown)");
  std::printf("fresh cases: %llu (seed %llu), %llu one-line, %llu two-line\n",
              static_cast<unsigned long long>(a.cases), static_cast<unsigned long long>(a.seed),
              static_cast<unsigned long long>(acc.table[kOneLine].count),
              static_cast<unsigned long long>(acc.table[kTwoLine].count));
  std::printf("error = bilinear estimate - exact coverage\n");
  std::printf("    %-26s %9s %9s %9s %9s\n", "", "RMS", "mean|e|", "p95|e|", ">1/16");
  for (int k = 0; k < kCaseKindCount; ++k) {
    std::printf("  %s cases%s\n", to_string(CaseKind(k)), k == kMix ? " (50/50)" : "");
    print_row("table", acc.table[k]);
    print_row("zero offset (no AA)", acc.zero_offset[k]);
    print_row("fallback rule", acc.fallback_rule[k]);
  }
  std::printf("  table error by the rule behind each case's mask entry (50/50 mix)\n");
  for (int s = 0; s < 3; ++s) {
    const ErrorStats& st = acc.by_source[s][kMix];
    const std::string label = std::string(to_string(OffsetSource(s))) + " (" +
                              std::to_string(st.count) + " cases)";
    print_row(label.c_str(), st);
  }
  return 0;
}

}  // namespace

Action add_eval_table_command(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand(
      "eval-table", "Accuracy of an offset table on fresh line cases (RMS, mean |error|, 95th "
                    "percentile, share > 1/16), beside the zero-offset and fallback baselines");
  cmd->add_option("file", args->file, "Table file (JSON)")->required();
  cmd->add_option("--cases", args->cases, "Number of fresh cases, half one-line, half two-line")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 32));
  cmd->add_option("--seed", args->seed, "Seed of the fresh cases (use one the trainer did not)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->add_option("--threads", args->threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  return [args] { return run_eval(*args); };
}

}  // namespace rsaa::cli
