// The rsaa subcommands. Each registers its options on the app and returns the action to run
// once parsing succeeded; an action returns the process exit code.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace rsaa::cli {

using Action = std::function<int()>;

Action add_train_command(CLI::App& app);
Action add_eval_table_command(CLI::App& app);
Action add_render_command(CLI::App& app);
Action add_compare_command(CLI::App& app);
Action add_view_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
Action add_plot_command(CLI::App& app);
Action add_diagnose_command(CLI::App& app);
Action add_shaders_command(CLI::App& app);
Action add_figures_command(CLI::App& app);

}  // namespace rsaa::cli
