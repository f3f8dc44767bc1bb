// One frame of one technique, read back into memory: what `rsaa render`, `rsaa compare`'s
// references, the tests and the bench use.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/util/image.h"
#include "runtime/camera.h"
#include "runtime/gpu_scene.h"
#include "runtime/technique_registry.h"

namespace rsaa {

// Largest image side accepted (llvmpipe's texture limit is 16384).
constexpr int kMaxImageSide = 8192;

// Throws std::invalid_argument unless 1 <= width, height <= kMaxImageSide.
void validate_size(int width, int height);

// A GL texture (RGBA16F/32F) read back as a linear Image, top row first: the one place where
// GL's bottom-up rows turn into pixel space's top-down rows.
Image read_back_image(GLuint texture, int width, int height);
// An R32UI texture read back top row first (masks).
std::vector<std::uint32_t> read_back_uints(GLuint texture, int width, int height);

struct RenderStats {
  std::string label;
  std::vector<PassTime> pass_times;
  double bytes_per_pixel = 0.0;
  std::string choices;  // Technique::choices()
};

// Needs a current GL context. Renders two frames, the first untimed (warm-up), and returns
// the second with its pass times.
Image render_frame(const GpuScene& scene, const Camera& camera, const TechniqueOptions& options,
                   int width, int height, RenderStats* stats = nullptr);

}  // namespace rsaa
