// rsaa: the 1x frame with its G-buffer, the RsaaPass pre-pass, and the post-process.
#include <sstream>

#include "core/rsaa/offset_table.h"
#include "runtime/rsaa_pass.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

class Rsaa : public Technique {
 public:
  Rsaa(const RsaaSettings& settings, int width, int height)
      : pass_(settings, width, height),
        renderer_(settings.facet_materials),
        targets_(width, height, settings.material_edges),
        material_edges_(settings.material_edges),
        in_place_(settings.post == "compute") {}

  void render(const GpuScene& scene, const View& view, GLuint output) override {
    // With the compute post-process the frame is drawn into the output and resolved in place (no
    // copy of the image).
    if (in_place_) targets_.use_colour(output);
    timer_.begin("main");
    renderer_.draw_gbuffer(scene, view, targets_);
    timer_.end();

    const RsaaFrame frame = targets_.frame(view.inverse_projection());
    timer_.begin("pre-pass");
    pass_.render_subsamples(frame, [&](GLuint program, glm::vec2 jitter) {
      SceneRenderer::draw_in_current_viewport(scene, view, jitter, program);
    });
    timer_.end();
    timer_.begin("post-process");
    pass_.resolve(frame, output, mask_output_);
    timer_.end();
  }

  std::string choices() const override { return "pre-pass in use: " + pass_.prepass_description(); }

  double bytes_per_pixel() const override {
    return RsaaTargets::bytes_per_pixel(material_edges_) + pass_.bytes_per_pixel(in_place_);
  }

  void set_mask_output(GLuint texture) { mask_output_ = texture; }

 private:
  RsaaPass pass_;
  SceneRenderer renderer_;
  RsaaTargets targets_;
  GLuint mask_output_ = 0;
  bool material_edges_, in_place_;
};

}  // namespace

std::unique_ptr<Technique> make_rsaa(const RsaaSettings& settings, int width, int height,
                                     GLuint mask_output) {
  auto t = std::make_unique<Rsaa>(settings, width, height);
  t->set_mask_output(mask_output);
  return t;
}

RsaaSettings rsaa_settings(const TechniqueOptions& o) {
  RsaaSettings s;
  if (!o.table.empty()) {
    s.table = std::make_shared<const OffsetTable>(read_offset_table(o.table));
    const int table_samples = s.table->pattern.size();
    if (o.samples != 0 && o.samples != table_samples)
      throw std::invalid_argument("--table " + o.table + " is for " + std::to_string(table_samples) +
                                  " samples (pattern '" + s.table->pattern.name + "'), but --samples is " +
                                  std::to_string(o.samples));
    s.pattern.clear();  // the table's own
  } else {
    const int n = samples_or(o, 8);
    s.pattern = n == 8 ? "d3d8x" : o.pattern.empty() ? "gl4x" : o.pattern;
  }
  s.similarity = o.similarity;
  s.auth = o.auth;
  s.threshold = o.threshold >= 0.0 ? float(o.threshold) : 0.4f;
  s.code_bits = o.code_bits;
  s.prepass = o.prepass;
  s.prepass_cull = o.prepass_cull;
  s.split_cap = float(o.split_cap);
  s.multi_surface = o.multi_surface;
  s.borrow_weight = float(o.borrow_weight);
  s.split_check = o.split_check;
  s.fetch_check = o.fetch_check;
  s.material_edges = o.material_edges == "on";
  s.facet_materials = facet_edges_on(o);
  s.post = o.post;
  return s;
}

