// Scene-specific tables (model only what a scene requires): harvest real cases from a scene's
// renders over several camera views (per pixel: its RSAA 8x mask, the no-AA colours of its 3x3
// neighbourhood and the 64x SSAA colour), fit one offset per mask with the trainer's Ceres fit,
// keep the generic table for masks the scene reaches too rarely, and measure both tables on
// held-out views with the CPU post-process.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/rsaa/offset_table.h"

namespace rsaa::bench {

struct SceneTableOptions {
  std::string scene = "builtin:default";
  int width = 320, height = 240;
  int training_views = 6;   // camera orbit positions used for fitting
  int held_out_views = 3;   // positions between them, used only for measuring
  double degrees_between_views = 6.0;
  int min_pixels = 20;      // masks seen at fewer pixels keep the generic offset
  // How the generic table was named on the command line (empty: the built-in d3d8x table), for
  // the command the table records.
  std::string generic_file;
};

struct SceneTableReport {
  OffsetTable table;                                   // pattern d3d8x
  std::vector<std::pair<Mask, std::uint64_t>> masks;  // pixels per mask over the training views
  std::uint64_t edge_pixels = 0;
  int masks_fitted = 0;
  double held_out_psnr_noaa = 0, held_out_psnr_generic = 0, held_out_psnr_scene = 0;  // mean dB
};

// Needs a current GL context. `progress` gets a line per step (may be null).
SceneTableReport train_scene_table(const SceneTableOptions& options, const OffsetTable& generic,
                                   const std::function<void(const std::string&)>& progress);

}  // namespace rsaa::bench
