// rsaa figures: the papers' figures (tools/bench/paper_figures.h), each written as CSV + PNG and a
// Markdown summary.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <sstream>

#include "image/image_io.h"
#include "runtime/gl_context.h"
#include "tools/bench/paper_figures.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/out_dir.h"

namespace rsaa::cli {
namespace {

constexpr const char* kEngine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

struct FiguresArgs {
  std::string figure = "all";
  std::string scenes;
  int width = 640, height = 480;
  int frames = 32;
  double pull_back = 16.0;
  bool quick = false;
  std::string out_dir = "out/papers";
  // Which of the options --quick sets were given: those keep their value.
  bool width_given = false, height_given = false, frames_given = false;
};

int run_figures(FiguresArgs a) {
  bench::FigureOptions o;
  o.scenes = {"builtin:default", kEngine};
  if (a.quick) {
    o.scenes = {"builtin:default"};
    if (!a.width_given) a.width = 160;
    if (!a.height_given) a.height = 120;
    if (!a.frames_given) a.frames = 4;
  }
  if (!a.scenes.empty()) {
    o.scenes.clear();
    std::stringstream list(a.scenes);
    std::string item;
    while (std::getline(list, item, ','))
      if (!item.empty()) o.scenes.push_back(item);
  }
  o.width = a.width, o.height = a.height, o.frames = a.frames, o.pull_back = a.pull_back;
  const std::vector<std::string>& known = bench::figure_names();
  std::vector<std::string> names = known;
  if (a.figure != "all") names = {a.figure};
  // Refused before the slow context and renders.
  if (std::find(known.begin(), known.end(), a.figure) == known.end() && a.figure != "all")
    throw std::invalid_argument("--figure: unknown figure '" + a.figure + "' (fig9, fig1, dcaa, agaa, memory or all)");
  // Claimed before the renders, so that an unwritable --out-dir is said at once.
  StagedOutputs staged(a.out_dir, "rsaa figures");
  require_image_module();  // its images are written at the end: said now if they cannot be
  gl::HeadlessContext context;
  for (const std::string& name : names) {
    const bench::Figure f = bench::make_figure(name, o, [](const std::string& what) {
      std::fprintf(stderr, "  %s\n", what.c_str());
    });
    bench::write_figure(f, staged.dir());
    std::printf("## %s\n\n%s\n", name.c_str(), f.markdown.c_str());
    std::fflush(stdout);
  }
  // Every figure of the run as one set: a run that fails on a later figure (a scene that does not
  // load, a full disk) leaves the previous run's files, never this run's first figures beside them.
  print_written(a.out_dir, staged.commit());
  return 0;
}

}  // namespace

Action add_figures_command(CLI::App& app) {
  auto args = std::make_shared<FiguresArgs>();
  CLI::App* cmd = app.add_subcommand(
      "figures", "The papers' figures against 64x SSAA, each as CSV + PNG + Markdown: fig9 (RSAA's Figure 9, PSNR "
                 "per frame while the camera pulls back to sub-pixel geometry), fig1 (RSAA's Figure 1, pixels above "
                 "a luminance-error threshold), dcaa (surfaces per pixel, quality against 2-8 surfaces), agaa "
                 "(quality against c = 1-4 aggregates, 4, 8 and 16 samples), memory (bytes per pixel beside the "
                 "papers' layouts)");
  cmd->add_option("--figure", args->figure, "fig9 | fig1 | dcaa | agaa | memory | all")->capture_default_str();
  cmd->add_option("--scenes", args->scenes,
                  "Comma-separated scenes (default: builtin:default and 2CylinderEngine; fig9 animates the first)");
  cmd->add_option("--width", args->width, "Image width")->capture_default_str()->check(whole_range(1, 8192));
  cmd->add_option("--height", args->height, "Image height")->capture_default_str()->check(whole_range(1, 8192));
  cmd->add_option("--frames", args->frames, "fig9: frames of the animation")
      ->capture_default_str()
      ->check(whole_range(2, 1000));
  cmd->add_option("--pull-back", args->pull_back, "fig9: the camera's last distance over its first")
      ->capture_default_str()
      ->check(finite_range(1.0, 1000.0));
  cmd->add_flag("--quick", args->quick, "CI scale: builtin:default at 160x120, 4 frames");
  cmd->add_option("--out-dir", args->out_dir, "Where the CSV, PNG and Markdown files go")->capture_default_str();
  return [args, cmd] {
    args->width_given = cmd->count("--width") > 0, args->height_given = cmd->count("--height") > 0;
    args->frames_given = cmd->count("--frames") > 0;
    return run_figures(*args);
  };
}

}  // namespace rsaa::cli
