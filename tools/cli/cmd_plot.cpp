// rsaa plot: a line chart of CSV columns (the trade curves of tools/trainer_trades.sh).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "tools/bench/bench.h"
#include "tools/cli/commands.h"

namespace rsaa::cli {
namespace {

struct PlotArgs {
  std::string csv, x, y, title, out;
  bool log_x = false;
};

int run_plot(const PlotArgs& a) {
  std::vector<std::string> ys;
  std::stringstream list(a.y);
  std::string item;
  while (std::getline(list, item, ','))
    if (!item.empty()) ys.push_back(item);
  if (ys.empty()) throw std::invalid_argument("--y: name at least one column");
  // The chart would replace the data it was drawn from.
  std::error_code error;
  if (std::filesystem::equivalent(a.csv, a.out, error))
    throw std::invalid_argument("--out '" + a.out + "' is the CSV file itself; write the chart elsewhere");
  bench::plot_csv(a.csv, a.x, ys, a.log_x, a.title.empty() ? a.csv : a.title, a.out);
  std::printf("wrote %s\n", a.out.c_str());
  return 0;
}

}  // namespace

Action add_plot_command(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand("plot", "Line chart (PNG) of one or more CSV columns against another");
  cmd->add_option("csv", args->csv, "CSV file with a header row")->required();
  cmd->add_option("--x", args->x, "Column for the x axis")->required();
  cmd->add_option("--y", args->y, "Comma-separated columns to draw")->required();
  cmd->add_flag("--log-x", args->log_x, "Logarithmic x axis");
  cmd->add_option("--title", args->title, "Chart title (default: the file name)");
  cmd->add_option("--out", args->out, "Output PNG")->required();
  return [args] { return run_plot(*args); };
}

}  // namespace rsaa::cli
