// Image metrics of docs/conventions.md section 5, on 8-bit sRGB display values.
#pragma once

#include "core/image_io.h"

namespace rsaa {

struct ImageComparison {
  double psnr_db = 0.0;          // RGB, MSE over the three channels, peak 255; +inf if equal
  double ssim = 0.0;             // OpenCV quality module, mean of the three channels
  double luma_error_share = 0.0;  // percentage of pixels with |Y(a) - Y(b)| > threshold
  double mse = 0.0;
};

// Throws std::invalid_argument when the sizes differ.
ImageComparison compare_images(const DisplayImage& a, const DisplayImage& reference,
                               double luma_threshold = 1.0 / 64.0);

}  // namespace rsaa
