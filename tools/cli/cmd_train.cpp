// rsaa train: fit an offset table and write tables/P.{json,glsl,hlsl}.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "core/util/parallel.h"
#include "runtime/gl_context.h"
#include "runtime/rsaa_pass.h"
#include "runtime/scene.h"
#include "runtime/shader_library.h"
#include "tools/scene_training/scene_tables.h"
#include "core/util/atomic_file.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/out_dir.h"
#include "tools/cli/progress.h"
#include "trainer/train.h"

namespace rsaa::cli {
namespace {

struct TrainArgs {
  std::string pattern;
  std::string positions;
  std::string cells;  // "CxR": the cell pattern of --pattern (empty: the pattern itself)
  std::uint64_t cases = 1000000;
  std::uint64_t seed = 1;
  std::string out_dir = "tables";
  std::string fit = "mixed";
  double two_line_weight = 0.5;
  int threads = 0;
  bool quiet = false;
  std::string from_scene;
  std::string generic;  // empty: the built-in d3d8x table
  int width = 320, height = 240, views = 6;
};

// Whether a number's text has a nonzero digit before its exponent ("1e-400" has, "0.0e5" not).
bool has_nonzero_mantissa(const std::string& number) {
  for (char c : number) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

// "x,y x,y ..." in pixel space (y down): 1 to kMaxTableSamples pairs, checked before anything is
// printed or created.
std::vector<Vec2> parse_positions(const std::string& text) {
  std::vector<Vec2> out;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    Vec2 p;
    char comma = 0;
    std::istringstream pair(token);
    if (!(pair >> p.x >> comma >> p.y) || comma != ',' || !pair.eof())
      throw std::invalid_argument("--positions: '" + token + "' is not an x,y pair");
    // A coordinate below the smallest normal double reads as 0 ("1e-400") or a denormal: it
    // would train another pattern than the one written.
    const std::size_t at = token.find(',');
    const std::pair<double, std::string> coordinates[] = {{p.x, token.substr(0, at)}, {p.y, token.substr(at + 1)}};
    for (const auto& [value, number] : coordinates)
      if (std::fpclassify(value) == FP_SUBNORMAL || (value == 0.0 && has_nonzero_mantissa(number)))
        throw std::invalid_argument("--positions: sample " + std::to_string(out.size()) + " ('" + token + "'): '" +
                                    number + "' is too small for a double (it reads as " +
                                    (value == 0.0 ? std::string("0") : "a denormal number") + "); write 0 or a coordinate of at least " +
                                    std::to_string(kMinSampleSpacing));
    out.push_back(p);
  }
  if (out.empty() || out.size() > static_cast<std::size_t>(kMaxTableSamples))
    throw std::invalid_argument("--positions: " + std::to_string(out.size()) + " x,y pairs; tables allow 1 to " +
                                std::to_string(kMaxTableSamples) + " subsamples");
  return out;
}

std::string rms_text(const TrainingError::Rms& s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.5f", s.rms);
  return s.count ? buffer : "-";
}

// A file-name stem from a scene name: letters, digits, '-' and '_' kept, anything else '_'.
std::string stem_text(const std::string& name) {
  std::string out;
  for (char c : name.substr(0, 48))
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return out.empty() ? "scene" : out;
}

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

// rsaa train --from-scene: a d3d8x table fitted on one scene's own cases.
int run_train_from_scene(const TrainArgs& a) {
  if (!a.pattern.empty() && a.pattern != "d3d8x")
    throw std::invalid_argument("--from-scene trains d3d8x tables only (RSAA 8x masks)");
  if (!a.cells.empty()) throw std::invalid_argument("--cells trains a pattern's table, not --from-scene's");
  const auto lock = claim_out_dir(a.out_dir, "rsaa train");
  const OffsetTable generic = a.generic.empty() ? gl::builtin_offset_table("d3d8x") : read_offset_table(a.generic);
  const std::string generic_name = a.generic.empty() ? "the built-in d3d8x table" : a.generic;
  bench::SceneTableOptions o;
  o.scene = a.from_scene;
  o.width = a.width, o.height = a.height, o.training_views = a.views;
  o.generic_file = a.generic;
  gl::HeadlessContext context;
  const auto report = bench::train_scene_table(o, generic, [&](const std::string& s) {
    if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
  });
  const std::string stem = "d3d8x-" + stem_text(scene_short_name(a.from_scene));
  const auto paths = write_offset_table_files(report.table, a.out_dir, stem);
  std::printf("rsaa train --from-scene %s: %dx%d, %d training views, %llu edge pixels, %zu masks occur, "
              "%d fitted (>= %d pixels), the rest from %s\n",
              a.from_scene.c_str(), o.width, o.height, o.training_views,
              static_cast<unsigned long long>(report.edge_pixels), report.masks.size(), report.masks_fitted,
              o.min_pixels, generic_name.c_str());
  std::printf("  most frequent masks (mask: pixels): ");
  for (std::size_t i = 0; i < std::min<std::size_t>(12, report.masks.size()); ++i)
    std::printf("%s%llu: %llu", i ? ", " : "", static_cast<unsigned long long>(report.masks[i].first),
                static_cast<unsigned long long>(report.masks[i].second));
  std::printf("\n  held-out views, PSNR vs 64x SSAA: no AA %.2f dB, generic table %.2f dB, scene table %.2f dB\n",
              report.held_out_psnr_noaa, report.held_out_psnr_generic, report.held_out_psnr_scene);
  for (const auto& p : paths) std::printf("  wrote   %s\n", p.c_str());
  return 0;
}

int run_train(const TrainArgs& a) {
  if (!a.from_scene.empty()) return run_train_from_scene(a);
  if (a.pattern.empty()) throw std::invalid_argument("--pattern is required (or --from-scene)");
  const auto start = std::chrono::steady_clock::now();
  TrainOptions options;
  if (a.positions.empty() && gl_pattern_samples(a.pattern) > 0) {
    gl::HeadlessContext context;  // the pattern of this machine's GL driver
    options.pattern = query_gl_sample_pattern(gl_pattern_samples(a.pattern));
  } else if (a.positions.empty()) {
    if (a.pattern.rfind("custom-", 0) == 0)
      throw std::invalid_argument("--pattern " + a.pattern + " needs --positions \"x,y x,y ...\" (pixel space, +y down)");
    options.pattern = builtin_pattern(a.pattern);
  } else {
    if (gl_pattern_samples(a.pattern) == 0 && a.pattern.rfind("custom-", 0) != 0)
      throw std::invalid_argument("--positions needs --pattern glNx (a driver's pattern read elsewhere) or --pattern custom-NAME");
    options.pattern = pattern_from_positions(a.pattern, parse_positions(a.positions));
  }
  if (!a.cells.empty()) {
    // "CxR", each 1..8: the pattern's cells (docs/conventions.md section 1), named custom-BASE-SHAPE.
    if (a.cells.size() != 3 || a.cells[1] != 'x' || a.cells[0] < '1' || a.cells[0] > '8' || a.cells[2] < '1' ||
        a.cells[2] > '8' || a.cells == "1x1")
      throw std::invalid_argument("--cells: '" + a.cells + "' is not COLUMNSxROWS, each 1 to 8, more than one cell (e.g. 1x2)");
    const int columns = a.cells[0] - '0', rows = a.cells[2] - '0';
    if (std::int64_t(columns) * rows * options.pattern.size() > kMaxTableSamples)
      throw std::invalid_argument("--cells " + a.cells + " of " + options.pattern.name + " (" +
                                  std::to_string(options.pattern.size()) + " samples) makes " +
                                  std::to_string(columns * rows * options.pattern.size()) +
                                  " subsamples; tables hold at most " + std::to_string(kMaxTableSamples));
    options.pattern = cell_pattern(options.pattern, columns, rows);
  }
  options.cases = a.cases;
  options.seed = a.seed;
  options.fit = a.fit == "ockham" ? FitRule::Ockham : FitRule::Mixed;
  options.two_line_weight = a.two_line_weight;
  options.threads = a.threads;
  const auto lock = claim_out_dir(a.out_dir, "rsaa train");

  const int threads = a.threads > 0 ? a.threads : default_thread_count();
  std::printf("rsaa train: pattern %s (%d subsamples, %zu masks), %llu cases, seed %llu, fit %s",
              options.pattern.name.c_str(), options.pattern.size(), options.pattern.mask_count(),
              static_cast<unsigned long long>(a.cases), static_cast<unsigned long long>(a.seed),
              a.fit.c_str());
  if (options.fit == FitRule::Mixed) std::printf(" (two-line weight %g)", a.two_line_weight);
  std::printf(", %d threads\n", threads);
  std::fflush(stdout);

  auto printer = std::make_shared<ProgressPrinter>(a.quiet);
  TrainProgress progress;
  progress.stage = [printer](const std::string& s) { printer->stage(s); };
  progress.step = [printer](std::uint64_t d, std::uint64_t t) { printer->step(d, t); };
  const TrainReport report = train_offset_table(options, progress);
  const auto paths = write_offset_table_files(report.table, a.out_dir);
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto& by = report.masks_by_source;
  const auto& acc = report.training_error;
  std::printf("  cases:   %llu generated in %.2f s (%.0f cases/s)\n",
              static_cast<unsigned long long>(a.cases), report.generate_seconds,
              a.cases / std::max(report.generate_seconds, 1e-9));
  std::printf("  fit:     %llu masks reached (%llu case groups), fitted in %.2f s (the all-similar "
              "mask stays (0, 0))\n",
              static_cast<unsigned long long>(by[0] + by[1]),
              static_cast<unsigned long long>(report.case_groups), report.fit_seconds);
  std::printf("  masks:   %llu explained by one line, %llu only by two lines, %llu by no case "
              "(fallback rule)\n",
              static_cast<unsigned long long>(by[0]), static_cast<unsigned long long>(by[1]),
              static_cast<unsigned long long>(by[2]));
  std::printf("  training RMS error   %-10s %-10s %-10s\n", "one-line", "two-line", "mix");
  for (int s = 0; s < 3; ++s) {
    if (acc.by_source[s][kMix].count == 0) continue;
    std::printf("    %-8s masks     %-10s %-10s %-10s\n", to_string(OffsetSource(s)),
                rms_text(acc.by_source[s][kOneLine]).c_str(),
                rms_text(acc.by_source[s][kTwoLine]).c_str(),
                rms_text(acc.by_source[s][kMix]).c_str());
  }
  std::printf("    whole table        %-10.5f %-10.5f %-10.5f\n", acc.table[kOneLine].rms,
              acc.table[kTwoLine].rms, acc.table[kMix].rms);
  std::printf("  time:    %.2f s in all; peak memory %.0f MiB\n", total, peak_memory_mib());
  for (const auto& p : paths) std::printf("  wrote   %s\n", p.c_str());
  return 0;
}

}  // namespace

Action add_train_command(CLI::App& app) {
  auto args = std::make_shared<TrainArgs>();
  CLI::App* cmd = app.add_subcommand(
      "train", "Fit one resampling offset per similarity mask on random line cases and write "
               "DIR/P.json, DIR/P.glsl, DIR/P.hlsl");
  cmd->add_option("--pattern", args->pattern,
                  "Sample pattern: d3d4x, d3d8x, d3d16x; gl2x, gl4x, gl8x, gl16x (read from this GL driver, "
                  "refused where it has fewer samples); custom-NAME with --positions");
  cmd->add_option("--positions", args->positions,
                  "Subsample positions in pixel space (+y down), \"x,y x,y ...\"");
  cmd->add_option("--cells", args->cells,
                  "COLUMNSxROWS: train the cell pattern of --pattern instead (its positions in each cell of "
                  "the pixel split so; a driver with that pattern draws it once at that multiple of the image: "
                  "gl4x --cells 1x2 is tables/custom-gl4x-tall.json); named custom-PATTERN-wide (2x1), -tall "
                  "(1x2), -quad (2x2) or -cellsCxR");
  cmd->add_option("--cases", args->cases, "Number of line cases, half one-line, half two-line")
      ->capture_default_str()
      ->check(whole_range(1, std::uint64_t{1} << 32));
  cmd->add_option("--seed", args->seed, "Random seed of the case set")->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--out-dir", args->out_dir,
                  "Directory for the three table files (created if missing; one train at a time)")
      ->capture_default_str();
  cmd->add_option("--fit", args->fit,
                  "ockham: one-line cases where one line explains the mask, else two-line "
                  "(the paper); mixed: both kinds, weighted")
      ->capture_default_str()
      ->check(CLI::IsMember({"ockham", "mixed"}));
  cmd->add_option("--two-line-weight", args->two_line_weight,
                  "Weight w of two-line cases in the mixed fit (one-line cases get 1 - w)")
      ->capture_default_str()
      ->check(finite_range(0.0, 1.0));
  cmd->add_option("--threads", args->threads, "Worker threads (0 = all cores; never changes output)")
      ->capture_default_str()
      ->check(whole_range(0, kMaxThreads));
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  cmd->add_option("--from-scene", args->from_scene,
                  "Fit a d3d8x table on this scene's own cases (builtin:NAME or a model): writes "
                  "DIR/d3d8x-NAME.*, reports the masks that occur and held-out PSNR");
  cmd->add_option("--generic", args->generic, "--from-scene: the table for masks the scene rarely reaches (default: the built-in d3d8x table)")
      ->capture_default_str();
  cmd->add_option("--width", args->width, "--from-scene: render width")->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--height", args->height, "--from-scene: render height")->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--views", args->views, "--from-scene: training camera views")->capture_default_str()
      ->check(whole_range(1, 100));
  return [args] { return run_train(*args); };
}

}  // namespace rsaa::cli
