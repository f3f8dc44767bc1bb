// Every anti-aliasing technique is a render pass behind this one interface (Falcor-style),
// chosen by name (docs/conventions.md section 4): noaa, msaa, ssaa, rsaa, ...
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/gpu_scene.h"
#include "runtime/pass_timer.h"

namespace rsaa {

struct TechniqueOptions {
  std::string technique = "noaa";
  int samples = 0;                   // 0: the technique's default
  std::string similarity = "sadp-plane";  // rsaa: sadp-plane (default) | sadp | depth (the paper's)
  int auth = 0;                      // rsaa: 0 none, 1 post-pass, 2 pre-pass
  double threshold = -1.0;           // rsaa: < 0 = default (0.4 SADP, 0.4 % depth)
  std::string pattern;               // rsaa 4x: gl4x (default) | d3d4x
  int code_bits = 8;                 // rsaa: 8 | 16 | 32 bits per stored similarity
  std::string table;                 // rsaa: an offset table file (JSON); empty: the built-in one
  std::string prepass = "jittered";  // rsaa: jittered | msaa (RsaaSettings::prepass)
  double split_cap = 0.0;            // rsaa: 0 the paper's k-means split, else capped (RsaaSettings::split_cap)
  std::string multi_surface = "fetch";  // rsaa: fetch (the paper) | neighbours (RsaaSettings::multi_surface)
  int kernel = 2;                    // ssaa-filtered: 1 box, 2 five-tap, 3 alpha-driven mix
  double agaa_k = 0.0;               // agaa: characteristic length of eq. 1 in scene units (the
                                     // paper's 0.1); 0: relative, agaa_k_pixels footprints
  double agaa_k_pixels = 4.0;        // agaa: k in pixel footprints at the surface
  int agaa_aggregates = 2;           // agaa: c, 1..4
  std::string agaa_diffuse = "filtered";  // agaa: filtered (Lambert term scaled by |Na|) | plain
  std::string rules = "surface";     // dyncov: surface | seed (core/dynamic_coverage.h);
                                     // dcaa: surface | paper (core/dcaa.h)
  bool z_prepass = false;            // dcaa, dyncov: DCAA's z-prepass (4x MSAA max depth)
};

// Options for a technique by name and sample count (0: its default), other fields defaulted.
TechniqueOptions technique_options(const std::string& technique, int samples = 0);

// The paper's 12 RSAA variants: samples 4 | 8 x similarity sadp | depth x auth 0 | 1 | 2.
std::vector<TechniqueOptions> rsaa_variants();
// The split cap the bench measures with the multi-surface resolve (RsaaSettings::split_cap):
// measured best of 1, 1.25, 1.5, 1.75, 2, 2.5, 3 (no bench scene below the paper's split).
constexpr double kRsaaSplitCap = 1.5;
// RSAA 8x default options with the extensions beyond the paper: --multi-surface neighbours, and
// with it --split-cap kRsaaSplitCap (the cap alone loses on thin curved wires: not a row).
std::vector<TechniqueOptions> rsaa_extensions();
// RSAA 4x and 8x with this project's default options (sadp-plane, auth 0).
std::vector<TechniqueOptions> rsaa_defaults();

// Throws std::invalid_argument naming the bad option (unknown technique, unsupported sample
// count, auth outside 0..2, ...).
void validate(const TechniqueOptions& options);
// "rsaa 8x sadp auth1", "ssaa 64x", ...
std::string technique_label(const TechniqueOptions& options);
const std::vector<std::string>& technique_names();

class Technique {
 public:
  virtual ~Technique() = default;
  // Renders a frame of `scene` into `output`, an RGBA16F texture of view.width x view.height
  // holding linear colour.
  virtual void render(const GpuScene& scene, const View& view, GLuint output) = 0;
  // Bytes per pixel of every buffer the technique keeps for a frame.
  virtual double bytes_per_pixel() const = 0;
  // The per-pixel fragment lists of a coverage technique (dcaa, dyncov), else nullptr: for tests
  // that compare the GL resolve with the CPU reference on the same fragments.
  virtual class CoverageFragmentLists* coverage_lists() { return nullptr; }
  // GL times of the passes of the last frame.
  std::vector<PassTime> take_pass_times() { return timer_.collect(); }

 protected:
  PassTimer timer_;
};

// Needs a current GL 4.5 context. Sizes are those of the frames it will render.
std::unique_ptr<Technique> make_technique(const TechniqueOptions& options, int width, int height);

}  // namespace rsaa
