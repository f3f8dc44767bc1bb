// The papers' figures, measured on our techniques against 64x SSAA (rsaa figures; issue 14,
// item 5). Each figure is one or more FigureTable (tools/bench/chart.h), written as CSV + PNG:
//   fig9    RSAA's Figure 9: PSNR per frame over a camera animation that pulls back until the
//           geometry is sub-pixel;
//   fig1    RSAA's Figure 1: the share of pixels whose luminance error exceeds a threshold, as a
//           curve over thresholds;
//   dcaa    DCAA: surfaces per pixel (histogram) and quality against the number of surfaces
//           (2-8, the CPU reference replaying the GL fragment lists);
//   agaa    AGAA: quality against c = 1-4 aggregates, with 4, 8 and 16 visibility samples;
//   memory  bytes per pixel of each technique as allocated, beside each paper's fixed layout.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/reference/coverage_fragment.h"
#include "core/reference/dcaa.h"
#include "runtime/camera.h"
#include "runtime/technique_registry.h"
#include "tools/bench/chart.h"

namespace rsaa::bench {

struct FigureOptions {
  std::vector<std::string> scenes;  // fig1, dcaa, agaa, memory: every scene; fig9: the first
  int width = 640, height = 480;
  int frames = 32;                  // fig9's animation
  double pull_back = 16.0;          // fig9: the camera's last distance / its first
  double orbit_degrees = 30.0;      // fig9: turn over the whole animation (keeps edges moving)
};

// One figure: its tables, each with a file stem (written as <stem>.csv and <stem>.png) and how
// to draw it, and a Markdown summary.
struct Figure {
  struct Part {
    std::string stem;
    FigureTable table;
    FigureTable plot_from;  // drawn instead of table when it has columns (table: the CSV)
    ChartStyle style;
    bool bars = false;
  };
  std::string name;
  std::vector<Part> parts;
  std::string markdown;
};

const std::vector<std::string>& figure_names();  // fig9, fig1, dcaa, agaa, memory

using FigureProgress = std::function<void(const std::string& what)>;

// Needs a current GL context. Throws std::invalid_argument for an unknown name.
Figure make_figure(const std::string& name, const FigureOptions& options, const FigureProgress& progress);
// Writes every part's CSV and PNG into `dir` and the Markdown as <name>.md.
void write_figure(const Figure& figure, const std::string& dir);

// --- The pieces with numbers of their own, tested on hand-made inputs ---

// The camera moved away from its target along its view direction by `factor` (> 0), near and far
// scaled with it (the same depth precision), after turning it by `degrees` about its up axis.
Camera pulled_back_camera(const Camera& camera, double factor, double degrees);
// Frame f of n: distance factor pull_back^(f / (n - 1)) (a steady shrink on screen).
double pull_back_factor(int frame, int frames, double pull_back);

// The luminance thresholds of fig1 (display units): 0.5/255 to 128/255, doubling.
std::vector<double> figure1_thresholds();

// DCAA's surfaces per pixel: counts[k] = pixels that keep k surfaces after replaying their
// fragments with `settings` (k = 0: no fragment; at settings.max_surfaces the slots were full).
// `pattern`: the coverage samples (the surface rules count visibility per sample). visible_only:
// count only the surfaces that keep a coverage sample after the depth resolve.
std::vector<std::size_t> dcaa_surface_histogram(const std::vector<std::vector<CoverageFragment>>& pixels,
                                                const DcaaSettings& settings, const SamplePattern& pattern,
                                                bool visible_only = false);

// The techniques fig9 and fig1 compare (the first is noaa).
std::vector<TechniqueOptions> figure_techniques();

}  // namespace rsaa::bench
