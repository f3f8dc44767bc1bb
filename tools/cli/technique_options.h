// The technique options shared by the commands that render (render, view, bench).
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "runtime/technique_registry.h"
#include "tools/cli/options.h"

namespace rsaa::cli {

// Longest a scene file may take to load before the command gives up with an error.
// Within the 60 s an input may take in all (docs/reliability.md).
constexpr double kSceneLoadSeconds = 40.0;

inline void add_technique_options(CLI::App* cmd, TechniqueOptions& o) {
  std::string techniques;  // from the registry: name (description), ...
  for (const TechniqueKind& kind : registered_techniques())
    techniques += (techniques.empty() ? "" : "; ") + kind.name + ": " + kind.description;
  cmd->add_option("--technique", o.technique, techniques)->capture_default_str();
  cmd->add_option("--samples", o.samples,
                  "msaa: 4 (hardware); ssaa: 8 (d3d8x) | 16 | 64; rsaa: 4 | 8 (default 8); agaa: 4 (hardware) | 8 "
                  "(jittered, default) | 16 (jittered)")
      ->check(whole_range(1, 64));  // given, a count: 0 stands for "not given" inside
  cmd->add_option("--similarity", o.similarity, "rsaa: sadp-plane (SADP or the gap between the surfaces' planes along the view ray, which finds silhouettes over grazing surfaces) | sadp | depth (the paper's two)")->capture_default_str();
  cmd->add_option("--auth", o.auth, "rsaa authentication: 0 none, 1 post-pass, 2 pre-pass")
      ->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--threshold", o.threshold,
                  "rsaa similarity threshold (default 0.4: SADP units, or percent of depth)")
      ->check(finite_range(0.0, 1e30));
  cmd->add_option("--pattern", o.pattern, "rsaa 4x sample pattern: gl4x (driver, default) | d3d4x");
  cmd->add_option("--table", o.table,
                  "rsaa: an offset table file (JSON: rsaa train, train --from-scene, a custom pattern) "
                  "instead of the built-in table; the pre-pass samples the table's positions");
  cmd->add_option("--prepass", o.prepass,
                  "rsaa pre-pass: auto (msaa where the driver can, else records while they fit 256 MiB, else "
                  "jittered) | jittered (one draw per "
                  "subsample) | msaa (one multisample draw writing surface records, then two compute passes "
                  "making the codes; where the driver samples the table's positions, one draw at twice the width "
                  "or height for a cell pattern such as tables/custom-gl4x-wide.json, or two draws, the second "
                  "shifted, for a union pattern such as tables/custom-gl4x-union.json) | records (one draw per "
                  "subsample writing surface records, the codes made as for msaa)")
      ->capture_default_str();
  cmd->add_option("--prepass-cull", o.prepass_cull,
                  "rsaa (ours): off | neighbours (the jittered pre-pass draws only where the 3x3 neighbourhood "
                  "shows another surface; a feature thinner than a pixel between pixel centres is missed)")
      ->capture_default_str();
  cmd->add_option("--split-cap", o.split_cap,
                  "rsaa (ours): cap the k-means split at this many thresholds (>= 1), so a clearly different "
                  "subsample is dissimilar even beside a far more different third surface; 0 = the paper's split")
      ->capture_default_str()
      ->check(finite_range(0.0, 1e30));
  cmd->add_option("--multi-surface", o.multi_surface,
                  "rsaa (ours): fetch (one bilinear fetch, the paper) | neighbours (pixels whose dissimilar "
                  "subsamples point at two different surfaces: mean over subsamples of the outside pixels' colours) | "
                  "borrow (as neighbours, each dissimilar subsample's colour taken from the pixel within two whose "
                  "centre shows its surface, also where only a pixel beyond the 3x3 does; needs a pre-pass writing "
                  "records, as neighbours with the jittered one)")
      ->capture_default_str();
  cmd->add_option("--borrow-weight", o.borrow_weight,
                  "rsaa (ours): with --multi-surface borrow, the share of the subsamples' mean where only a source "
                  "beyond the 3x3 calls for it (no 3+ surfaces), the rest the table's fetch; 1 = the mean alone")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--split-check", o.split_check,
                  "rsaa (ours): neighbours (a subsample above the threshold that the split calls similar is "
                  "dissimilar when the outside pixel in its direction shows a surface about as different) | "
                  "off (the paper's split decides)")
      ->capture_default_str();
  cmd->add_option("--fetch-check", o.fetch_check,
                  "rsaa (ours): neighbours (a pixel none of whose dissimilar subsamples finds a surface about as "
                  "different in the outside pixel in its direction fetches with half the offset) | off (the paper's "
                  "fetch)")
      ->capture_default_str();
  cmd->add_option("--material-edges", o.material_edges,
                  "rsaa (ours): off (subsamples compare geometry only, the paper) | on (a subsample on another "
                  "material than the centre's is dissimilar: colour edges between coplanar parts)")
      ->capture_default_str();
  cmd->add_option("--facet-edges", o.facet_edges,
                  "rsaa (ours): auto (on with --material-edges on) | on (needs --material-edges on) | off "
                  "(triangles parted by a crease of their shading "
                  "normals, and flat surfaces, get materials of their own, so a subsample on another facet of a "
                  "flat-shaded mesh is dissimilar: the shading creases the geometry calls one surface)")
      ->capture_default_str();
  cmd->add_option("--post", o.post,
                  "rsaa post-process: compute (a compute shader lists the pixels to resolve, the resolve runs "
                  "on the list) | edges (an edge pass marks them in a depth target, the resolve runs behind "
                  "a depth test) | single (one pass over every pixel); the same image")
      ->capture_default_str();
  cmd->add_option("--code-bits", o.code_bits, "rsaa bits per stored similarity: 8 | 16 | 32")
      ->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--kernel", o.kernel,
                  "ssaa-filtered downsampling: 1 box 2x2, 2 five-tap rotated grid, 3 lerp of a large "
                  "and the five-tap kernel by the object's filter alpha")
      ->capture_default_str()
      ->check(kWholeNumber);
  cmd->add_option("--agaa-k", o.agaa_k,
                  "agaa: characteristic length of the clustering distance in scene units (the paper: 10 cm); "
                  "0 (default): relative, --agaa-k-pixels")
      ->capture_default_str();
  cmd->add_flag("--z-prepass", o.z_prepass,
                "dcaa, dyncov: cull fragments behind the farthest of 4 hardware MSAA depths (DCAA's section 4.2)");
  cmd->add_option("--agaa-diffuse", o.agaa_diffuse,
                  "agaa: filtered (Lambert term scaled by the aggregate's mean normal length) | plain")
      ->capture_default_str();
  cmd->add_option("--agaa-aggregates", o.agaa_aggregates, "agaa: c, aggregates per pixel (1-4)")->capture_default_str();
  cmd->add_option("--agaa-k-pixels", o.agaa_k_pixels,
                  "agaa: characteristic length in pixel footprints at the surface (independent of the units)")
      ->capture_default_str();
  cmd->add_option("--shade", o.shade,
                  "dcaa: fragment (each fragment shaded at the pixel centre, colours merged) | surface (fragments "
                  "carry albedo and shading normal, each visible surface shaded once from its merged attributes)")
      ->capture_default_str();
  cmd->add_option("--rules", o.rules,
                  "dyncov: surface (merge fragments of one surface, per-sample visibility) | seed (the seed's "
                  "rules as written); dcaa: surface | paper (Algorithm 1 as written)")
      ->capture_default_str();
}

