#include "tools/bench/markdown.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <cstdio>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/util/atomic_file.h"
#include "core/util/json_unique.h"
#include "image/image_io.h"
#include "image/image_metrics.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "tools/bench/copy_pass.h"
#include "tools/bench/growth.h"

namespace rsaa::bench {
namespace {

constexpr int kBenchJsonVersion = 1;  // bench.json's layout (read_results_json reads this one only)
constexpr double kIdenticalDb = 99.0;  // PSNR reported for identical images
// The label of the second baseline: what RSAA's added cost is compared with.
const char* const kMsaaBaseline = "msaa 4x";

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double capped(double db) { return std::isfinite(db) ? std::min(db, kIdenticalDb) : kIdenticalDb; }

double psnr_of_mse(double mse) { return mse > 0 ? capped(10.0 * std::log10(255.0 * 255.0 / mse)) : kIdenticalDb; }

// PSNR of the frame-to-frame change of a sequence against the reference's change.
double flicker_psnr(const std::vector<DisplayImage>& frames, const std::vector<DisplayImage>& reference) {
  double squared = 0.0;
  std::size_t n = 0;
  for (std::size_t f = 1; f < frames.size(); ++f)
    for (std::size_t i = 0; i < frames[f].rgb.size(); ++i) {
      const double change = double(frames[f].rgb[i]) - frames[f - 1].rgb[i];
      const double reference_change = double(reference[f].rgb[i]) - reference[f - 1].rgb[i];
      squared += (change - reference_change) * (change - reference_change);
      ++n;
    }
  return n ? psnr_of_mse(squared / double(n)) : kIdenticalDb;
}

}  // namespace

std::vector<TechniqueOptions> default_techniques() {
  std::vector<TechniqueOptions> list = {technique_options("noaa", 0), technique_options("fxaa", 0),
                                        technique_options("msaa", 4), technique_options("ssaa", 8),
                                        technique_options("ssaa", 16)};
  for (int kernel : {1, 2, 3}) {
    TechniqueOptions o = technique_options("ssaa-filtered", 0);
    o.kernel = kernel;
    list.push_back(o);
  }
  list.push_back(technique_options("dyncov", 0));
  TechniqueOptions seed_rules = technique_options("dyncov", 0);
  seed_rules.rules = "seed";
  list.push_back(seed_rules);
  list.push_back(technique_options("dcaa", 0));
  list.push_back(technique_options("agaa", 4));
  list.push_back(technique_options("agaa", 8));
  for (const TechniqueOptions& o : rsaa_variants()) list.push_back(o);
  for (const TechniqueOptions& o : rsaa_defaults()) list.push_back(o);
  // RSAA with the defaults but one option, beside the defaults.
  const auto rsaa_with = [&list](int samples, const std::function<void(TechniqueOptions&)>& change) {
    TechniqueOptions o = technique_options("rsaa", samples);
    change(o);
    list.push_back(o);
  };
  // RSAA 4x with the jittered pre-pass (a draw per subsample), beside the default, which is the
  // one-draw multisample pre-pass where the driver samples gl4x (same masks).
  rsaa_with(4, [](TechniqueOptions& o) { o.prepass = "jittered"; });
  // RSAA 8x with the jittered pre-pass (a draw per subsample computing its codes), beside the
  // default on this driver, the same draws writing surface records whose codes the record passes
  // make (the same masks up to float ties).
  rsaa_with(8, [](TechniqueOptions& o) { o.prepass = "jittered"; });
  list.push_back(rsaa_default_without_extensions());
  // The defaults' post-process in one pass over every pixel, beside the two-pass one (same image).
  rsaa_with(8, [](TechniqueOptions& o) { o.post = "single"; });
  // The defaults' post-process as an edge pass and a depth-tested resolve (the default before the
  // edge list; same image).
  rsaa_with(8, [](TechniqueOptions& o) { o.post = "edges"; });
  // The defaults with the culled jittered pre-pass, beside the full one (same masks but where
  // features thinner than a pixel slip between pixel centres).
  rsaa_with(8, [](TechniqueOptions& o) { o.prepass_cull = "neighbours"; });
  // The defaults without facet edges (ours, a default since session 26: facets parted by shading
  // creases, and flat surfaces, differ by material).
  rsaa_with(8, [](TechniqueOptions& o) { o.facet_edges = "off"; });
  // The defaults without borrowed colours (ours, a default since session 30: a dissimilar
  // subsample's colour from the pixel within two that shows its surface), RSAA 8x and 4x.
  rsaa_with(8, [](TechniqueOptions& o) { o.multi_surface = "neighbours"; });
  rsaa_with(4, [](TechniqueOptions& o) { o.multi_surface = "neighbours"; });
  return list;
}

std::vector<std::string> default_scenes() {
  std::vector<std::string> scenes;
  for (const std::string& name : builtin_scene_names()) scenes.push_back("builtin:" + name);
  scenes.push_back("/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  scenes.push_back("/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf");
  scenes.push_back("/usr/share/assimp/models/OBJ/spider.obj");
  return scenes;
}

std::vector<FrameTiming> time_rounds(const std::vector<Technique*>& techniques, const GpuScene& gpu,
                                     const View& view, GLuint output, int frames, CopyPass& copy) {
  struct Samples {
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> per_pass;
    std::vector<std::string> pass_order;
    std::vector<double> frame_ms, copy_ms;
  };
  const std::size_t n = techniques.size();
  std::vector<Samples> samples(n);
  for (Technique* t : techniques) {  // warm-up: shader compilation
    t->render(gpu, view, output);
    t->take_pass_times();
  }
  for (int k = 0; k < frames; ++k)
    for (std::size_t step = 0; step < n; ++step) {
      const std::size_t i = (step + std::size_t(k)) % n;
      Samples& s = samples[i];
      techniques[i]->render(gpu, view, output);
      double sum = 0.0;
      for (const PassTime& p : techniques[i]->take_pass_times()) {
        if (!s.per_pass.count(p.pass)) s.pass_order.push_back(p.pass);
        s.per_pass[p.pass].first.push_back(p.wall_milliseconds);
        s.per_pass[p.pass].second.push_back(p.milliseconds);
        sum += p.wall_milliseconds;
      }
      s.frame_ms.push_back(sum);
      // Beside every frame, so that the ratio sees the same load on the shared machine.
      s.copy_ms.push_back(copy.time_ms(output));
    }
  std::vector<FrameTiming> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Samples& s = samples[i];
    for (const std::string& pass : s.pass_order) {
      const std::vector<double>& queries = s.per_pass[pass].second;
      const bool all_plausible = std::find(queries.begin(), queries.end(), kNoTimerQuery) == queries.end();
      out[i].pass_medians.push_back(
          {pass, all_plausible ? median(queries) : kNoTimerQuery, median(s.per_pass[pass].first)});
    }
    out[i].frame_ms = median(s.frame_ms);
    out[i].copy_ms = median(s.copy_ms);
  }
  return out;
}

std::vector<TechniqueResult> run_bench(const BenchOptions& o, const Progress& progress) {
  if (o.techniques.empty() || o.techniques.front().technique != "noaa")
    throw std::invalid_argument("bench: the first technique must be noaa (the ratio baseline)");
  if (o.frames < 1 || o.orbit_frames < 2)
    throw std::invalid_argument("bench: --frames must be >= 1 and --orbit-frames >= 2");
  validate_size(o.width, o.height);
  for (const TechniqueOptions& t : o.techniques) validate(t);
  std::vector<TechniqueResult> results;
  const int total = int(o.scenes.size() * (o.techniques.size() + 1));
  int done = 0;
  for (const std::string& spec : o.scenes) {
    const Scene loaded = load_scene_within(spec, 120.0);
    const Camera start = choose_camera(loaded, std::nullopt);
    Scene scene = with_lights(loaded, start, o.lights);
    scene.texture_anisotropy = o.texture_anisotropy;
    const GpuScene gpu(scene, needs_facet_colours(o.techniques));
    std::vector<Camera> cameras;
    for (int f = 0; f < o.orbit_frames; ++f) cameras.push_back(orbit_camera(start, f * o.orbit_degrees_per_frame));
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, o.width, o.height);
    CopyPass copy(o.width, o.height);
    copy.time_ms(output.get());  // warm-up: shader compilation

    if (progress) progress(spec + ": 64x SSAA reference", done, total);
    std::vector<DisplayImage> reference;
    {
      TechniqueOptions ssaa = technique_options("ssaa", 64);
      auto t = make_technique(ssaa, o.width, o.height);
      for (const Camera& c : cameras) {
        t->render(gpu, make_view(c, o.width, o.height), output.get());
        reference.push_back(to_display(read_back_image(output.get(), o.width, o.height)));
      }
    }
    ++done;

    // The baselines, kept for the scene and timed in every technique's rounds: no AA (the frame
    // ratio's) and 4x MSAA when benched (the added-cost table's).
    const View view = make_view(cameras[0], o.width, o.height);
    const std::unique_ptr<Technique> noaa = make_technique(o.techniques.front(), o.width, o.height);
    std::unique_ptr<Technique> msaa;
    for (const TechniqueOptions& options : o.techniques)
      if (technique_label(options) == kMsaaBaseline) msaa = make_technique(options, o.width, o.height);
    std::vector<std::pair<std::string, DisplayImage>> crop_images;
    for (std::size_t index = 0; index < o.techniques.size(); ++index) {
      const TechniqueOptions& options = o.techniques[index];
      TechniqueResult r;
      r.scene = scene.name;
      r.label = technique_label(options);
      r.options = options;
      if (progress) progress(spec + ": " + r.label, done, total);
      std::unique_ptr<Technique> own;
      Technique* t = index == 0 ? noaa.get() : r.label == kMsaaBaseline ? msaa.get() : nullptr;
      if (!t) own = make_technique(options, o.width, o.height), t = own.get();
      std::vector<Technique*> round = {t};
      if (t != noaa.get()) round.push_back(noaa.get());
      if (msaa && t != msaa.get()) round.push_back(msaa.get());
      const std::vector<FrameTiming> timings = time_rounds(round, gpu, view, output.get(), o.frames, copy);
      const auto frame_of = [&](const Technique* baseline) {
        return timings[std::size_t(std::find(round.begin(), round.end(), baseline) - round.begin())].frame_ms;
      };
      r.pass_medians = timings[0].pass_medians;
      r.frame_ms = timings[0].frame_ms;
      r.copy_ms = timings[0].copy_ms;
      r.paired_noaa_ms = frame_of(noaa.get());
      r.paired_msaa_ms = msaa ? frame_of(msaa.get()) : 0.0;
      r.frame_ratio = r.paired_noaa_ms > 0 ? r.frame_ms / r.paired_noaa_ms : 1.0;
      r.bytes_per_pixel = t->bytes_per_pixel();
      // Its own frame in the output again: the last round may have ended with a baseline's.
      t->render(gpu, view, output.get());
      t->take_pass_times();

      std::vector<DisplayImage> frames = {to_display(read_back_image(output.get(), o.width, o.height))};
      // A technique that renders NaN or infinity is broken, not measurable: said, never scored.
      if (frames[0].non_finite_pixels > 0)
        throw std::runtime_error(r.label + " on " + scene.name + ": " + std::to_string(frames[0].non_finite_pixels) +
                                 " pixels of its image are not finite (NaN or infinite)");
      const ImageComparison c = compare_images(frames[0], reference[0]);
      r.psnr_db = capped(c.psnr_db);
      r.ssim = c.ssim;
      r.luma_error_share = c.luma_error_share;
      const auto& shown = crop_labels();
      if (std::find(shown.begin(), shown.end(), r.label) != shown.end()) crop_images.push_back({r.label, frames[0]});
      double psnr_sum = r.psnr_db;
      for (std::size_t f = 1; f < cameras.size(); ++f) {
        t->render(gpu, make_view(cameras[f], o.width, o.height), output.get());
        t->take_pass_times();
        frames.push_back(to_display(read_back_image(output.get(), o.width, o.height)));
        psnr_sum += capped(compare_images(frames.back(), reference[f]).psnr_db);
      }
      r.orbit_psnr_db = psnr_sum / double(cameras.size());
      r.flicker_psnr_db = flicker_psnr(frames, reference);
      results.push_back(r);
      ++done;
    }
    if (!o.crops_dir.empty())
      plot_crops(crop_images, reference[0], o.crops_dir + "/crops-" + scene_short_name(scene.name) + ".png");
  }
  mark_pareto(results);
  if (progress) progress("done", done, total);
  return results;
}

