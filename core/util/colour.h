// sRGB transfer functions (IEC 61966-2-1) and Rec. 709 luminance. Shading and filtering work in
// linear light; 8-bit image files hold sRGB-encoded values (docs/conventions.md section 5).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rsaa {

inline float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Clamps to [0, 1] first; a non-finite value encodes as 0 so that no NaN reaches a file.
inline float linear_to_srgb(float v) {
  if (!std::isfinite(v)) return 0.0f;
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

inline std::uint8_t linear_to_srgb8(float v) {
  return static_cast<std::uint8_t>(std::lround(linear_to_srgb(v) * 255.0f));
}

// Rec. 709 luminance of display (encoded) values in [0, 1].
inline double rec709_luma(double r, double g, double b) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

}  // namespace rsaa
