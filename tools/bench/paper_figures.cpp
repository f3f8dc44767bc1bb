// rsaa figures: RSAA's Figures 9 and 1 and the memory comparison; the coverage family's figures
// are in coverage_figures.cpp.
#include "tools/bench/paper_figures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "core/reference/agaa.h"
#include "core/util/atomic_file.h"
#include "core/reference/dynamic_coverage.h"
#include "image/image_metrics.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "tools/bench/figure_internal.h"

namespace rsaa::bench {

const std::vector<std::string>& figure_names() {
  static const std::vector<std::string> names = {"fig9", "fig1", "dcaa", "agaa", "memory"};
  return names;
}

std::vector<TechniqueOptions> figure_techniques() {
  std::vector<TechniqueOptions> list = {technique_options("noaa"), technique_options("fxaa"),
                                        technique_options("msaa", 4)};
  for (const TechniqueOptions& o : rsaa_defaults()) list.push_back(o);
  list.push_back(technique_options("dyncov"));
  list.push_back(technique_options("dcaa"));
  list.push_back(technique_options("agaa", 8));
  return list;
}

Camera pulled_back_camera(const Camera& camera, double factor, double degrees) {
  if (!(factor > 0.0) || !std::isfinite(factor)) throw std::invalid_argument("pulled_back_camera: factor must be > 0");
  Camera c = orbit_camera(camera, degrees);
  c.eye = c.target + (c.eye - c.target) * float(factor);
  c.near_plane *= float(factor);
  c.far_plane *= float(factor);
  return c;
}

double pull_back_factor(int frame, int frames, double pull_back) {
  return frames > 1 ? std::pow(pull_back, double(frame) / double(frames - 1)) : 1.0;
}

std::vector<double> figure1_thresholds() {
  std::vector<double> t;
  for (double v = 0.5; v <= 128.0; v *= 2.0) t.push_back(v / 255.0);
  return t;
}

namespace {


Figure figure9(const FigureOptions& o, const FigureProgress& progress) {
  const std::string spec = o.scenes.front();
  const Scene scene = load_scene_within(spec, 120.0);
  const GpuScene gpu(scene);
  const Camera start = choose_camera(scene, std::nullopt);
  const std::vector<TechniqueOptions> techniques = figure_techniques();
  std::vector<std::unique_ptr<Technique>> renderers;
  for (const TechniqueOptions& t : techniques) renderers.push_back(make_technique(t, o.width, o.height));
  auto reference_renderer = make_technique(technique_options("ssaa", 64), o.width, o.height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, o.width, o.height);

  Figure f;
  f.name = "fig9";
  Figure::Part part;
  part.stem = "fig9";
  part.table.columns = {"frame", "distance"};
  for (const TechniqueOptions& t : techniques) part.table.columns.push_back(technique_label(t));
  for (int frame = 0; frame < o.frames; ++frame) {
    const double factor = pull_back_factor(frame, o.frames, o.pull_back);
    const double degrees = o.frames > 1 ? o.orbit_degrees * frame / (o.frames - 1) : 0.0;
    const View view = make_view(pulled_back_camera(start, factor, degrees), o.width, o.height);
    if (progress) progress("fig9 frame " + std::to_string(frame + 1) + "/" + std::to_string(o.frames));
    reference_renderer->render(gpu, view, output.get());
    const DisplayImage reference = to_display(read_back_image(output.get(), o.width, o.height));
    std::vector<double> row = {double(frame), factor};
    for (auto& t : renderers) {
      t->render(gpu, view, output.get());
      t->take_pass_times();
      row.push_back(capped_psnr(to_display(read_back_image(output.get(), o.width, o.height)), reference));
    }
    part.table.add(row);
  }
  // fig9.csv keeps the distance; fig9.png is drawn without it (another scale).
  part.plot_from = part.table;
  for (auto& row : part.plot_from.rows) row.erase(row.begin() + 1);
  part.plot_from.columns.erase(part.plot_from.columns.begin() + 1);
  part.style = {"Fig. 9: PSNR per frame vs 64x SSAA, " + scene_short_name(spec) + ", camera pulled back 1x to " +
                    fixed(o.pull_back, 0) + "x",
                "frame", "PSNR dB", false, {"msaa", "noaa"}};

  std::ostringstream md;
  md << "PSNR (dB) against 64x SSAA per frame, " << scene_short_name(spec) << " at " << o.width << "x" << o.height
     << ", " << o.frames << " frames; the camera pulls back from 1x to " << fixed(o.pull_back, 0)
     << "x its distance (geometrically) while turning " << fixed(o.orbit_degrees, 0) << " degrees.\n\n";
  // The frame's PSNR rises as the scene shrinks (more background): the gain over no AA of the
  // same frame is what compares early and late frames.
  md << "| technique | first frame | mean, first half | mean, last quarter | last frame | frames below msaa 4x | "
        "over noaa, first frame | over noaa, last quarter |\n";
  md << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  const std::size_t msaa = part.table.column("msaa 4x"), noaa = part.table.column("noaa");
  const std::size_t n = part.table.rows.size();
  for (std::size_t c = 2; c < part.table.columns.size(); ++c) {
    double first_half = 0, last_quarter = 0, gain_last_quarter = 0;
    int halves = 0, quarters = 0, below = 0;
    for (std::size_t r = 0; r < n; ++r) {
      const double v = part.table.rows[r][c];
      if (2 * r < n) first_half += v, ++halves;
      if (4 * r >= 3 * n) last_quarter += v, gain_last_quarter += v - part.table.rows[r][noaa], ++quarters;
      below += v < part.table.rows[r][msaa];
    }
    md << "| " << part.table.columns[c] << " | " << fixed(part.table.rows.front()[c]) << " | "
       << fixed(first_half / std::max(1, halves)) << " | " << fixed(last_quarter / std::max(1, quarters)) << " | "
       << fixed(part.table.rows.back()[c]) << " | " << (c == msaa ? "-" : std::to_string(below)) << " | "
       << fixed(part.table.rows.front()[c] - part.table.rows.front()[noaa]) << " | "
       << fixed(gain_last_quarter / std::max(1, quarters)) << " |\n";
  }
  f.markdown = md.str();
  f.parts = {part};
  return f;
}

Figure figure1(const FigureOptions& o, const FigureProgress& progress) {
  Figure f;
  f.name = "fig1";
  const std::vector<double> thresholds = figure1_thresholds();
  std::ostringstream md;
  md << "Share of pixels (%) whose luminance error against 64x SSAA exceeds a threshold (in 1/255 of the "
        "display range), "
     << o.width << "x" << o.height << ".\n\n";
  for (const std::string& spec : o.scenes) {
    const auto frame = load_scene_frame(spec, o, progress);
    Figure::Part part;
    part.stem = "fig1-" + scene_short_name(spec);
    part.table.columns = {"threshold_255"};
    std::vector<std::vector<double>> shares;
    for (const TechniqueOptions& t : figure_techniques()) {
      if (progress) progress("fig1 " + scene_short_name(spec) + ": " + technique_label(t));
      part.table.columns.push_back(technique_label(t));
      shares.push_back(luma_error_shares(frame->render(t).image, frame->reference, thresholds));
    }
    for (std::size_t k = 0; k < thresholds.size(); ++k) {
      std::vector<double> row = {thresholds[k] * 255.0};
      for (const auto& s : shares) row.push_back(s[k]);
      part.table.add(row);
    }
    part.style = {"Fig. 1: pixels with luminance error above a threshold, " + scene_short_name(spec),
                  "threshold (1/255 of the display range)", "% of pixels", true, {"msaa", "noaa"}};
    md << "**" << scene_short_name(spec) << "**\n\n";
    std::vector<std::string> threshold_columns;
    for (double t : thresholds) threshold_columns.push_back("> " + fixed(t * 255.0, t * 255.0 < 1 ? 1 : 0));
    markdown_table_head(md, "technique", threshold_columns);
    for (std::size_t c = 1; c < part.table.columns.size(); ++c) {
      md << "| " << part.table.columns[c] << " |";
      for (const auto& row : part.table.rows) md << " " << fixed(row[c]) << " |";
      md << "\n";
    }
    md << "\n";
    f.parts.push_back(part);
  }
  f.markdown = md.str();
  return f;
}

// The papers' own layouts (B/px), where they give one, as they count them.
double paper_bytes(const TechniqueOptions& t) {
  if (t.technique == "dcaa") return kDcaaPaperBytesPerPixel;
  if (t.technique == "dyncov") return kDynamicCoveragePaperBytesPerPixel;
  if (t.technique == "agaa") return agaa_paper_bytes_per_pixel(t.samples ? t.samples : 8, t.agaa_aggregates);
  if (t.technique == "msaa") return kDynamicCoveragePaperMsaaBytesPerPixel;  // the dyncov paper's 4x MSAA
  return std::numeric_limits<double>::quiet_NaN();
}

Figure memory_figure(const FigureOptions& o, const FigureProgress& progress) {
  // The compared techniques, with DCAA's z-prepass and AGAA's other sample counts beside them.
  TechniqueOptions zpre = technique_options("dcaa");
  zpre.z_prepass = true;
  std::vector<TechniqueOptions> techniques;
  for (const TechniqueOptions& t : figure_techniques()) {
    if (t.technique == "agaa") techniques.push_back(technique_options("agaa", 4));
    techniques.push_back(t);
    if (t.technique == "dcaa") techniques.push_back(zpre);
  }
  techniques.push_back(technique_options("agaa", 16));
  Figure f;
  f.name = "memory";
  Figure::Part part;
  part.stem = "memory";
  part.table.columns = {"index"};
  for (const std::string& spec : o.scenes) part.table.columns.push_back("ours, " + scene_short_name(spec));
  part.table.columns.push_back("paper's layout");
  std::vector<std::vector<double>> ours(techniques.size());
  for (const std::string& spec : o.scenes) {
    const Scene scene = load_scene_within(spec, 120.0);
    const GpuScene gpu(scene);
    const View view = make_view(choose_camera(scene, std::nullopt), o.width, o.height);
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, o.width, o.height);
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      if (progress) progress("memory " + scene_short_name(spec) + ": " + technique_label(techniques[i]));
      auto t = make_technique(techniques[i], o.width, o.height);
      // Two frames of a steady view: the fragment lists grow to the first frame's fragments (or
      // shrink to them, when it used less than half of the initial buffer) before the second.
      t->render(gpu, view, output.get());
      t->render(gpu, view, output.get());
      ours[i].push_back(t->bytes_per_pixel());
    }
  }
  std::ostringstream md;
  md << "Bytes per pixel as allocated after two frames of each scene at " << o.width << "x" << o.height
     << ", beside the layout each paper gives (msaa 4x: as the dynamic-coverage paper counts it).\n\n| technique |";
  for (const std::string& spec : o.scenes) md << " ours, " << scene_short_name(spec) << " |";
  md << " the paper's layout |\n| --- |";
  for (std::size_t k = 0; k <= o.scenes.size(); ++k) md << " --- |";
  md << "\n";
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    std::vector<double> row = {double(i)};
    row.insert(row.end(), ours[i].begin(), ours[i].end());
    row.push_back(paper_bytes(techniques[i]));
    part.table.add(row, technique_label(techniques[i]));
    md << "| " << technique_label(techniques[i]) << " |";
    for (double b : ours[i]) md << " " << fixed(b, 0) << " |";
    md << " " << (std::isfinite(row.back()) ? fixed(row.back(), 0) : "-") << " |\n";
  }
  part.style = {"Memory per pixel: our buffers as allocated vs the papers' fixed layouts", "", "bytes per pixel", false, {}};
  part.bars = true;
  f.parts = {part};
  f.markdown = md.str();
  return f;
}

}  // namespace

