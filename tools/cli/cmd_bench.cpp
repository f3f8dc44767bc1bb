// rsaa bench: the speed/accuracy trade of every technique, written as JSON, CSV, PNG plots and a
// Markdown table.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "core/util/atomic_file.h"
#include "image/image_io.h"
#include "runtime/gl_context.h"
#include "runtime/scene.h"
#include "tools/bench/bench.h"
#include "tools/bench/growth.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/out_dir.h"

namespace rsaa::cli {
namespace {

struct BenchArgs {
  std::string scenes, techniques, table, table_prepass = "auto";
  int width = 640, height = 480;
  int frames = 5, orbit_frames = 4;
  bool quick = false;
  std::string out_dir = "out/bench";
  double target_psnr = 0.0;
  std::string from_json;
  bool growth = false;
  std::string lights;
  float anisotropy = kDefaultTextureAnisotropy;
  // Which of the options --quick sets were given: those keep their value (--quick used to
  // replace them without a word: --quick --width 99999 ran at 160x120).
  bool width_given = false, height_given = false, frames_given = false, orbit_frames_given = false;
  bool scenes_given = false;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<int> light_counts(const std::string& list) {
  std::vector<int> out;
  for (const std::string& item : split(list)) {
    std::size_t end = 0;
    int n = -1;
    try {
      n = std::stoi(item, &end);
    } catch (const std::exception&) {
    }
    // The fixed light plus at most kMaxScenePointLights point lights (what the shaders hold).
    if (end != item.size() || n < 1 || n > kMaxScenePointLights + 1)
      throw std::invalid_argument("--lights: '" + item + "' is not a light count within 1.." +
                                  std::to_string(kMaxScenePointLights + 1));
    out.push_back(n);
  }
  return out;
}

// The techniques of `all` whose labels `list` names (comma-separated), in `all`'s order; noaa stays
// first as the ratio baseline. A label that is not in `all` is refused, naming the valid ones.
std::vector<TechniqueOptions> keep_techniques(const std::vector<TechniqueOptions>& all, const std::string& list) {
  const std::vector<std::string> keep = split(list);
  std::vector<TechniqueOptions> chosen;
  for (const TechniqueOptions& t : all)
    if (t.technique == "noaa" || std::find(keep.begin(), keep.end(), technique_label(t)) != keep.end())
      chosen.push_back(t);
  for (const std::string& k : keep)
    if (std::none_of(chosen.begin(), chosen.end(), [&](const TechniqueOptions& t) { return technique_label(t) == k; })) {
      std::string labels;
      for (const TechniqueOptions& t : all) labels += (labels.empty() ? "'" : ", '") + technique_label(t) + "'";
      throw std::invalid_argument("--techniques: no technique labelled '" + k + "' in the bench; its labels: " + labels);
    }
  return chosen;
}

// rsaa bench --growth: frame time against image size and triangle count, plots and slopes.
// RSAA (default options) with the user's table (--table), beside the built-in rows, with the
// pre-pass or pre-passes --table-prepass names.
void add_table_rows(const BenchArgs& a, std::vector<TechniqueOptions>& techniques) {
  if (a.table.empty()) return;
  if (a.table_prepass != "auto" && a.table_prepass != "jittered" && a.table_prepass != "msaa" &&
      a.table_prepass != "both")
    throw std::invalid_argument("--table-prepass must be auto, jittered, msaa or both, not '" + a.table_prepass + "'");
  for (const char* prepass : {"auto", "jittered", "msaa"}) {
    const bool both = a.table_prepass == "both" && std::string(prepass) != "auto";
    if (!both && a.table_prepass != prepass) continue;
    TechniqueOptions t = technique_options("rsaa");
    t.table = a.table;
    t.prepass = prepass;
    validate(t);
    techniques.push_back(t);
  }
}

int run_growth_command(const BenchArgs& a) {
  bench::GrowthOptions o;
  o.techniques = bench::default_techniques();
  if (!a.techniques.empty()) o.techniques = keep_techniques(o.techniques, a.techniques);
  add_table_rows(a, o.techniques);
  if (a.quick) {
    o.sizes = {{160, 120}, {320, 240}};
    o.subdivision_levels = {0, 1};
    o.light_counts = {1, 4};
    // Given sizes and frames keep their value, as in the bench's --quick.
    o.width = a.width_given ? a.width : 160, o.height = a.height_given ? a.height : 120;
    o.frames = a.frames_given ? a.frames : 2;
  } else {
    o.light_counts = {1, 2, 4, 8, 16, 32};
    o.width = a.width, o.height = a.height, o.frames = a.frames;
  }
  if (!a.lights.empty()) o.light_counts = light_counts(a.lights);
  o.texture_anisotropy = a.anisotropy;
  if (!a.scenes.empty()) {
    const auto scenes = split(a.scenes);
    if (scenes.size() != 1) throw std::invalid_argument("--growth measures one scene: give one in --scenes");
    o.scene = scenes.front();
  }
  StagedOutputs staged(a.out_dir, "rsaa bench");
  const std::string dir = staged.dir();
  require_image_module();  // its images are written at the end: said now if they cannot be
  gl::HeadlessContext context;
  const auto results = bench::run_growth(o, [](const std::string& what, int done, int total) {
    std::fprintf(stderr, "[%3d/%3d] %s\n", done, total, what.c_str());
  });
  write_file_atomically(dir + "/growth.json", bench::growth_json(o, results));
  write_file_atomically(dir + "/growth.csv", bench::growth_csv(results));
  bench::plot_growth(results, bench::GrowthAxis::Pixels, dir + "/growth-pixels.png");
  bench::plot_growth(results, bench::GrowthAxis::Triangles, dir + "/growth-triangles.png");
  bench::plot_growth(results, bench::GrowthAxis::Lights, dir + "/growth-lights.png");
  const std::string report = bench::growth_markdown(o, results);
  write_file_atomically(dir + "/growth.md", report);
  print_written(a.out_dir, staged.commit("growth"));
  std::printf("%s", report.c_str());
  return 0;
}

// Each scene's plots and crops are named after its short name: two scenes of one name (or one
// listed twice) would overwrite each other's files.
void require_distinct_file_names(const std::vector<std::string>& scenes, const std::string& where) {
  for (std::size_t i = 0; i < scenes.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (scene_short_name(scenes[i]) == scene_short_name(scenes[k]))
        throw std::invalid_argument(where + ": '" + scenes[k] + "' and '" + scenes[i] + "' would both write pareto-" +
                                    scene_short_name(scenes[i]) +
                                    ".png and the other files of that name; give each scene once, from files of "
                                    "different names");
}

int run_bench_command(BenchArgs a) {
  if (a.growth) return run_growth_command(a);
  bench::BenchOptions o;
  o.techniques = bench::default_techniques();
  if (a.quick) {
    o.scenes = {"builtin:default", "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"};
    if (!a.width_given) a.width = 160;
    if (!a.height_given) a.height = 120;
    if (!a.frames_given) a.frames = 3;
    if (!a.orbit_frames_given) a.orbit_frames = 3;
  } else {
    o.scenes = bench::default_scenes();
  }
  if (a.scenes_given && split(a.scenes).empty()) throw std::invalid_argument("--scenes: no scene named");
  if (!a.scenes.empty()) o.scenes = split(a.scenes);
  require_distinct_file_names(o.scenes, "--scenes");
  if (!a.techniques.empty()) o.techniques = keep_techniques(o.techniques, a.techniques);
  add_table_rows(a, o.techniques);
  o.width = a.width, o.height = a.height, o.frames = a.frames, o.orbit_frames = a.orbit_frames;
  o.texture_anisotropy = a.anisotropy;
  if (!a.lights.empty()) {
    const auto lights = light_counts(a.lights);
    if (lights.size() != 1) throw std::invalid_argument("--lights: one count, or a list with --growth");
    o.lights = lights.front();
  }
  StagedOutputs staged(a.out_dir, "rsaa bench");
  const std::string dir = staged.dir();
  std::vector<bench::TechniqueResult> results;
  if (!a.from_json.empty()) {
    results = bench::read_results_json(a.from_json, o);
    // The redrawn report's own data beside it, as a measured run leaves it.
    write_file_atomically(dir + "/bench.json", bench::results_json(o, results));
    write_file_atomically(dir + "/bench.csv", bench::results_csv(results));
  } else {
    require_image_module();  // its images are written at the end: said now if they cannot be
    gl::HeadlessContext context;
    o.crops_dir = dir;
    results = bench::run_bench(o, [](const std::string& what, int done, int total) {
      std::fprintf(stderr, "[%3d/%3d] %s\n", done, total, what.c_str());
    });
    write_file_atomically(dir + "/bench.json", bench::results_json(o, results));
    write_file_atomically(dir + "/bench.csv", bench::results_csv(results));
  }
  std::vector<std::string> scenes;
  for (const auto& r : results)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  require_distinct_file_names(scenes, a.from_json.empty() ? "--scenes" : a.from_json);
  // A redraw cannot make the crops again (they need the images): those of its scenes already in
  // the directory stay in the set.
  if (!a.from_json.empty())
    for (const std::string& scene : scenes) {
      const std::string crops = "crops-" + scene_short_name(scene) + ".png";
      std::error_code error;
      if (std::filesystem::is_regular_file(a.out_dir + "/" + crops, error))
        std::filesystem::copy_file(a.out_dir + "/" + crops, dir + "/" + crops, error);
    }
  for (const std::string& scene : scenes) {
    bench::plot_pareto(results, scene, dir + "/pareto-" + scene_short_name(scene) + ".png");
    bench::plot_pass_times(results, scene, dir + "/passes-" + scene_short_name(scene) + ".png");
  }
  const std::string report = bench::results_markdown(o, results);
  write_file_atomically(dir + "/report.md", report);
  print_written(a.out_dir, staged.commit("bench"));
  std::printf("%s", report.c_str());
  if (a.target_psnr > 0) {
    std::printf("\ncheapest technique reaching %.1f dB:\n", a.target_psnr);
    for (const std::string& scene : scenes) {
      const auto* best = bench::cheapest_reaching(results, scene, a.target_psnr);
      if (best)
        std::printf("  %-20s %s (%.2fx noaa)\n", scene_short_name(scene).c_str(), best->label.c_str(), best->frame_ratio);
      else
        std::printf("  %-20s none of the techniques\n", scene_short_name(scene).c_str());
    }
  }
  return 0;
}

}  // namespace

Action add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Measure the speed/accuracy trade of every technique on scenes (times, PSNR/SSIM vs "
               "64x SSAA, temporal flicker, memory); writes JSON, CSV and PNG plots");
  cmd->add_option("--scenes", args->scenes,
                  "Comma-separated scenes (default: all built-in scenes and three assimp test models)");
  cmd->add_option("--techniques", args->techniques,
                  "Comma-separated labels to keep (e.g. 'msaa 4x,dyncov'; noaa is always run)");
  cmd->add_option("--table", args->table,
                  "Also bench RSAA (default options) with this offset table file (JSON), e.g. a scene-specific one "
                  "(with --growth too)");
  cmd->add_option("--table-prepass", args->table_prepass,
                  "Pre-pass of the --table row: auto (msaa where the driver can, else records), jittered, msaa (one "
                  "multisample draw, at twice the width for a cell pattern such as tables/custom-gl4x-wide.json, or "
                  "two for a union pattern such as tables/custom-gl4x-union.json) or both "
                  "(a jittered and an msaa row)")
      ->capture_default_str();
  cmd->add_option("--width", args->width, "Image width")->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")->capture_default_str();
  cmd->add_option("--frames", args->frames, "Timed frames per technique (median)")->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--orbit-frames", args->orbit_frames, "Frames of the camera orbit (temporal metrics)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1000));
  cmd->add_flag("--quick", args->quick, "CI-scale run: 2 scenes, 160x120, 3 frames, 3 orbit frames");
  cmd->add_option("--out-dir", args->out_dir, "Where bench.json, bench.csv and the plots go")->capture_default_str();
  cmd->add_option("--target-psnr", args->target_psnr, "Also name the cheapest technique reaching this PSNR (dB)")
      ->check(finite_range(0.0, 1000.0));
  cmd->add_flag("--growth", args->growth,
                "Instead: frame time of every technique against image size (640x480 to 2560x1440), "
                "triangle count (the scene subdivided 1x, 4x, 16x) and light count (--lights, default "
                "1,2,4,8,16,32) at --width x --height, with slopes; one scene (default builtin:default); "
                "writes growth.{json,csv,md} and growth-*.png");
  cmd->add_option("--lights", args->lights,
                  "Shade with the fixed light plus N - 1 point lights (default 1: the fixed light only); "
                  "with --growth a comma-separated list of N");
  add_anisotropy_option(cmd, args->anisotropy);
  cmd->add_option("--from-json", args->from_json,
                  "Report and plot a previous run's bench.json again instead of measuring");
  return [args, cmd] {
    // A redraw takes everything from the file: a measuring option beside it would be ignored.
    if (!args->from_json.empty())
      for (const char* option : {"--growth", "--quick", "--scenes", "--techniques", "--table", "--table-prepass",
                                 "--width", "--height", "--frames", "--orbit-frames", "--lights", "--anisotropy"})
        if (cmd->count(option) > 0)
          throw std::invalid_argument(std::string("--from-json redraws a measured run as it was: ") + option +
                                      " belongs to a measurement; leave it out");
    args->width_given = cmd->count("--width") > 0, args->height_given = cmd->count("--height") > 0;
    args->frames_given = cmd->count("--frames") > 0, args->orbit_frames_given = cmd->count("--orbit-frames") > 0;
    args->scenes_given = cmd->count("--scenes") > 0;
    return run_bench_command(*args);
  };
}

}  // namespace rsaa::cli
