#include "image/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/quality.hpp>

#include "core/util/colour.h"

namespace rsaa {
namespace {

// SSIM, the mean of its map, computed over bands of rows: the whole image at once took about
// 225 bytes a pixel (OpenCV's float images of means and variances; an 8192 x 8192 PNG of
// 196 KB took 13 GB). Each band is computed with the rows either side that its 11 x 11 Gaussian
// window reads, so that its own rows' map is the whole image's; the means agree to rounding.
double mean_ssim(const cv::Mat& a, const cv::Mat& b) {
  constexpr int kWindowRadius = 5;           // OpenCV's SSIM window: 11 x 11, sigma 1.5
  constexpr std::int64_t kBandPixels = 1 << 20;  // about 240 MB at the peak
  const int band = int(std::max<std::int64_t>(4 * kWindowRadius, kBandPixels / std::max(1, a.cols)));
  if (a.rows <= band) {
    const cv::Scalar ssim = cv::quality::QualitySSIM::compute(a, b, cv::noArray());
    return (ssim[0] + ssim[1] + ssim[2]) / 3.0;
  }
  cv::Scalar sum = cv::Scalar::all(0.0);
  for (int first = 0; first < a.rows; first += band) {
    const int end = std::min(first + band, a.rows);
    const int top = std::max(0, first - kWindowRadius), bottom = std::min(a.rows, end + kWindowRadius);
    cv::Mat map;
    cv::quality::QualitySSIM::compute(a.rowRange(top, bottom), b.rowRange(top, bottom), map);
    sum += cv::sum(map.rowRange(first - top, end - top));
  }
  const double pixels = double(a.rows) * double(a.cols);
  return (sum[0] + sum[1] + sum[2]) / (3.0 * pixels);
}

}  // namespace

ImageComparison compare_images(const DisplayImage& a, const DisplayImage& b, double luma_threshold) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " against " + std::to_string(b.width) +
                                "x" + std::to_string(b.height));
  ImageComparison c;
  c.non_finite_a = a.non_finite_pixels;
  c.non_finite_reference = b.non_finite_pixels;
  double squared = 0.0;
  std::size_t over = 0;
  const std::size_t n = std::size_t(a.width) * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double d = double(a.rgb[3 * i + k]) - double(b.rgb[3 * i + k]);
      squared += d * d;
    }
    const double ya = rec709_luma(a.rgb[3 * i] / 255.0, a.rgb[3 * i + 1] / 255.0, a.rgb[3 * i + 2] / 255.0);
    const double yb = rec709_luma(b.rgb[3 * i] / 255.0, b.rgb[3 * i + 1] / 255.0, b.rgb[3 * i + 2] / 255.0);
    over += std::abs(ya - yb) > luma_threshold;
  }
  c.mse = squared / (3.0 * double(n));
  c.psnr_db = c.mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / c.mse)
                        : std::numeric_limits<double>::infinity();
  c.luma_error_share = 100.0 * double(over) / double(n);
  const cv::Mat ma(a.height, a.width, CV_8UC3, const_cast<std::uint8_t*>(a.rgb.data()));
  const cv::Mat mb(b.height, b.width, CV_8UC3, const_cast<std::uint8_t*>(b.rgb.data()));
  c.ssim = mean_ssim(ma, mb);
  if (!c.defined()) c.psnr_db = c.ssim = c.mse = c.luma_error_share = std::numeric_limits<double>::quiet_NaN();
  return c;
}

std::vector<double> luma_error_shares(const DisplayImage& a, const DisplayImage& b,
                                      const std::vector<double>& thresholds) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("luma_error_shares: images differ in size");
  for (double t : thresholds)
    if (!std::isfinite(t)) throw std::invalid_argument("luma_error_shares: thresholds must be finite");
  std::vector<std::size_t> over(thresholds.size(), 0);
  const std::size_t n = std::size_t(a.width) * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    const double ya = rec709_luma(a.rgb[3 * i] / 255.0, a.rgb[3 * i + 1] / 255.0, a.rgb[3 * i + 2] / 255.0);
    const double yb = rec709_luma(b.rgb[3 * i] / 255.0, b.rgb[3 * i + 1] / 255.0, b.rgb[3 * i + 2] / 255.0);
    const double error = std::abs(ya - yb);
    for (std::size_t k = 0; k < thresholds.size(); ++k) over[k] += error > thresholds[k];
  }
  std::vector<double> shares;
  for (std::size_t count : over) shares.push_back(n ? 100.0 * double(count) / double(n) : 0.0);
  return shares;
}

}  // namespace rsaa
