// The techniques by name (docs/conventions.md section 4): their options, and the registry that
// names, validates, labels and makes each one. A technique registers itself in its own file
// (runtime/techniques/NAME.cpp returns its TechniqueKind) and is listed once in
// runtime/techniques/registry.cpp: a new technique is one source file, its shaders and one line
// (options of its own are fields of TechniqueOptions and flags in tools/cli/technique_options.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/technique.h"

namespace rsaa {

// Every technique's options in one bag (what the command line fills); each technique reads and
// validates its own fields.
struct TechniqueOptions {
  std::string technique = "noaa";
  int samples = 0;                   // 0: the technique's default
  std::string similarity = "sadp-plane";  // rsaa: sadp-plane (default) | sadp | depth (the paper's)
  int auth = 1;                      // rsaa: 0 none, 1 post-pass (default), 2 pre-pass
  double threshold = -1.0;           // rsaa: < 0 = default (0.4 SADP, 0.4 % depth)
  std::string pattern;               // rsaa 4x: gl4x (default) | d3d4x
  int code_bits = 8;                 // rsaa: 8 | 16 | 32 bits per stored similarity
  std::string table;                 // rsaa: an offset table file (JSON); empty: the built-in one
  std::string prepass = "auto";      // rsaa: auto | jittered | msaa (RsaaSettings::prepass)
  std::string prepass_cull = "off";  // rsaa: off | neighbours (RsaaSettings::prepass_cull)
  double split_cap = 1.5;            // rsaa: 0 the paper's k-means split, else capped (RsaaSettings::split_cap)
  std::string multi_surface = "borrow";  // rsaa: borrow (default) | neighbours | fetch (the paper's)
  double borrow_weight = 0.75;       // rsaa: with borrow, the mean's share where only a far source calls for it
  std::string split_check = "neighbours";    // rsaa: neighbours (default) | off (the paper's)
  std::string fetch_check = "neighbours";    // rsaa: neighbours (default) | off (the paper's)
  std::string material_edges = "on";         // rsaa: on (default: the renderer knows each draw's
                                             // material) | off (geometry only, the paper's)
  std::string facet_edges = "auto";          // rsaa: auto (default: on with material edges) | on | off
                                             // (facets parted by shading creases, and flat surfaces,
                                             // differ by material: RsaaSettings::facet_materials)
  std::string post = "compute";      // rsaa: compute (edge list) | edges (two passes) | single (RsaaSettings::post)
  int kernel = 2;                    // ssaa-filtered: 1 box, 2 five-tap, 3 alpha-driven mix
  double agaa_k = 0.0;               // agaa: characteristic length of eq. 1 in scene units (the
                                     // paper's 0.1); 0: relative, agaa_k_pixels footprints
  double agaa_k_pixels = 4.0;        // agaa: k in pixel footprints at the surface
  int agaa_aggregates = 2;           // agaa: c, 1..4
  std::string agaa_diffuse = "filtered";  // agaa: filtered (Lambert term scaled by |Na|) | plain
  std::string rules = "surface";     // dyncov: surface | seed (core/reference/dynamic_coverage.h);
                                     // dcaa: surface | paper (core/reference/dcaa.h)
  bool z_prepass = false;            // dcaa, dyncov: DCAA's z-prepass (4x MSAA max depth)
  std::string shade = "fragment";    // dcaa: fragment (each fragment's colour, merged) | surface
                                     // (each surface shaded once from its merged attributes)
};

// What a technique registers.
struct TechniqueKind {
  std::string name;         // "rsaa", what --technique takes
  std::string description;  // one line for help texts
  // Throws std::invalid_argument naming the bad option (unsupported sample count, ...).
  void (*validate)(const TechniqueOptions& options);
  // "rsaa 8x sadp auth1", "ssaa 64x": the name in tables, plots and file names.
  std::string (*label)(const TechniqueOptions& options);
  // Needs a current GL 4.5 context; options validated. Sizes are those of the frames it renders.
  std::unique_ptr<Technique> (*make)(const TechniqueOptions& options, int width, int height);
};

// The registered techniques, in the order help texts list them.
const std::vector<TechniqueKind>& registered_techniques();
// Throws std::invalid_argument naming the known techniques when `name` is not one.
const TechniqueKind& find_technique(const std::string& name);
const std::vector<std::string>& technique_names();

// Options for a technique by name and sample count (0: its default), other fields defaulted.
TechniqueOptions technique_options(const std::string& technique, int samples = 0);
// The paper's 12 RSAA variants: samples 4 | 8 x similarity sadp | depth x auth 0 | 1 | 2.
std::vector<TechniqueOptions> rsaa_variants();
// RSAA 4x and 8x with this project's default options (sadp-plane, post-pass authentication, the
// split capped at 1.5 thresholds, the multi-surface resolve).
std::vector<TechniqueOptions> rsaa_defaults();
// RSAA 8x sadp-plane auth 0 with the paper's resolve (no split cap, one fetch everywhere): the
// default before the extensions, measured beside them.
TechniqueOptions rsaa_default_without_extensions();

// The registry's validate, label and make for options.technique. validate throws
// std::invalid_argument naming the bad option (unknown technique, unsupported sample count, ...).
void validate(const TechniqueOptions& options);
std::string technique_label(const TechniqueOptions& options);
// Whether rsaa's facet edges are on: "on", or "auto" (the default) with material edges on.
bool facet_edges_on(const TechniqueOptions& options);
// Whether the technique draws with facet materials (rsaa --facet-edges on): its scene must be
// uploaded with the facet colours (GpuScene(scene, true)).
bool needs_facet_colours(const TechniqueOptions& options);
bool needs_facet_colours(const std::vector<TechniqueOptions>& options);
std::unique_ptr<Technique> make_technique(const TechniqueOptions& options, int width, int height);

// options.samples, or `fallback` when 0 (the technique's default).
inline int samples_or(const TechniqueOptions& options, int fallback) {
  return options.samples ? options.samples : fallback;
}

}  // namespace rsaa