// Options that only some techniques read, given with another technique, are refused: they would
// change nothing without a word (render --technique noaa --similarity bogus exited 0). (Not for
// `view`, whose keys switch techniques.)
inline void refuse_options_of_other_techniques(const CLI::App& cmd, const std::string& technique) {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> readers = {
      {"--similarity", {"rsaa"}},      {"--auth", {"rsaa"}},         {"--threshold", {"rsaa"}},
      {"--prepass", {"rsaa"}},         {"--prepass-cull", {"rsaa"}}, {"--split-cap", {"rsaa"}},
      {"--multi-surface", {"rsaa"}},   {"--split-check", {"rsaa"}},  {"--fetch-check", {"rsaa"}},
      {"--material-edges", {"rsaa"}},  {"--facet-edges", {"rsaa"}},  {"--post", {"rsaa"}},         {"--code-bits", {"rsaa"}},
      {"--kernel", {"ssaa-filtered"}}, {"--agaa-k", {"agaa"}},       {"--agaa-diffuse", {"agaa"}},
      {"--agaa-aggregates", {"agaa"}}, {"--agaa-k-pixels", {"agaa"}}, {"--z-prepass", {"dcaa", "dyncov"}},
      {"--shade", {"dcaa", "dyncov"}}, {"--rules", {"dcaa", "dyncov"}}};
  for (const auto& [option, techniques] : readers) {
    if (cmd.count(option) == 0 || std::find(techniques.begin(), techniques.end(), technique) != techniques.end())
      continue;
    // A flag given as false (--z-prepass=false) asks for nothing.
    if (const CLI::Option* given = cmd.get_option_no_throw(option);
        given && given->get_items_expected_max() == 0 && !given->as<bool>())
      continue;
    std::string by;
    for (const std::string& t : techniques) by += (by.empty() ? "" : " and ") + t;
    throw std::invalid_argument(option + " is an option of " + by + ", not of " + technique +
                                " (which it would leave unchanged)");
  }
}

}  // namespace rsaa::cli