double copy_multiple(const TechniqueResult& r, const PassTime& p) {
  return r.copy_ms > 0 ? p.wall_milliseconds / r.copy_ms : 0.0;
}

void mark_pareto(std::vector<TechniqueResult>& results) {
  for (TechniqueResult& r : results) {
    r.pareto = true;
    for (const TechniqueResult& other : results)
      if (&other != &r && other.scene == r.scene && other.frame_ratio <= r.frame_ratio &&
          other.psnr_db >= r.psnr_db && (other.frame_ratio < r.frame_ratio || other.psnr_db > r.psnr_db))
        r.pareto = false;
  }
}

const TechniqueResult* cheapest_reaching(const std::vector<TechniqueResult>& results,
                                         const std::string& scene, double target_db) {
  const TechniqueResult* best = nullptr;
  for (const TechniqueResult& r : results)
    if (r.scene == scene && r.psnr_db >= target_db && (!best || r.frame_ratio < best->frame_ratio)) best = &r;
  return best;
}

std::string results_json(const BenchOptions& o, const std::vector<TechniqueResult>& results) {
  nlohmann::json out = {{"format", "rsaa-bench"},
                        {"version", kBenchJsonVersion},
                        {"width", o.width},
                        {"height", o.height},
                        {"timed_frames", o.frames},
                        {"lights", o.lights},
                        {"orbit_frames", o.orbit_frames},
                        {"orbit_degrees_per_frame", o.orbit_degrees_per_frame},
                        {"reference", "ssaa 64x"},
                        {"psnr_identical_db", kIdenticalDb},
                        {"copy_pass", "full-screen RGBA16F -> RGBA8 copy, one texelFetch per pixel, "
                                      "timed after each timed frame; copy_ms is its median, "
                                      "copy_multiple = pass wall_ms / copy_ms"},
                        {"results", nlohmann::json::array()}};
  for (const TechniqueResult& r : results) {
    nlohmann::json passes = nlohmann::json::array();
    for (const PassTime& p : r.pass_medians)
      passes.push_back({{"pass", p.pass},
                        {"wall_ms", p.wall_milliseconds},
                        {"gl_timer_ms", p.milliseconds == kNoTimerQuery ? nlohmann::json(nullptr)
                                                                        : nlohmann::json(p.milliseconds)},
                        {"copy_multiple", copy_multiple(r, p)}});
    out["results"].push_back({{"scene", r.scene},
                              {"technique", r.label},
                              {"options", {{"technique", r.options.technique},
                                           {"samples", r.options.samples},
                                           {"similarity", r.options.similarity},
                                           {"auth", r.options.auth},
                                           {"pattern", r.options.pattern},
                                           {"kernel", r.options.kernel},
                                           {"rules", r.options.rules},
                                           {"shade", r.options.shade}}},
                              {"passes", passes},
                              {"frame_ms", r.frame_ms},
                              {"frame_ratio_to_noaa", r.frame_ratio},
                              {"paired_noaa_ms", r.paired_noaa_ms},
                              {"paired_msaa_4x_ms", r.paired_msaa_ms > 0.0 ? nlohmann::json(r.paired_msaa_ms)
                                                                            : nlohmann::json(nullptr)},
                              {"copy_ms", r.copy_ms},
                              {"psnr_db", r.psnr_db},
                              {"ssim", r.ssim},
                              {"luma_error_share_percent", r.luma_error_share},
                              {"orbit_psnr_db", r.orbit_psnr_db},
                              {"flicker_psnr_db", r.flicker_psnr_db},
                              {"bytes_per_pixel", r.bytes_per_pixel},
                              {"pareto", r.pareto}});
  }
  return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string results_csv(const std::vector<TechniqueResult>& results) {
  std::ostringstream s;
  s << "scene,technique,frame_ms,frame_ratio_to_noaa,psnr_db,ssim,luma_error_share_percent,"
       "orbit_psnr_db,flicker_psnr_db,bytes_per_pixel,pareto,passes_wall_ms,copy_ms,passes_copy_multiple,"
       "paired_noaa_ms,paired_msaa_4x_ms\n";
  for (const TechniqueResult& r : results) {
    s << csv_text(r.scene) << ',' << csv_text(r.label) << ',' << r.frame_ms << ',' << r.frame_ratio << ','
      << r.psnr_db << ',' << r.ssim << ',' << r.luma_error_share << ',' << r.orbit_psnr_db << ','
      << r.flicker_psnr_db << ',' << r.bytes_per_pixel << ',' << (r.pareto ? 1 : 0) << ',';
    std::ostringstream passes;
    for (std::size_t i = 0; i < r.pass_medians.size(); ++i)
      passes << (i ? ";" : "") << r.pass_medians[i].pass << '=' << r.pass_medians[i].wall_milliseconds;
    std::ostringstream multiples;
    for (std::size_t i = 0; i < r.pass_medians.size(); ++i)
      multiples << (i ? ";" : "") << r.pass_medians[i].pass << '=' << copy_multiple(r, r.pass_medians[i]);
    s << csv_text(passes.str()) << ',' << r.copy_ms << ',' << csv_text(multiples.str()) << ',' << r.paired_noaa_ms
      << ',' << r.paired_msaa_ms << '\n';
  }
  return s.str();
}

namespace {
constexpr std::size_t kMaxResults = 4096, kMaxResultsPerScene = 256, kMaxPasses = 64;

// A measured number of a bench file, within what a run can produce: the report prints it and the
// plots place it (a hand-edited PSNR of -3e9 hung the Pareto plot's grid, a ratio of -5 was
// reported as "-5.0x"). `where` names the entry and the field.
double measured(const nlohmann::json& entry, const char* field, double lo, double hi, const std::string& where) {
  const nlohmann::json& value = entry.at(field);
  const double v = value.is_number() ? value.get<double>() : std::nan("");
  if (!(v >= lo && v <= hi)) {
    char range[96];
    std::snprintf(range, sizeof range, "a number from %g to %g", lo, hi);
    throw std::runtime_error(where + "." + field + " is " + value.dump() + ", expected " + range);
  }
  return v;
}
}  // namespace

std::vector<TechniqueResult> read_results_json(const std::string& path, BenchOptions& o) {
  nlohmann::json j;
  try {
    j = parse_json_with_unique_keys(read_whole_file(path));
    if (j.at("format") != "rsaa-bench") throw std::runtime_error("not an rsaa-bench file");
    // Fields may change meaning between versions: only the one this build writes is read.
    if (!j.contains("version") || j.at("version") != kBenchJsonVersion)
      throw std::runtime_error("version " + (j.contains("version") ? j.at("version").dump() : std::string("missing")) +
                               ", this build reads version " + std::to_string(kBenchJsonVersion));
    o.width = j.at("width");
    o.height = j.at("height");
    o.frames = j.at("timed_frames");
    o.lights = j.value("lights", 1);
    o.orbit_frames = j.at("orbit_frames");
    // The report prints these: a hand-edited file with -5 or 1e10 was reported as it was.
    validate_size(o.width, o.height);
    if (o.frames < 1 || o.frames > 1000 || o.orbit_frames < 2 || o.orbit_frames > 1000 || o.lights < 1 || o.lights > 65)
      throw std::runtime_error("timed_frames, orbit_frames or lights outside the bench's ranges");
    // Bounded as the bench's own runs are (tens of techniques on tens of scenes): every scene's
    // plots grow with its rows, and 40,000 hand-made rows took 16 GB and a plot 960,110 pixels tall.
    const auto& entries = j.at("results");
    if (!entries.is_array() || entries.size() > kMaxResults)
      throw std::runtime_error("results: expected an array of at most " + std::to_string(kMaxResults) + " entries");
    std::map<std::string, std::size_t> rows_per_scene;
    std::vector<TechniqueResult> results;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const auto& e = entries[i];
      const std::string where = "results[" + std::to_string(i) + "]";
      TechniqueResult r;
      r.scene = e.at("scene");
      if (++rows_per_scene[r.scene] > kMaxResultsPerScene)
        throw std::runtime_error("results: more than " + std::to_string(kMaxResultsPerScene) + " rows for scene " +
                                 r.scene);
      r.label = e.at("technique");
      const auto& opt = e.at("options");
      r.options.technique = opt.at("technique");
      r.options.samples = opt.at("samples");
      r.options.similarity = opt.at("similarity");
      r.options.auth = opt.at("auth");
      r.options.pattern = opt.at("pattern");
      r.options.kernel = opt.value("kernel", 2);
      r.options.rules = opt.value("rules", TechniqueOptions{}.rules);
      r.options.shade = opt.value("shade", TechniqueOptions{}.shade);
      const auto& passes = e.at("passes");
      if (!passes.is_array() || passes.size() > kMaxPasses)
        throw std::runtime_error("passes: expected an array of at most " + std::to_string(kMaxPasses) + " entries");
      // Times up to a day, ratios between 1e-6 and 1e6, PSNR as the bench caps it.
      constexpr double kLongestMs = 8.64e7;
      for (std::size_t k = 0; k < passes.size(); ++k) {
        const auto& p = passes[k];
        const std::string pass_where = where + ".passes[" + std::to_string(k) + "]";
        r.pass_medians.push_back({p.at("pass"),
                                  p.at("gl_timer_ms").is_null() ? kNoTimerQuery
                                                                : measured(p, "gl_timer_ms", 0.0, kLongestMs, pass_where),
                                  measured(p, "wall_ms", 0.0, kLongestMs, pass_where)});
      }
      r.frame_ms = measured(e, "frame_ms", 0.0, kLongestMs, where);
      r.frame_ratio = measured(e, "frame_ratio_to_noaa", 1e-6, 1e6, where);
      // (absent from files before timing in rounds; the report then uses the baselines' rows)
      if (e.contains("paired_noaa_ms")) r.paired_noaa_ms = measured(e, "paired_noaa_ms", 0.0, kLongestMs, where);
      if (e.contains("paired_msaa_4x_ms") && !e.at("paired_msaa_4x_ms").is_null())
        r.paired_msaa_ms = measured(e, "paired_msaa_4x_ms", 0.0, kLongestMs, where);
      r.copy_ms = e.contains("copy_ms") ? measured(e, "copy_ms", 0.0, kLongestMs, where) : 0.0;
      r.psnr_db = measured(e, "psnr_db", 0.0, kIdenticalDb, where);
      r.ssim = measured(e, "ssim", -1.0, 1.0, where);
      r.luma_error_share = measured(e, "luma_error_share_percent", 0.0, 100.0, where);
      r.orbit_psnr_db = measured(e, "orbit_psnr_db", 0.0, kIdenticalDb, where);
      r.flicker_psnr_db = measured(e, "flicker_psnr_db", 0.0, kIdenticalDb, where);
      r.bytes_per_pixel = measured(e, "bytes_per_pixel", 0.0, 1e9, where);
      r.pareto = e.at("pareto");
      results.push_back(r);
    }
    return results;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a bench result file (" + e.what() + ")");
  }
}

