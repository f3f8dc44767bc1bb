// rsaa_reliability: runs the broken-input corpora and the bounded fuzz loops, prints a Markdown
// report, and exits non-zero if any input was mishandled. Short by default (CI); longer with
// --iterations.
#include <cstdio>
#include <cstring>
#include <string>

#include "tools/reliability/suite.h"

int main(int argc, char** argv) {
  using namespace rsaa::reliability;
  Options options;
  bool tables_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--iterations" && has_value) {
      options.iterations = std::stoull(argv[++i]);
    } else if (a == "--seed" && has_value) {
      options.seed = std::stoull(argv[++i]);
    } else if (a == "--rsaa" && has_value) {
      options.rsaa_binary = argv[++i];
    } else if (a == "--tables-only") {
      tables_only = true;
    } else {
      std::fprintf(stderr,
                   "usage: rsaa_reliability [--iterations N] [--seed S] [--rsaa PATH] [--tables-only]\n"
                   "  Feeds broken and mutated inputs (N mutations per fuzz loop, default 200) to the\n"
                   "  table reader, scene loader, image reader and command line; prints a report.\n");
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  std::vector<SuiteResult (*)(const Options&)> suites = {table_corpus, table_fuzz};
#ifdef RSAA_RELIABILITY_WITH_RUNTIME
  if (!tables_only)
    for (auto s : {scene_corpus, scene_fuzz, image_corpus, command_line_corpus}) suites.push_back(s);
#else
  (void)tables_only;  // a build without the runtime has only the table suites
#endif
  std::printf("| inputs | tried | refused with a clear error | accepted as valid | mishandled |\n");
  std::printf("| --- | --- | --- | --- | --- |\n");
  std::uint64_t failed = 0;
  std::vector<std::string> failures;
  std::vector<SuiteResult> results;
  for (auto suite : suites) results.push_back(suite(options));
#ifdef RSAA_RELIABILITY_WITH_RUNTIME
  if (!tables_only)
    for (SuiteResult& r : hostile_suites(options)) results.push_back(std::move(r));
#endif
  for (const SuiteResult& r : results) {
    if (r.inputs == 0) continue;
    std::printf("| %s | %llu | %llu | %llu | %llu |\n", r.what.c_str(),
                static_cast<unsigned long long>(r.inputs), static_cast<unsigned long long>(r.rejected),
                static_cast<unsigned long long>(r.accepted), static_cast<unsigned long long>(r.failed));
    std::fflush(stdout);
    failed += r.failed;
    failures.insert(failures.end(), r.failures.begin(), r.failures.end());
  }
  for (const std::string& f : failures) std::fprintf(stderr, "mishandled: %s\n", f.c_str());
  return failed == 0 ? 0 : 1;
}
