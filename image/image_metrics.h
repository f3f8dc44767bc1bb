// Image metrics of docs/conventions.md section 5, on 8-bit sRGB display values.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image_io.h"

namespace rsaa {

struct ImageComparison {
  // All four are NaN when either image has non-finite pixels: such images are neither equal
  // nor different by a number (their pixels are encoded as 0 only to be displayable).
  double psnr_db = 0.0;          // RGB, MSE over the three channels, peak 255; +inf if equal
  double ssim = 0.0;             // OpenCV quality module, mean of the three channels
  double luma_error_share = 0.0;  // percentage of pixels with |Y(a) - Y(b)| > threshold
  double mse = 0.0;
  std::uint64_t non_finite_a = 0, non_finite_reference = 0;  // pixels with NaN/Inf channels
  bool defined() const { return non_finite_a == 0 && non_finite_reference == 0; }
};

// Throws std::invalid_argument when the sizes differ.
ImageComparison compare_images(const DisplayImage& a, const DisplayImage& reference,
                               double luma_threshold = 1.0 / 64.0);

// The luminance-error share of compare_images() at each of `thresholds` (display units, [0, 1]),
// in one pass: RSAA's Figure 1 as a curve. Percentages, in the order of `thresholds`. Throws
// std::invalid_argument when the sizes differ or a threshold is not finite.
std::vector<double> luma_error_shares(const DisplayImage& a, const DisplayImage& reference,
                                      const std::vector<double>& thresholds);

}  // namespace rsaa
