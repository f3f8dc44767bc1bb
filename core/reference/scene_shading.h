// The CPU twin of shaders/shading.glsl: the scene's shading of one surface point (fixed
// directional light in view space plus optional point lights, Lambert + Phong, linear light; the
// normal given on the side the eye sees). The AGAA oracle
// shades its aggregates with it; tests compare it with the GL shading through the techniques.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/reference/coverage_fragment.h"
#include "core/util/image.h"

namespace rsaa {

constexpr float kSceneSpecularExponent = 32.0f;
constexpr int kMaxScenePointLights = 64;  // SCENE_MAX_POINT_LIGHTS

// A point light in view space; its light falls off as 1 / (1 + d^2 / radius^2).
struct PointLight {
  Normal3 position{0.0f, 0.0f, 0.0f};
  float radius = 1.0f;
  Rgb colour;
};
constexpr float kSceneSpecularScale = 0.25f;

// Unit vector along v; (0, 0, 1) for a zero or non-finite v.
inline Normal3 normalized(Normal3 v) {
  const float len = std::sqrt(dot(v, v));
  if (!(len > 0.0f) || !std::isfinite(len)) return {};
  return {v.x / len, v.y / len, v.z / len};
}

// diffuse_scale: see shaders/shading.glsl (AGAA's filtered Lambert term), applied to every light.
inline Rgb shade_surface(Rgb albedo, Normal3 n, Normal3 view_position, float specular_exponent, float specular_scale,
                         float diffuse_scale = 1.0f, const std::vector<PointLight>& point_lights = {}) {
  // n is on the side the eye sees already (shaders/scene_normal_side.glsl, or the mean of such
  // normals): turned here by the view, it flipped inside surfaces near silhouettes.
  const Normal3 to_eye = normalized({-view_position.x, -view_position.y, -view_position.z});
  // reflect(-l, n) . to_eye, with reflect(-l, n) = -l + 2 (n . l) n
  const auto specular_of = [&](Normal3 l) {
    const float nl = dot(n, l);
    const Normal3 r{-l.x + 2 * nl * n.x, -l.y + 2 * nl * n.y, -l.z + 2 * nl * n.z};
    return std::pow(std::max(dot(r, to_eye), 0.0f), specular_exponent);
  };
  const Normal3 light = normalized({-0.4f, 0.7f, 0.6f});
  const float diffuse = std::max(dot(n, light), 0.0f);
  const float specular = specular_of(light);
  const float d = 0.12f + 0.88f * diffuse_scale * diffuse;
  Rgb c{albedo.r * d + specular_scale * specular, albedo.g * d + specular_scale * specular,
        albedo.b * d + specular_scale * specular};
  const std::size_t count = std::min<std::size_t>(point_lights.size(), kMaxScenePointLights);
  for (std::size_t i = 0; i < count; ++i) {
    const PointLight& p = point_lights[i];
    const Normal3 to_light{p.position.x - view_position.x, p.position.y - view_position.y,
                           p.position.z - view_position.z};
    const float falloff = 1.0f / (1.0f + dot(to_light, to_light) / (p.radius * p.radius));
    const Normal3 l = normalized(to_light);
    const float dl = diffuse_scale * std::max(dot(n, l), 0.0f);
    const float sl = specular_of(l);
    c.r += p.colour.r * falloff * (albedo.r * dl + specular_scale * sl);
    c.g += p.colour.g * falloff * (albedo.g * dl + specular_scale * sl);
    c.b += p.colour.b * falloff * (albedo.b * dl + specular_scale * sl);
  }
  return c;
}

}  // namespace rsaa
