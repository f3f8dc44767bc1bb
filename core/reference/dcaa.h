// CPU reference of Decoupled Coverage Anti-Aliasing (DCAA, seed 000): at most 4 surfaces per pixel,
// each a coverage mask over 64 samples, a depth plane, a facet normal and a colour; fragments are
// merged into surfaces in primitive order by the paper's Algorithm 1, then resolved per coverage
// sample by depth. The GL technique (runtime/techniques/dcaa.cpp, shaders/coverage_resolve.frag)
// implements the same rules; this is the oracle its tests compare against.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/reference/coverage_fragment.h"
#include "core/rsaa/sample_pattern.h"

namespace rsaa {

// The surface rules' colour tolerance of the first merge (DcaaSettings::merge_colour_tolerance).
constexpr float kMergeColourToleranceDefault = 0.06f;

struct DcaaSettings {
  int max_surfaces = 4;
  float cos_normal_threshold = 0.98078528f;  // cos(pi / 16), the paper's aligned-normal rule
  // Second merge, which surface counts as least visible: false (the paper) = the coarse depth
  // resolve, front to back by depth at the pixel centre; true = per coverage sample by the depth
  // planes (needs the coverage pattern), right where planes cross inside the pixel (a fin on
  // the surface it stands on: extrapolated to the centre it lies behind that surface).
  bool per_sample_visibility = false;
  // Second merge of a surface with no sample left visible: the paper merges it like any other
  // (true); false drops it, so a hidden surface (a back face, the far side of a fin) never blends
  // its colour, normal and depth into a visible one.
  bool merge_hidden = true;
  // First merge only into a surface that covers none of the fragment's samples: fragments of one
  // tessellated surface never cover a sample twice, two layers crossing at a small angle do
  // (the paper's normal and depth tests alone merge them; its Fig. 10(b)). false: the paper.
  bool merge_disjoint_only = false;
  // Second merge into every surface whose depth interval overlaps the least visible one, as
  // Algorithm 1 writes it (true), or only into the one that overlaps it most (false).
  bool second_merge_into_all = true;
  // Second merge: the colour (or albedo and shading normal) weighted by the samples each of the two
  // surfaces shows (per-sample visibility among the surfaces and the fragment) instead of the
  // samples it covers, so a surface mostly hidden behind the one it goes into (the floor behind a
  // fin) gives its colour only where it is seen; the depth plane and facet normal stay weighted by
  // coverage (the merged surface covers both: by what is seen, its plane extrapolated over the
  // hidden one's samples came in front of later fragments: -1.1 dB on the distant scene).
  // false: everything by coverage, as the first merge and the paper's Merge().
  bool second_merge_by_visible = false;
  // First merge only between fragments whose colours (albedos, shading surfaces) differ by at most
  // this much in any channel on a square-root scale (0: no colour test, the paper). Fragments are
  // shaded at the same pixel centre, so the triangles of one surface agree closely; coplanar parts
  // of different materials (a wall's dark plinth flush with a pale slab) do not, and merged they
  // give one colour to samples where only one of them is visible.
  float merge_colour_tolerance = 0.0f;
  // Slots full (needs per_sample_visibility): instead of removing the least visible candidate
  // (merged into the most overlapping surface, or dropped), take the drop or merge that changes
  // the colours of the samples shown least. Dropping a candidate costs each sample it shows (what
  // shows there instead is not known yet: later fragments may cover it); merging two whose depth
  // intervals overlap costs 2 s_a s_b / (s_a + s_b) times their colour difference (the largest
  // channel difference on a square-root scale): the change of the shown samples' colours when
  // the merged colour is weighted by samples shown. (The pixel's mean is kept by such a merge
  // until a later fragment covers part of it; the cost counts the change as if one will:
  // discounting it by 1/2 to 1/10 measured the same on average.) Two facets of one curved surface,
  // whose normals differ beyond the first merge's cone, then share a slot rather than push out
  // the nearer surface's first small fragment. Ties: the drop (of the least visible, the farther
  // first), then the first pair in slot order. The rule replaces second_merge_into_all,
  // merge_hidden and second_merge_by_visible (a hidden candidate costs nothing to drop; merges
  // weight colours by samples shown).
  bool second_merge_least_change = false;
};

struct DcaaSurface {
  Mask coverage = 0;
  DepthPlane depth;
  Normal3 normal;
  Rgb colour;
  // Shading once per surface (dcaa --shade surface): the merged shading inputs, until `shaded`.
  Rgb albedo;
  Normal3 shading_normal;
  bool shaded = true;  // colour holds the surface's colour (always, shading fragments)
};

// How a surface gets its colour: `dcaa --shade fragment` keeps each fragment's colour (merged by
// coverage); `surface` shades each visible surface once from its merged albedo and shading normal
// at the view position its depth plane gives at the pixel centre (the caller knows the camera: it
// maps the surface to that position and shades it). A second merge (slots full) joins surfaces
// that need not be alike (a top face into a side face): shading their mean normal would light
// neither, so both are shaded first and their colours merged, as fragments' are; so is a first
// merge whose shading normals differ beyond the cone (fragments of a rounded bevel, whose
// normals extrapolated to the pixel centre spread far wider than their facets): the specular
// lobe of their mean is not the mean of their lobes.
using DcaaSurfaceShader = std::function<Rgb(const DcaaSurface&)>;

// `dcaa --rules`: "paper" = Algorithm 1 as written (DcaaSettings{}); "surface" (the default) =
// the answers dynamic coverage's surface rules give to the same questions (core/reference/dynamic_coverage.h):
// first merge only between disjoint coverage, second merge choosing by per-sample visibility,
// dropping hidden surfaces and merging into the most overlapping surface only. Throws
// std::invalid_argument for another name.
DcaaSettings dcaa_settings(const std::string& rules);

// Merge(a, b) of the paper: normals, depth planes, colours and the shading inputs (albedo,
// shading normal) averaged weighted by coverage counts (normals renormalised), coverage ORed.
// Returns the merged surface.
DcaaSurface merge_surfaces(const DcaaSurface& a, const DcaaSurface& b);
// The same with the colour, albedo and shading normal weighted seen_a : seen_b (both 0: equally),
// the geometry still by coverage.
DcaaSurface merge_surfaces(const DcaaSurface& a, const DcaaSurface& b, float seen_a, float seen_b);

// What insert() did with a fragment, for tests and statistics.
enum class DcaaEvent { Ignored, Merged, Stored, SecondMerge, Discarded };

class DcaaPixel {
 public:
  // `coverage_pattern` (kept by pointer): needed when settings.per_sample_visibility. `shade`:
  // shade surfaces once (fragments carry albedo and shading normal), else fragments' colours.
  explicit DcaaPixel(DcaaSettings settings = {}, const SamplePattern* coverage_pattern = nullptr,
                     DcaaSurfaceShader shade = {});

