// The CPU twin of shaders/shading.glsl: the scene's shading of one surface point (fixed
// directional light in view space, Lambert + Phong, two-sided, linear light). The AGAA oracle
// shades its aggregates with it; tests compare it with the GL shading through the techniques.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/coverage_fragment.h"
#include "core/image.h"

namespace rsaa {

constexpr float kSceneSpecularExponent = 32.0f;
constexpr float kSceneSpecularScale = 0.25f;

// Unit vector along v; (0, 0, 1) for a zero or non-finite v.
inline Normal3 normalized(Normal3 v) {
  const float len = std::sqrt(dot(v, v));
  if (!(len > 0.0f) || !std::isfinite(len)) return {};
  return {v.x / len, v.y / len, v.z / len};
}

// diffuse_scale: see shaders/shading.glsl (AGAA's filtered Lambert term).
inline Rgb shade_surface(Rgb albedo, Normal3 n, Normal3 view_position, float specular_exponent, float specular_scale,
                         float diffuse_scale = 1.0f) {
  const Normal3 to_eye = normalized({-view_position.x, -view_position.y, -view_position.z});
  if (dot(n, to_eye) < 0.0f) n = {-n.x, -n.y, -n.z};
  const Normal3 light = normalized({-0.4f, 0.7f, 0.6f});
  const float diffuse = std::max(dot(n, light), 0.0f);
  // reflect(-light, n) = -light + 2 (n . light) n
  const float nl = dot(n, light);
  const Normal3 r{-light.x + 2 * nl * n.x, -light.y + 2 * nl * n.y, -light.z + 2 * nl * n.z};
  const float specular = std::pow(std::max(dot(r, to_eye), 0.0f), specular_exponent);
  const float d = 0.12f + 0.88f * diffuse_scale * diffuse;
  return {albedo.r * d + specular_scale * specular, albedo.g * d + specular_scale * specular,
          albedo.b * d + specular_scale * specular};
}

}  // namespace rsaa
