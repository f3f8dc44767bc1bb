#include "runtime/technique.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/dynamic_coverage.h"
#include "runtime/techniques/techniques.h"

namespace rsaa {
namespace {

int samples_or(const TechniqueOptions& o, int fallback) { return o.samples ? o.samples : fallback; }

}  // namespace

TechniqueOptions technique_options(const std::string& technique, int samples) {
  TechniqueOptions o;
  o.technique = technique;
  o.samples = samples;
  return o;
}

std::vector<TechniqueOptions> rsaa_variants() {
  std::vector<TechniqueOptions> list;
  for (int samples : {4, 8})
    for (const char* similarity : {"sadp", "depth"})
      for (int auth : {0, 1, 2}) {
        TechniqueOptions o = technique_options("rsaa", samples);
        o.similarity = similarity;
        o.auth = auth;
        list.push_back(o);
      }
  return list;
}

std::vector<TechniqueOptions> rsaa_defaults() {
  return {technique_options("rsaa", 4), technique_options("rsaa", 8)};
}

std::vector<TechniqueOptions> rsaa_extensions() {
  TechniqueOptions multi = technique_options("rsaa", 8);
  multi.multi_surface = "neighbours";
  TechniqueOptions both = multi;
  both.split_cap = kRsaaSplitCap;
  return {multi, both};
}

const std::vector<std::string>& technique_names() {
  static const std::vector<std::string> names = {"noaa", "fxaa", "msaa", "ssaa", "ssaa-filtered", "rsaa", "dcaa", "dyncov", "agaa"};
  return names;
}

void validate(const TechniqueOptions& o) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!o.table.empty() && o.technique != "rsaa") bad("--table is an rsaa option, not " + o.technique + "'s");
  if (o.technique == "noaa" || o.technique == "fxaa") {
    if (o.samples > 1) bad(o.technique + " takes no --samples");
  } else if (o.technique == "dcaa") {
    if (o.samples != 0 && o.samples != 64) bad("dcaa always uses 64 coverage samples");
    dcaa_settings(o.rules);
  } else if (o.technique == "agaa") {
    const int n = samples_or(o, 8);
    if (n != 4 && n != 8) bad("agaa --samples must be 4 (hardware) or 8 (jittered), not " + std::to_string(n));
    if (!(o.agaa_k >= 0.0) || !std::isfinite(o.agaa_k)) bad("agaa --agaa-k must be a finite length >= 0");
    if (o.agaa_diffuse != "filtered" && o.agaa_diffuse != "plain") bad("agaa --agaa-diffuse must be filtered or plain");
    if (o.agaa_aggregates < 1 || o.agaa_aggregates > 4) bad("agaa --agaa-aggregates must be 1, 2, 3 or 4");
    if (!(o.agaa_k_pixels > 0.0) || !std::isfinite(o.agaa_k_pixels)) bad("agaa --agaa-k-pixels must be finite and > 0");
  } else if (o.technique == "dyncov") {
    if (o.samples != 0 && o.samples != 16) bad("dyncov always uses 16 coverage samples");
    dynamic_coverage_rules(o.rules);
  } else if (o.technique == "msaa") {
    // llvmpipe's only multisample count is 4; a jittered 8-sample baseline shades every sample,
    // which is supersampling, so it is named ssaa --samples 8.
    const int n = samples_or(o, 4);
    if (n == 8) bad("msaa --samples 8: the driver has no 8x MSAA; its jittered stand-in shades every sample: use ssaa --samples 8");
    if (n != 4) bad("msaa --samples must be 4, not " + std::to_string(n));
  } else if (o.technique == "ssaa") {
    const int n = samples_or(o, 64);
    if (n != 8 && n != 16 && n != 64) bad("ssaa --samples must be 8, 16 or 64, not " + std::to_string(n));
  } else if (o.technique == "ssaa-filtered") {
    if (o.samples != 0 && o.samples != 4) bad("ssaa-filtered always uses 4 samples (2x2)");
    if (o.kernel < 1 || o.kernel > 3) bad("ssaa-filtered --kernel must be 1, 2 or 3");
  } else if (o.technique == "rsaa") {
    const int n = samples_or(o, 8);
    if (o.table.empty() && n != 4 && n != 8) bad("rsaa --samples must be 4 or 8, not " + std::to_string(n));
    if (o.similarity != "sadp" && o.similarity != "depth" && o.similarity != "sadp-plane")
      bad("rsaa --similarity must be sadp, depth or sadp-plane, not '" + o.similarity + "'");
    if (o.auth < 0 || o.auth > 2) bad("rsaa --auth must be 0, 1 or 2");
    if (!o.pattern.empty()) {
      if (n == 8 && o.pattern != "d3d8x") bad("rsaa --samples 8 uses --pattern d3d8x");
      if (n == 4 && o.pattern != "gl4x" && o.pattern != "d3d4x")
        bad("rsaa --samples 4 uses --pattern gl4x or d3d4x");
    }
    if (o.prepass != "jittered" && o.prepass != "msaa")
      bad("rsaa --prepass must be jittered or msaa, not '" + o.prepass + "'");
    if (!o.table.empty() && !o.pattern.empty())
      bad("rsaa --table brings its own sample pattern: leave out --pattern");
    if (o.code_bits != 8 && o.code_bits != 16 && o.code_bits != 32)
      bad("rsaa --code-bits must be 8, 16 or 32");
    if (!(o.split_cap == 0.0 || (o.split_cap >= 1.0 && std::isfinite(o.split_cap))))
      bad("rsaa --split-cap must be 0 (the paper's split) or a finite number >= 1");
    if (o.multi_surface != "fetch" && o.multi_surface != "neighbours")
      bad("rsaa --multi-surface must be fetch or neighbours, not '" + o.multi_surface + "'");
    if (o.threshold >= 0.0 ? !std::isfinite(o.threshold) : o.threshold != -1.0)
      bad("rsaa --threshold must be a finite number >= 0");
  } else {
    std::string known;
    for (const auto& n : technique_names()) known += (known.empty() ? "" : ", ") + n;
    bad("unknown technique '" + o.technique + "' (known: " + known + ")");
  }
}