std::unique_ptr<SceneFrame> load_scene_frame(const std::string& spec, const FigureOptions& o,
                                             const FigureProgress& progress) {
  if (progress) progress(scene_short_name(spec) + ": 64x SSAA reference");
  auto s = std::make_unique<SceneFrame>(load_scene_within(spec, 120.0), o.width, o.height);
  s->reference = s->render(technique_options("ssaa", 64)).image;
  return s;
}

SceneFrame::SceneFrame(Scene loaded, int width, int height)
    : scene(std::move(loaded)),
      gpu(scene),
      view(make_view(choose_camera(scene, std::nullopt), width, height)),
      output(gl::make_texture_2d(GL_RGBA16F, width, height)) {}

SceneFrame::Rendered SceneFrame::render(const TechniqueOptions& options) const {
  auto t = make_technique(options, view.width, view.height);
  return render(*t);
}

SceneFrame::Rendered SceneFrame::render(Technique& t) const {
  t.render(gpu, view, output.get());
  return {to_display(read_back_image(output.get(), view.width, view.height)), t.bytes_per_pixel()};
}

Figure make_figure(const std::string& name, const FigureOptions& o, const FigureProgress& progress) {
  if (o.scenes.empty()) throw std::invalid_argument("figures: no scene");
  if (o.frames < 2) throw std::invalid_argument("figures: --frames must be >= 2");
  if (!(o.pull_back >= 1.0) || !std::isfinite(o.pull_back)) throw std::invalid_argument("figures: --pull-back must be >= 1");
  validate_size(o.width, o.height);
  if (name == "fig9") return figure9(o, progress);
  if (name == "fig1") return figure1(o, progress);
  if (name == "dcaa") return dcaa_figure(o, progress);
  if (name == "agaa") return agaa_figure(o, progress);
  if (name == "memory") return memory_figure(o, progress);
  std::string known;
  for (const std::string& n : figure_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown figure '" + name + "' (known: " + known + ", all)");
}

void write_figure(const Figure& f, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (const Figure::Part& p : f.parts) {
    write_file_atomically(dir + "/" + p.stem + ".csv", table_csv(p.table));
    const FigureTable& drawn = p.plot_from.columns.empty() ? p.table : p.plot_from;
    if (p.bars) plot_bars(drawn, p.style, dir + "/" + p.stem + ".png");
    else plot_lines(drawn, p.style, dir + "/" + p.stem + ".png");
  }
  write_file_atomically(dir + "/" + f.name + ".md", f.markdown);
}

double capped_psnr(const DisplayImage& a, const DisplayImage& reference) {
  const double db = compare_images(a, reference).psnr_db;
  return std::isfinite(db) ? std::min(db, 99.0) : 99.0;
}

void markdown_table_head(std::ostream& md, const std::string& first, const std::vector<std::string>& columns) {
  md << "| " << first << " |";
  for (const std::string& c : columns) md << " " << c << " |";
  md << "\n| --- |";
  for (std::size_t c = 0; c < columns.size(); ++c) md << " --- |";
  md << "\n";
}

std::string fixed(double v, int decimals) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", decimals, v);
  return s;
}

}  // namespace rsaa::bench
