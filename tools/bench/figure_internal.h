// Shared by the figure files (paper_figures.cpp, coverage_figures.cpp): one scene at its own
// camera, its 64x SSAA reference, and techniques rendered against it.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "runtime/gl_objects.h"
#include "runtime/gpu_scene.h"
#include "runtime/scene.h"
#include "tools/bench/paper_figures.h"

namespace rsaa::bench {

struct SceneFrame {
  SceneFrame(Scene scene, int width, int height);

  struct Rendered {
    DisplayImage image;
    double bytes_per_pixel = 0.0;
  };
  Rendered render(const TechniqueOptions& options) const;
  Rendered render(Technique& technique) const;  // keeps the technique (its buffers) for the caller

  Scene scene;
  GpuScene gpu;
  View view;
  gl::Texture output;
  DisplayImage reference;  // 64x SSAA
};

// PSNR of `a` against `reference`, 99 dB for identical images (finite, for tables and plots).
double capped_psnr(const DisplayImage& a, const DisplayImage& reference);
// `v` with `decimals` decimals.
std::string fixed(double v, int decimals = 2);
// A Markdown table's header and separator rows: `first`, then `columns`.
void markdown_table_head(std::ostream& md, const std::string& first, const std::vector<std::string>& columns);

// Loads `spec` and renders its reference. Needs a current GL context.
std::unique_ptr<SceneFrame> load_scene_frame(const std::string& spec, const FigureOptions& options, const FigureProgress& progress);

Figure dcaa_figure(const FigureOptions& options, const FigureProgress& progress);
Figure agaa_figure(const FigureOptions& options, const FigureProgress& progress);

}  // namespace rsaa::bench