// " cap2.5", " ms": the options beyond the paper, when not the paper's.
static std::string rsaa_extension_label(const TechniqueOptions& o) {
  std::string label;
  if (o.split_cap > 0.0) {
    std::ostringstream cap;
    cap << " cap" << o.split_cap;
    label += cap.str();
  }
  if (o.multi_surface != "fetch") label += " ms";
  return label;
}

std::string technique_label(const TechniqueOptions& o) {
  if (o.technique == "dyncov")
    return std::string("dyncov") + (o.rules == TechniqueOptions{}.rules ? "" : " " + o.rules) + (o.z_prepass ? " zpre" : "");
  if (o.technique == "dcaa")
    return std::string("dcaa") + (o.rules == TechniqueOptions{}.rules ? "" : " " + o.rules) + (o.z_prepass ? " zpre" : "");
  if (o.technique == "noaa" || o.technique == "fxaa") return o.technique;
  if (o.technique == "msaa") return "msaa " + std::to_string(samples_or(o, 4)) + "x";
  if (o.technique == "ssaa") return "ssaa " + std::to_string(samples_or(o, 64)) + "x";
  if (o.technique == "ssaa-filtered") return "ssaa-filtered k" + std::to_string(o.kernel);
  if (o.technique == "agaa") {
    std::string label = "agaa " + std::to_string(samples_or(o, 8)) + "x";
    std::ostringstream k;
    if (o.agaa_k > 0.0) k << " k" << o.agaa_k;
    else if (o.agaa_k_pixels != TechniqueOptions{}.agaa_k_pixels) k << " k" << o.agaa_k_pixels << "px";
    if (o.agaa_aggregates != TechniqueOptions{}.agaa_aggregates) k << " c" << o.agaa_aggregates;
    if (o.agaa_diffuse != TechniqueOptions{}.agaa_diffuse) k << " " << o.agaa_diffuse;
    return label + k.str();
  }
  if (!o.table.empty()) {  // the table's file name stands for its pattern and sample count
    const std::size_t slash = o.table.find_last_of('/');
    std::string stem = o.table.substr(slash == std::string::npos ? 0 : slash + 1);
    if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0) stem.resize(stem.size() - 5);
    return "rsaa table " + stem + " " + o.similarity + " auth" + std::to_string(o.auth) +
           (o.prepass == "jittered" ? "" : " " + o.prepass) + rsaa_extension_label(o);
  }
  const int n = samples_or(o, 8);
  std::string label = "rsaa " + std::to_string(n) + "x ";
  if (n == 4) label += (o.pattern.empty() ? std::string("gl4x") : o.pattern) + " ";
  return label + o.similarity + " auth" + std::to_string(o.auth) + (o.prepass == "jittered" ? "" : " " + o.prepass) +
         rsaa_extension_label(o);
}

std::unique_ptr<Technique> make_technique(const TechniqueOptions& o, int width, int height) {
  validate(o);
  if (o.technique == "noaa") return make_noaa(width, height);
  if (o.technique == "fxaa") return make_fxaa(width, height);
  if (o.technique == "dcaa") return make_dcaa(dcaa_settings(o.rules), o.z_prepass, width, height);
  if (o.technique == "dyncov") return make_dynamic_coverage(dynamic_coverage_rules(o.rules), o.z_prepass, width, height);
  if (o.technique == "agaa") {
    AgaaSettings s;
    s.k = float(o.agaa_k);
    s.aggregates = o.agaa_aggregates;
    s.filtered_diffuse = o.agaa_diffuse == "filtered";
    return make_agaa(samples_or(o, 8), s, float(o.agaa_k > 0.0 ? 0.0 : o.agaa_k_pixels), width, height);
  }
  if (o.technique == "ssaa-filtered") return make_filtered_ssaa(o.kernel, width, height);
  if (o.technique == "msaa") return make_hardware_msaa(4, width, height);
  if (o.technique == "ssaa") {
    if (samples_or(o, 64) == 8) return make_jittered_supersampling(builtin_pattern("d3d8x").positions, width, height);
    return make_jittered_supersampling(stratified_positions(samples_or(o, 64) == 64 ? 8 : 4, 64),
                                       width, height);
  }
  return make_rsaa(rsaa_settings(o), width, height);
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
  s.split_cap = float(o.split_cap);
  s.multi_surface = o.multi_surface;
  return s;
}

}  // namespace rsaa