  // Algorithm 1. Fragments with no coverage or a non-finite depth or colour are ignored (they
  // cover no sample or cannot be weighted); a non-finite normal counts as facing the viewer.
  //  1. First merge: among surfaces with n_i . n > cos(pi/16) whose depth intervals over the
  //     pixel overlap, the best candidate (largest n_i . n, then largest overlap) takes it.
  //  2. Else, when a slot is free, it becomes a new surface.
  //  3. Else (full): coarse depth resolve of the surfaces plus the fragment (front to back by
  //     depth at the centre, each masked by the closer ones); the one with the smallest visible
  //     coverage, the front-most excluded (ties: the farther), is merged into the surface whose
  //     depth interval overlaps it most, or dropped when none overlaps. With
  //     per_sample_visibility the visible coverage is counted per sample instead (no exclusion;
  //     ties: the farther at the centre); without merge_hidden a surface with none is dropped.
  DcaaEvent insert(const CoverageFragment& fragment);

  const std::vector<DcaaSurface>& surfaces() const { return surfaces_; }

  // Final depth resolve: each coverage sample takes the surface that covers it with the
  // smallest depth at the sample (ties: the earlier surface); samples no surface covers show
  // the background (the clear colour: our scenes have no background geometry).
  // C = sum_i n_i / N c_i + (N - sum n_i) / N background.
  // Shading surfaces, each one that shows a sample and is not shaded yet is shaded once.
  Rgb resolve(const SamplePattern& coverage_pattern, Rgb background) const;
  // Shading invocations so far (second merges) plus those resolve() makes.
  int shading_invocations(const SamplePattern& coverage_pattern) const;
  // n_i of each surface after the depth resolve.
  std::vector<int> visible_counts(const SamplePattern& coverage_pattern) const;

 private:
  DcaaSurface shaded(const DcaaSurface& s);

  DcaaSettings settings_;
  const SamplePattern* pattern_;
  DcaaSurfaceShader shade_;
  std::vector<DcaaSurface> surfaces_;
  int merge_shadings_ = 0;
};

// Bytes per pixel of the paper's design: 4 surfaces of 8 B coverage + 3 B depth + 4 B normal +
// the G-buffer attributes, quoted by the paper as 112 B (against 128 B for 8x MSAA).
constexpr double kDcaaPaperBytesPerPixel = 112.0;

}  // namespace rsaa
