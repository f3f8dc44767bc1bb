// Where RSAA's image error lives: its squared error against the reference split by pixel class
// (how many surfaces the reference sees in the pixel, which rule made the mask's offset, missed
// edges, neighbourhoods without a pure colour of the other surface), beside the error of no AA
// and of the best single bilinear fetch (the oracle bound of any offset table). CPU only: the
// GL side (rsaa diagnose) gathers the inputs.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/util/image.h"
#include "core/rsaa/mask.h"
#include "core/rsaa/offset_table.h"
#include "runtime/scene.h"

namespace rsaa {

// Surfaces seen in one pixel: ids of distinct surfaces (0 = background), most samples first.
struct PixelSurfaces {
  static constexpr int kMaxKept = 4;
  std::array<std::uint32_t, kMaxKept> ids{};
  int count = 0;  // distinct surfaces seen, may exceed kMaxKept
  std::array<int, kMaxKept> samples{};  // samples that saw ids[k]
  int total = 0;                        // samples taken (0: unknown, no coverage bound)
};

struct DiagnosisInputs {
  Image noaa, rsaa, reference;          // linear, same size
  Image baseline;                       // optional (empty: none): a technique to compare with
  std::vector<Mask> masks;              // RSAA's mask per pixel (all-similar: left alone)
  std::vector<PixelSurfaces> surfaces;  // from a supersampled surface-id pass
  std::vector<std::uint32_t> centre_surface;  // the surface at each pixel centre (1x)
  // Per pixel: 1 if a subsample of RSAA's pattern sees another surface than the centre.
  std::vector<std::uint8_t> subsample_sees_other;
  const OffsetTable* table = nullptr;   // for the rule behind each mask's offset
};

enum class DiagnosisClass : std::uint8_t {
  OneSurfaceUntouched,  // interior pixels: shading/texture aliasing, RSAA leaves them alone
  OneSurfaceResampled,  // a false edge: RSAA moved a pixel the reference sees as one surface
  Unsampled,            // 2+ surfaces, but no subsample of the pattern sees another one
  Missed,               // 2+ surfaces, a subsample sees another, yet the mask is all-similar
  NoOtherColour,        // 2+ surfaces, no neighbour centre shows another surface of the pixel
  TwoSurfacesOneLine,   // 2 surfaces, offset fitted on one-line cases
  TwoSurfacesTwoLine,
  TwoSurfacesFallback,  // 2 surfaces, the fallback rule (or a scene-fitted offset)
  ThreeSurfaces,        // 3+ surfaces, resampled
};
constexpr int kDiagnosisClassCount = 9;
const char* to_string(DiagnosisClass c);

struct DiagnosisRow {
  std::string name;
  std::size_t pixels = 0;
  double rsaa_error = 0.0;    // summed squared error, 8-bit sRGB units, mean of RGB
  double noaa_error = 0.0;
  double oracle_error = 0.0;  // best single bilinear fetch within [-1, 1]^2
  double coverage_error = 0.0;  // exact coverage blend of the 1x colours (coverage_resolve)
  double line_fit_error = 0.0;  // the line fitted across the 3x3 masks (line_fit_resolve)
  double baseline_error = 0.0;
};

struct Diagnosis {
  int width = 0, height = 0;
  std::vector<DiagnosisRow> rows;              // one per DiagnosisClass
  std::vector<DiagnosisClass> pixel_class;     // per pixel
  std::vector<float> rsaa_error;               // per pixel squared error
  double rsaa_psnr = 0.0, noaa_psnr = 0.0, oracle_psnr = 0.0, baseline_psnr = 0.0, coverage_psnr = 0.0;
  double line_fit_psnr = 0.0;  // RSAA's image with line_fit_resolve() on its two-surface pixels
  bool has_baseline = false;
  Image oracle;                                // the oracle image
  Image coverage;                              // the exact-coverage image (coverage_resolve)
};

// The exact-coverage bound of resampling the 1x image: each surface the supersampled pass saw in
// the pixel weighted by its share of the samples, coloured as the 1x image shows it (the pixel's
// own colour for its centre's surface, else the nearest neighbour centre showing it: edge
// neighbours first; the own colour when none does). What no error in the mask or the offset
// limits: the rest is shading and texture seen once per pixel, which more subsamples cannot fix.
Rgb coverage_resolve(const DiagnosisInputs& in, int x, int y);

// What one fetch could do if the offset came from the edge line fitted across neighbouring masks
// rather than from the pixel's mask alone (a measurement, not a runtime option): one straight line
// fitted to the subsamples of the pixel and of its neighbours that lie within one pixel of its
// centre (a neighbour's subsample is on the pixel's surface when the reference shows that surface
// at the neighbour's centre and the neighbour's mask calls the subsample similar, or neither; the
// pixel's own subsamples count three times), the fit with the fewest misplaced subsamples over
// 128 directions, then the widest gap. The fetch moves from the centre along the line's normal
// until the bilinear weight on neighbour centres of another surface equals the share of the pixel
// beyond the line. Returns RSAA's pixel where no subsample is labelled another surface.
Rgb line_fit_resolve(const DiagnosisInputs& in, int x, int y);

// A surface id per triangle (1-based): triangles of one draw range that share an edge (welded by
// position) and whose face normals differ by less than 30 degrees belong to one surface, so a
// tessellated sphere is one surface and a box has six. Degenerate triangles are surfaces alone.
std::vector<std::uint32_t> smooth_surface_ids(const Scene& scene);

// Throws std::invalid_argument when sizes disagree or the table is missing.
Diagnosis diagnose(const DiagnosisInputs& in);

// Markdown table of the rows (pixels, share of RSAA's error, PSNR-equivalent figures).
std::string diagnosis_markdown(const Diagnosis& d, const std::string& title,
                               const std::string& baseline_name = "baseline");

// The error map: brightness = sqrt of RSAA's error, hue = the pixel's class (legend in the
// Markdown); 8-bit sRGB RGB, top row first.
std::vector<std::uint8_t> diagnosis_picture(const Diagnosis& d);
// The class colours, in DiagnosisClass order (sRGB 8-bit).
const std::array<std::array<std::uint8_t, 3>, kDiagnosisClassCount>& diagnosis_class_colours();

}  // namespace rsaa
