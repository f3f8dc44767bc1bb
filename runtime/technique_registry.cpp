#include "runtime/technique_registry.h"

#include <stdexcept>

namespace rsaa {

const TechniqueKind& find_technique(const std::string& name) {
  for (const TechniqueKind& kind : registered_techniques())
    if (kind.name == name) return kind;
  std::string known;
  for (const auto& n : technique_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown technique '" + name + "' (known: " + known + ")");
}

const std::vector<std::string>& technique_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const TechniqueKind& kind : registered_techniques()) out.push_back(kind.name);
    return out;
  }();
  return names;
}

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
        o.split_cap = 0.0;  // the paper's split and resolve
        o.multi_surface = "fetch";
        o.split_check = "off";
        o.fetch_check = "off";
        o.material_edges = "off";
        o.facet_edges = "off";
        list.push_back(o);
      }
  return list;
}

std::vector<TechniqueOptions> rsaa_defaults() {
  return {technique_options("rsaa", 4), technique_options("rsaa", 8)};
}

TechniqueOptions rsaa_default_without_extensions() {
  TechniqueOptions o = technique_options("rsaa", 8);
  o.auth = 0;
  o.split_cap = 0.0;
  o.multi_surface = "fetch";
  o.split_check = "off";
  o.fetch_check = "off";
  o.material_edges = "off";
  o.facet_edges = "off";
  return o;
}

void validate(const TechniqueOptions& o) {
  const TechniqueKind& kind = find_technique(o.technique);
  if (!o.table.empty() && o.technique != "rsaa")
    throw std::invalid_argument("--table is an rsaa option, not " + o.technique + "'s");
  if (!o.pattern.empty() && o.technique != "rsaa")
    throw std::invalid_argument("--pattern is an rsaa option, not " + o.technique + "'s");
  kind.validate(o);
}

std::string technique_label(const TechniqueOptions& o) { return find_technique(o.technique).label(o); }

bool facet_edges_on(const TechniqueOptions& o) {
  return o.facet_edges == "on" || (o.facet_edges == "auto" && o.material_edges == "on");
}

bool needs_facet_colours(const TechniqueOptions& o) { return o.technique == "rsaa" && facet_edges_on(o); }

bool needs_facet_colours(const std::vector<TechniqueOptions>& options) {
  for (const TechniqueOptions& o : options)
    if (needs_facet_colours(o)) return true;
  return false;
}

std::unique_ptr<Technique> make_technique(const TechniqueOptions& o, int width, int height) {
  validate(o);
  return find_technique(o.technique).make(o, width, height);
}

}  // namespace rsaa
