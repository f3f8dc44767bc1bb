// rsaa compare: PSNR, SSIM and the luminance-error share of an image against a reference.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <memory>

#include <nlohmann/json.hpp>

#include "image/image_metrics.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"

namespace rsaa::cli {
namespace {

struct CompareArgs {
  std::string image, reference;
  double luma_threshold = 1.0 / 64.0;
  bool json = false;
};

int run_compare(const CompareArgs& a) {
  if (!(a.luma_threshold > 0.0 && a.luma_threshold < 1.0))
    throw std::invalid_argument("--luma-threshold must be within (0, 1)");
  const DisplayImage image = read_display_image(a.image);
  const DisplayImage reference = read_display_image(a.reference);
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument(a.image + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                ", " + a.reference + " " + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ": images of one size are compared");
  const ImageComparison c = compare_images(image, reference, a.luma_threshold);
  // NaN or infinite pixels make every figure undefined: refused, never reported as a number.
  if (!c.defined()) {
    std::string which;
    for (const auto& [path, count] : {std::pair{a.image, c.non_finite_a}, std::pair{a.reference, c.non_finite_reference}})
      if (count)
        which += (which.empty() ? "" : "; ") + path + ": " + std::to_string(count) + " of " +
                 std::to_string(std::uint64_t(image.width) * image.height) + " pixels are NaN or infinite";
    throw std::runtime_error(which + " (PSNR and SSIM are undefined)");
  }
  if (a.json) {
    nlohmann::json out = {{"image", a.image},
                          {"reference", a.reference},
                          // Identical images have no finite PSNR: null (JSON has no infinity), and
                          // "identical" says why.
                          {"psnr_db", std::isfinite(c.psnr_db) ? nlohmann::json(c.psnr_db) : nlohmann::json()},
                          {"identical", !(c.mse > 0.0)},
                          {"ssim", c.ssim},
                          {"luma_error_share_percent", c.luma_error_share},
                          {"luma_threshold", a.luma_threshold}};
    // File names are any bytes: invalid UTF-8 is printed as U+FFFD rather than failing.
    std::printf("%s\n", out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
  } else {
    char psnr[32] = "identical images";
    if (std::isfinite(c.psnr_db)) std::snprintf(psnr, sizeof psnr, "%.2f dB", c.psnr_db);
    std::printf("%s against %s\n  PSNR %s   SSIM %.4f   luminance error > %.4f: %.2f%% of pixels\n", a.image.c_str(),
                a.reference.c_str(), psnr, c.ssim, a.luma_threshold, c.luma_error_share);
  }
  return 0;
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "PSNR (RGB of 8-bit sRGB, peak 255), SSIM and luminance-error share of A against B");
  cmd->add_option("A", args->image, "Image to measure")->required();
  cmd->add_option("B", args->reference, "Reference image (e.g. ssaa --samples 64)")->required();
  cmd->add_option("--luma-threshold", args->luma_threshold,
                  "|Y(A) - Y(B)| above this counts as an error (display values in [0, 1])")
      ->capture_default_str()
      ->check(finite_range(0.0, 1.0));
  cmd->add_flag("--json", args->json, "Print JSON");
  return [args] { return run_compare(*args); };
}

}  // namespace rsaa::cli