namespace {

const TechniqueResult* find(const std::vector<TechniqueResult>& results, const std::string& scene,
                            const std::string& label) {
  for (const TechniqueResult& r : results)
    if (r.scene == scene && r.label == label) return &r;
  return nullptr;
}

std::string signed_db(const TechniqueResult* a, const TechniqueResult* b) {
  if (!a || !b) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f", a->psnr_db - b->psnr_db);
  return text;
}

}  // namespace

std::string results_markdown(const BenchOptions& o, const std::vector<TechniqueResult>& results) {
  std::ostringstream s;
  char line[512];
  // Files from before timing in rounds have no paired baseline frames.
  const bool timed_in_rounds = std::any_of(results.begin(), results.end(),
                                           [](const TechniqueResult& r) { return r.paired_noaa_ms > 0.0; });
  s << o.width << "x" << o.height << ", " << o.lights << (o.lights == 1 ? " light" : " lights")
    << ", median of " << o.frames << " timed frames after a warm-up, "
    << (timed_in_rounds ? "in rounds with no AA's frames (and 4x MSAA's when benched), x noaa against those"
                        : "one technique after another (a file from before timing in rounds), x noaa against the noaa row")
    << "; orbit of "
    << o.orbit_frames << " frames; * = on the Pareto front (frame-time ratio down, PSNR up)\n\n";
  s << "| scene | technique | PSNR dB | SSIM | luma err % | orbit PSNR | flicker PSNR | frame ms | x noaa | B/px |\n";
  s << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  std::vector<std::string> scenes;
  for (const TechniqueResult& r : results) {
    if (scenes.empty() || scenes.back() != r.scene) scenes.push_back(r.scene);
    std::snprintf(line, sizeof line, "| %s | %s%s | %.2f | %.4f | %.2f | %.2f | %.2f | %.1f | %.2f | %.0f |\n",
                  markdown_cell(scene_short_name(r.scene)).c_str(), r.pareto ? "* " : "", r.label.c_str(), r.psnr_db, r.ssim,
                  r.luma_error_share, r.orbit_psnr_db, r.flicker_psnr_db, r.frame_ms, r.frame_ratio,
                  r.bytes_per_pixel);
    s << line;
  }
  s << "\nPer pass: wall ms and, in brackets, the multiple of a full-screen copy pass (RGBA16F -> RGBA8, one "
       "texelFetch) timed beside each frame at the same size: the speed of light of a post-process.\n\n";
  s << "| scene | technique | copy ms | passes: ms (x copy) |\n";
  s << "| --- | --- | --- | --- |\n";
  for (const TechniqueResult& r : results) {
    std::string passes;
    for (const PassTime& p : r.pass_medians) {
      std::snprintf(line, sizeof line, "%s%s %.1f (%.1fx)", passes.empty() ? "" : ", ", p.pass.c_str(),
                    p.wall_milliseconds, copy_multiple(r, p));
      passes += line;
    }
    std::snprintf(line, sizeof line, "| %s | %s | %.2f | %s |\n", markdown_cell(scene_short_name(r.scene)).c_str(), r.label.c_str(),
                  r.copy_ms, passes.c_str());
    s << line;
  }
  // What RSAA adds to the frame against what hardware 4x MSAA adds, the trade RSAA is for (the
  // frame over no AA's, medians of one run): from the baselines' frames timed in the RSAA row's own
  // rounds, or (files from before them) from the baselines' rows.
  std::string added;
  bool added_from_rows = false;
  for (const TechniqueResult& r : results) {
    const TechniqueResult* noaa = find(results, r.scene, "noaa");
    const TechniqueResult* msaa = find(results, r.scene, kMsaaBaseline);
    if (r.options.technique != "rsaa" || !noaa || !msaa) continue;
    const bool paired = r.paired_noaa_ms > 0.0 && r.paired_msaa_ms > 0.0;
    added_from_rows = added_from_rows || !paired;
    const double noaa_ms = paired ? r.paired_noaa_ms : noaa->frame_ms;
    const double msaa_ms = paired ? r.paired_msaa_ms : msaa->frame_ms;
    const double rsaa_adds = r.frame_ms - noaa_ms, msaa_adds = msaa_ms - noaa_ms;
    char multiple[32] = "-";  // 4x MSAA added nothing measurable: no multiple of it
    if (msaa_adds > 0.0) std::snprintf(multiple, sizeof multiple, "%.2fx", rsaa_adds / msaa_adds);
    std::snprintf(line, sizeof line, "| %s | %s | %.1f | %.1f | %s |\n", markdown_cell(scene_short_name(r.scene)).c_str(),
                  r.label.c_str(), rsaa_adds, msaa_adds, multiple);
    added += line;
  }
  if (!added.empty())
    s << "\nAdded cost: each RSAA frame's ms over no AA's, as a multiple of what hardware 4x MSAA adds ("
      << (added_from_rows ? "from the noaa and msaa 4x rows: a file from before timing in rounds"
                          : "no AA's and 4x MSAA's frames timed in the same rounds as the RSAA row's")
      << "; - where 4x MSAA added nothing measurable).\n\n"
         "| scene | technique | RSAA adds ms | 4x MSAA adds ms | multiple |\n"
         "| --- | --- | --- | --- | --- |\n"
      << added;
  s << "\nPer scene: the paper's trades (it reports about +4 dB for 8 over 4 samples and up to +3 dB "
       "for SADP over depth) and the RSAA variants on the Pareto front.\n\n";
  s << "| scene | noaa | fxaa | msaa 4x | best RSAA | RSAA 8x - 4x (SADP, auth 0) | SADP - depth (8x, auth 0) | RSAA on the front |\n";
  s << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const std::string& scene : scenes) {
    const TechniqueResult* best = nullptr;
    std::string front;
    for (const TechniqueResult& r : results) {
      if (r.scene != scene || r.options.technique != "rsaa") continue;
      if (!best || r.psnr_db > best->psnr_db) best = &r;
      if (r.pareto) front += (front.empty() ? "" : ", ") + r.label;
    }
    const auto psnr = [&](const char* label) {
      const TechniqueResult* r = find(results, scene, label);
      if (!r) return std::string("-");
      char text[32];  // rounded, as every other table of the report (substr cut 30.678 to 30.67)
      std::snprintf(text, sizeof text, "%.2f", r->psnr_db);
      return std::string(text);
    };
    char best_text[128] = "-";
    if (best) std::snprintf(best_text, sizeof best_text, "%s: %.2f (%.1fx)", best->label.c_str(), best->psnr_db, best->frame_ratio);
    s << "| " << markdown_cell(scene_short_name(scene)) << " | " << psnr("noaa") << " | " << psnr("fxaa") << " | " << psnr("msaa 4x")
      << " | " << best_text << " | "
      << signed_db(find(results, scene, "rsaa 8x sadp auth0"), find(results, scene, "rsaa 4x gl4x sadp auth0")) << " | "
      << signed_db(find(results, scene, "rsaa 8x sadp auth0"), find(results, scene, "rsaa 8x depth auth0")) << " | "
      << (front.empty() ? "none" : front) << " |\n";
  }
  return s.str();
}

}  // namespace rsaa::bench
