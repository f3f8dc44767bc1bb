// rsaa: one executable, one subcommand per job (DESIGN.md section 4).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>

#include "tools/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"rsaa: Resampling Anti-Aliasing (Reshetov, HPG 2012): table trainer, renderer and tools"};
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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  const CLI::App* chosen = app.get_subcommands().front();
  try {
    return actions.at(chosen)();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rsaa %s: error: %s\n", chosen->get_name().c_str(), e.what());
    std::fflush(nullptr);
    // Leave at once: a scene loader that timed out may still be running on its own thread.
    std::_Exit(1);
  }
}
