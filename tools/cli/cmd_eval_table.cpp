// rsaa eval-table: accuracy of tables on fresh line cases, beside two baselines. Several tables
// of one pattern are measured on the same cases and printed side by side.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "core/util/printable.h"
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/rsaa/case_set.h"
#include "core/rsaa/table_accuracy.h"
#include "core/util/parallel.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/progress.h"

namespace rsaa::cli {
namespace {

struct EvalArgs {
  std::vector<std::string> files;
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

nlohmann::json accuracy_json(const std::string& file, const OffsetTable& table,
                             const TableAccuracy& acc) {
  nlohmann::json out = {{"table", file}, {"pattern", table.pattern.name},
                        {"training", table.training}};
  for (int k = 0; k < kCaseKindCount; ++k) {
    out["results"][to_string(CaseKind(k))] = {{"table", stats_json(acc.table[k])},
                                              {"zero_offset", stats_json(acc.zero_offset[k])},
                                              {"fallback_rule", stats_json(acc.fallback_rule[k])}};
    for (int s = 0; s < kOffsetSourceCount; ++s)
      out["by_source"][to_string(OffsetSource(s))][to_string(CaseKind(k))] =
          stats_json(acc.by_source[s][k]);
  }
  return out;
}

std::string made_by(const OffsetTable& table) {
  const auto command = table.training.find("command");
  return command != table.training.end() && command->is_string() ? printable(command->get<std::string>())
                                                                   : "(unknown)";
}

void print_row(const std::string& label, const ErrorStats& s) {
  if (s.count == 0) {
    std::printf("    %-26s %9s %9s %9s %9s\n", label.c_str(), "-", "-", "-", "-");
    return;
  }
  std::printf("    %-26s %9.5f %9.5f %9.5f %8.2f%%\n", label.c_str(), s.rms, s.mean_abs,
              s.p95_abs, 100.0 * s.share_over_1_16);
}

void print_one(const std::string& file, const OffsetTable& table, const TableAccuracy& acc) {
  std::printf("table %s: pattern %s, made by: %s\n", file.c_str(), table.pattern.name.c_str(),
              made_by(table).c_str());
  std::printf("    %-26s %9s %9s %9s %9s\n", "", "RMS", "mean|e|", "p95|e|", ">1/16");
  for (int k = 0; k < kCaseKindCount; ++k) {
    std::printf("  %s cases%s\n", to_string(CaseKind(k)), k == kMix ? " (50/50)" : "");
    print_row("table", acc.table[k]);
    print_row("zero offset (no AA)", acc.zero_offset[k]);
    print_row("fallback rule", acc.fallback_rule[k]);
  }
  std::printf("  table error by the rule behind each case's mask entry (50/50 mix)\n");
  for (int s = 0; s < kOffsetSourceCount; ++s) {
    const ErrorStats& st = acc.by_source[s][kMix];
    if (st.count == 0 && OffsetSource(s) == OffsetSource::Scene) continue;
    print_row(std::string(to_string(OffsetSource(s))) + " (" + std::to_string(st.count) + " cases)",
              st);
  }
}

// One line per table: RMS per case kind, then p95 and share > 1/16 of the mix.
void print_comparison(const std::vector<std::string>& files, const std::vector<TableAccuracy>& acc) {
  std::printf("%-44s %9s %9s %9s %9s %8s\n", "RMS error (one-line, two-line, 50/50 mix)",
              "one-line", "two-line", "mix", "mix p95", "mix>1/16");
  const auto row = [](const std::string& label, const std::array<ErrorStats, kCaseKindCount>& s) {
    std::printf("%-44s %9.5f %9.5f %9.5f %9.5f %7.2f%%\n", label.c_str(), s[kOneLine].rms,
                s[kTwoLine].rms, s[kMix].rms, s[kMix].p95_abs, 100.0 * s[kMix].share_over_1_16);
  };
  for (std::size_t i = 0; i < files.size(); ++i) row(files[i], acc[i].table);
  row("baseline: zero offset (no AA)", acc[0].zero_offset);
  row("baseline: fallback rule for every mask", acc[0].fallback_rule);
}

// Every case and its errors are kept, for the exact 95th percentile: about this many bytes a
// case at the peak (measured: 0.95 GB for 10^7 cases, whatever the number of tables).
constexpr double kBytesPerCase = 100.0;
// Address space (ulimit -v) beyond what the process maps at the start, measured with the
// smallest limit that runs 4 * 10^6 cases: about 110 bytes a case, and 72 MiB a worker thread
// that gets work (its stack and malloc arena; the cases go out 2^14 at a time).
constexpr double kAddressSpacePerCase = 120.0;
constexpr double kAddressSpacePerThread = 72.0 * 1024 * 1024;
constexpr std::uint64_t kCasesPerThreadTask = std::uint64_t{1} << 14;

// A number from the first line of `path` that starts with `key` (a /proc or cgroup file), or -1.
double read_number(const std::string& path, const std::string& key, double scale) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    char* end = nullptr;
    const double value = std::strtod(line.c_str() + key.size(), &end);
    return end == line.c_str() + key.size() ? -1.0 : value * scale;
  }
  return -1.0;
}

// The memory this process can take: the kernel's MemAvailable (free memory and the page cache it
// can drop), within a cgroup v2 limit where one is set (a container's memory.max).
double available_memory_bytes() {
  double available = read_number("/proc/meminfo", "MemAvailable:", 1024.0);
  if (available < 0) {
    const long pages = sysconf(_SC_AVPHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page_size > 0) available = double(pages) * double(page_size);
  }
  const double limit = read_number("/sys/fs/cgroup/memory.max", "", 1.0);  // "max" reads as no number
  const double used = read_number("/sys/fs/cgroup/memory.current", "", 1.0);
  if (limit > 0 && used >= 0 && (available < 0 || limit - used < available)) available = std::max(0.0, limit - used);
  return available;
}

// The address space this process can still map under ulimit -v (RLIMIT_AS): the limit less what
// it maps now (the first number of /proc/self/statm, in pages); -1 without a limit.
double available_address_space_bytes() {
  const std::uint64_t limit = address_space_limit();
  if (limit == 0) return -1.0;
  const double mapped = read_number("/proc/self/statm", "", double(sysconf(_SC_PAGESIZE)));
  return std::max(0.0, double(limit) - std::max(0.0, mapped));
}

std::string gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

// A case count whose memory the machine does not have is refused before any work, rather than
// the process being killed by the kernel part way (10^9 cases reached 23 GB) or running out of
// its address space after minutes (ulimit -v 4000000 and 4 * 10^7 cases: 43 s).
void require_memory_for(std::uint64_t cases, int threads) {
  const double available = available_memory_bytes(), needed = double(cases) * kBytesPerCase;
  if (available >= 0 && needed > 0.8 * available)
    throw std::invalid_argument("--cases " + std::to_string(cases) + " needs about " + gib(needed) +
                                " (every case's error is kept for the exact 95th percentile); this machine has " +
                                gib(available) + " available: use at most " +
                                std::to_string(std::uint64_t(0.8 * available / kBytesPerCase)) + " cases");
  const double address_space = available_address_space_bytes();
  const std::uint64_t busy_threads = std::min<std::uint64_t>(threads, 1 + cases / kCasesPerThreadTask);
  const double threads_need = double(busy_threads) * kAddressSpacePerThread;
  const double space_needed = double(cases) * kAddressSpacePerCase + threads_need;
  if (address_space >= 0 && space_needed > address_space)
    throw std::invalid_argument(
        "--cases " + std::to_string(cases) + " on " + std::to_string(busy_threads) + (busy_threads == 1 ? " thread" : " threads") + " needs about " +
        gib(space_needed) + " of address space (every case's error is kept for the exact 95th percentile); the " +
        "address-space limit (ulimit -v) leaves " + gib(address_space) + ": use at most " +
        std::to_string(std::uint64_t(std::max(0.0, address_space - threads_need) / kAddressSpacePerCase)) +
        " cases, fewer --threads, or raise ulimit -v");
}

int run_eval(const EvalArgs& a) {
  require_memory_for(a.cases, a.threads > 0 ? a.threads : default_thread_count());
  std::vector<OffsetTable> tables;
  for (const std::string& file : a.files) {
    tables.push_back(read_offset_table(file));
    const OffsetTable& t = tables.back();
    // One case set serves every table: the sample positions must be the same, not only the
    // name (two custom-x or gl4x tables can differ).
    const SamplePattern& first = tables.front().pattern;
    if (t.pattern.name != first.name)
      throw std::invalid_argument(file + ": pattern " + t.pattern.name + " differs from " +
                                  first.name + " of " + a.files.front() +
                                  "; compare tables of one pattern");
    if (t.pattern.positions.size() != first.positions.size())
      throw std::invalid_argument(file + ": pattern " + t.pattern.name + " has " +
                                  std::to_string(t.pattern.size()) + " samples, " + a.files.front() +
                                  " has " + std::to_string(first.size()) + "; compare tables of one pattern");
    for (std::size_t i = 0; i < first.positions.size(); ++i)
      if (t.pattern.positions[i].x != first.positions[i].x || t.pattern.positions[i].y != first.positions[i].y)
        throw std::invalid_argument(file + ": samples[" + std::to_string(i) + "] differs from " +
                                    a.files.front() + " (pattern " + first.name +
                                    " with other sample positions); compare tables of one pattern");
    const auto seed = t.training.find("seed");
    if (seed != t.training.end() && seed->is_number_unsigned() && seed->get<std::uint64_t>() == a.seed)
      std::fprintf(stderr,
                   "rsaa eval-table: warning: --seed %llu is the training seed of %s: these are "
                   "its training cases, not fresh ones\n",
                   static_cast<unsigned long long>(a.seed), file.c_str());
  }
  ProgressPrinter printer(a.json);
  printer.stage("generating " + std::to_string(a.cases) + " fresh cases");
  const auto cases = generate_cases(tables.front().pattern, a.cases, a.seed, a.threads,
                                    [&](std::uint64_t d, std::uint64_t t) { printer.step(d, t); });
  std::vector<TableAccuracy> accuracy;
  for (const OffsetTable& t : tables) accuracy.push_back(evaluate_table(t, cases));

  if (a.json) {
    nlohmann::json out = {{"cases", a.cases}, {"seed", a.seed}, {"tables", nlohmann::json::array()}};
    for (std::size_t i = 0; i < tables.size(); ++i)
      out["tables"].push_back(accuracy_json(a.files[i], tables[i], accuracy[i]));
    // One table: its fields at the top level too, the common case for scripts.
    if (tables.size() == 1) out.update(out["tables"][0]);
    std::printf("%s\n", out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    return 0;
  }
  std::printf("fresh cases: %llu (seed %llu), %llu one-line, %llu two-line; "
              "error = bilinear estimate - exact coverage\n",
              static_cast<unsigned long long>(a.cases), static_cast<unsigned long long>(a.seed),
              static_cast<unsigned long long>(accuracy[0].table[kOneLine].count),
              static_cast<unsigned long long>(accuracy[0].table[kTwoLine].count));
  if (tables.size() == 1)
    print_one(a.files[0], tables[0], accuracy[0]);
  else
    print_comparison(a.files, accuracy);
  return 0;
}

}  // namespace

Action add_eval_table_command(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand(
      "eval-table", "Accuracy of offset tables on fresh line cases (RMS, mean |error|, 95th "
                    "percentile, share > 1/16), beside the zero-offset and fallback baselines; "
                    "several tables of one pattern are compared on the same cases");
  cmd->add_option("files", args->files, "Table files (JSON)")->required();
  cmd->add_option("--cases", args->cases, "Number of fresh cases, half one-line, half two-line")
      ->capture_default_str()
      ->check(whole_range(1, std::uint64_t{1} << 32));
  cmd->add_option("--seed", args->seed, "Seed of the fresh cases (use one the trainer did not)")
      ->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->add_option("--threads", args->threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(whole_range(0, kMaxThreads));
  return [args] { return run_eval(*args); };
}

}  // namespace rsaa::cli