namespace {

void validate_rsaa(const TechniqueOptions& o) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  const int n = samples_or(o, 8);
  if (o.table.empty() && n != 4 && n != 8) bad("rsaa --samples must be 4 or 8, not " + std::to_string(n));
  if (o.similarity != "sadp" && o.similarity != "depth" && o.similarity != "sadp-plane")
    bad("rsaa --similarity must be sadp, depth or sadp-plane, not '" + o.similarity + "'");
  if (o.auth < 0 || o.auth > 2) bad("rsaa --auth must be 0, 1 or 2");
  if (!o.table.empty() && !o.pattern.empty()) bad("rsaa --table brings its own sample pattern: leave out --pattern");
  if (!o.pattern.empty()) {
    // Without --samples the count is the default 8: say so rather than name a --samples not given.
    const std::string samples = o.samples ? "--samples " + std::to_string(n) : "8 subsamples (the default)";
    if (n == 8 && o.pattern != "d3d8x") bad("rsaa " + samples + " uses --pattern d3d8x, not '" + o.pattern + "'");
    if (n == 4 && o.pattern != "gl4x" && o.pattern != "d3d4x") bad("rsaa --samples 4 uses --pattern gl4x or d3d4x");
  }
  if (o.prepass != "auto" && o.prepass != "jittered" && o.prepass != "msaa" && o.prepass != "records")
    bad("rsaa --prepass must be auto, jittered, msaa or records, not '" + o.prepass + "'");
  if (o.prepass_cull != "off" && o.prepass_cull != "neighbours")
    bad("rsaa --prepass-cull must be off or neighbours, not '" + o.prepass_cull + "'");
  if (o.prepass_cull != "off" && (o.prepass == "msaa" || o.prepass == "records"))
    bad("rsaa --prepass-cull needs --prepass jittered (or auto)");
  if (o.code_bits != 8 && o.code_bits != 16 && o.code_bits != 32) bad("rsaa --code-bits must be 8, 16 or 32");
  if (o.threshold >= 0.0 ? !std::isfinite(o.threshold) : o.threshold != -1.0)
    bad("rsaa --threshold must be a finite number >= 0");
  if (!(o.split_cap == 0.0 || (o.split_cap >= 1.0 && std::isfinite(o.split_cap))))
    bad("rsaa --split-cap must be 0 (the paper's split) or a finite number >= 1");
  if (o.multi_surface != "fetch" && o.multi_surface != "neighbours" && o.multi_surface != "borrow")
    bad("rsaa --multi-surface must be fetch, neighbours or borrow, not '" + o.multi_surface + "'");
  if (!(o.borrow_weight >= 0.0 && o.borrow_weight <= 1.0))
    bad("rsaa --borrow-weight must be a number in [0, 1]");
  if (o.borrow_weight != TechniqueOptions{}.borrow_weight && o.multi_surface != "borrow")
    bad("rsaa --borrow-weight needs --multi-surface borrow");
  if (o.split_check != "off" && o.split_check != "neighbours")
    bad("rsaa --split-check must be off or neighbours, not '" + o.split_check + "'");
  if (o.fetch_check != "off" && o.fetch_check != "neighbours")
    bad("rsaa --fetch-check must be off or neighbours, not '" + o.fetch_check + "'");
  if (o.material_edges != "off" && o.material_edges != "on")
    bad("rsaa --material-edges must be off or on, not '" + o.material_edges + "'");
  if (o.facet_edges != "off" && o.facet_edges != "on" && o.facet_edges != "auto")
    bad("rsaa --facet-edges must be off, on or auto, not '" + o.facet_edges + "'");
  if (o.facet_edges == "on" && o.material_edges != "on")
    bad("rsaa --facet-edges on needs --material-edges on (facets differ by their materials)");
  if (o.post != "edges" && o.post != "compute" && o.post != "single")
    bad("rsaa --post must be edges, compute or single, not '" + o.post + "'");
}

// " cap1.5 ms sc fc me": the options beyond the paper, when used.
std::string rsaa_extension_label(const TechniqueOptions& o) {
  std::ostringstream label;
  if (o.split_cap > 0.0) label << " cap" << o.split_cap;
  if (o.multi_surface == "neighbours") label << " ms";
  if (o.multi_surface == "borrow") label << " mb";
  if (o.multi_surface == "borrow" && o.borrow_weight != TechniqueOptions{}.borrow_weight) label << o.borrow_weight;
  if (o.split_check != "off") label << " sc";
  if (o.fetch_check != "off") label << " fc";
  if (o.material_edges != "off") label << " me";
  if (facet_edges_on(o)) label << " fe";
  if (o.post != "compute") label << " " << o.post << "-pass";
  if (o.prepass_cull != "off") label << " cull";
  return label.str();
}

std::string rsaa_label(const TechniqueOptions& o) {
  const std::string tail = " " + o.similarity + " auth" + std::to_string(o.auth) +
                           (o.prepass == "auto" ? "" : " " + o.prepass) + rsaa_extension_label(o);
  if (!o.table.empty()) {  // the table's file name stands for its pattern and sample count
    const std::size_t slash = o.table.find_last_of('/');
    std::string stem = o.table.substr(slash == std::string::npos ? 0 : slash + 1);
    if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0) stem.resize(stem.size() - 5);
    return "rsaa table " + stem + tail;
  }
  const int n = samples_or(o, 8);
  return "rsaa " + std::to_string(n) + "x" + (n == 4 ? " " + (o.pattern.empty() ? std::string("gl4x") : o.pattern) : "") +
         tail;
}

}  // namespace

TechniqueKind rsaa_technique() {
  return {"rsaa", "Resampling Anti-Aliasing: similarity mask -> table offset -> one bilinear fetch",
          validate_rsaa, rsaa_label, [](const TechniqueOptions& o, int width, int height) {
            return make_rsaa(rsaa_settings(o), width, height);
          }};
}

}  // namespace rsaa
