// rsaa: one executable, one subcommand per job (docs/conventions.md section 4).
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "core/util/printable.h"
#include "tools/cli/commands.h"

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The first word names the subcommand; CLI11 would only say that it was not expected.
int refuse_unknown_command(const CLI::App& app, const std::string& word) {
  std::string nearest, names;
  std::size_t best = std::string::npos;
  for (const CLI::App* sub : app.get_subcommands({})) {
    const std::string& name = sub->get_name();
    names += (names.empty() ? "" : ", ") + name;
    const std::size_t d = edit_distance(word, name);
    if (d < best) best = d, nearest = name;
  }
  std::fprintf(stderr, "rsaa: error: unknown command '%s'", word.c_str());
  if (best <= std::max<std::size_t>(2, nearest.size() / 3)) std::fprintf(stderr, "; did you mean '%s'?", nearest.c_str());
  std::fprintf(stderr, " (commands: %s; rsaa --help)\n", names.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  // A write beyond the file-size limit (ulimit -f) then fails with EFBIG and is reported like a
  // full disk, instead of SIGXFSZ ending the process in the middle of a write.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"rsaa: Resampling Anti-Aliasing (Reshetov, HPG 2012): table trainer, renderer and tools"};
  app.set_version_flag("--version", std::string("rsaa ") + RSAA_VERSION);
  app.require_subcommand(1);
  std::map<const CLI::App*, rsaa::cli::Action> actions;
  const auto add = [&](rsaa::cli::Action (*add_command)(CLI::App&)) {
    const std::size_t before = app.get_subcommands({}).size();
    rsaa::cli::Action action = add_command(app);
    actions[app.get_subcommands({})[before]] = std::move(action);
  };
  add(rsaa::cli::add_train_command);
  add(rsaa::cli::add_eval_table_command);
  add(rsaa::cli::add_render_command);
  add(rsaa::cli::add_compare_command);
  add(rsaa::cli::add_view_command);
  add(rsaa::cli::add_bench_command);
  add(rsaa::cli::add_plot_command);
  add(rsaa::cli::add_diagnose_command);
  add(rsaa::cli::add_shaders_command);
  add(rsaa::cli::add_figures_command);

  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) known = known || sub->check_name(argv[1]);
    if (!known) return refuse_unknown_command(app, argv[1]);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  const CLI::App* chosen = app.get_subcommands().front();
  // An empty value names nothing; taken as "the default" it hid typos such as --techniques ''
  // (every technique ran) or --keys '' (view waited for keys that never came).
  for (const CLI::Option* option : chosen->get_options()) {
    if (option->count() == 0 || option->get_items_expected_min() == 0) continue;  // flags take no value
    for (const std::string& value : option->results())
      if (value.empty()) {
        std::fprintf(stderr, "rsaa %s: error: %s: an empty value names nothing%s\n", chosen->get_name().c_str(),
                     option->get_name().c_str(),
                     option->get_required() ? "" : "; leave the option out for its default");
        return 2;
      }
  }
  try {
    return actions.at(chosen)();
  } catch (const std::bad_alloc&) {
    rlimit limit{};
    const bool capped = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    std::fprintf(stderr, "rsaa %s: error: out of memory (%s)\n", chosen->get_name().c_str(),
                 capped ? ("address space limited to " + std::to_string(limit.rlim_cur >> 20) +
                           " MiB; fewer --threads or a smaller input may fit").c_str()
                        : "an input declares more data than fits in the memory available");
    std::fflush(nullptr);
    std::_Exit(1);
  } catch (const std::exception& e) {
    // (printable: a file name or file text in the message may hold terminal escapes; a driver's
    // compile log keeps its lines)
    std::fprintf(stderr, "rsaa %s: error: %s\n", chosen->get_name().c_str(),
                 rsaa::printable(e.what(), true).c_str());
    std::fflush(nullptr);
    // Leave at once: a scene loader that timed out may still be running on its own thread.
    std::_Exit(1);
  }
}
