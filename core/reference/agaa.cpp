#include "core/reference/agaa.h"

#include <cmath>

#include "core/reference/scene_shading.h"

namespace rsaa {

float agaa_distance(const AgaaSample& a, const AgaaSample& b, float k) {
  const Normal3 d{(a.position.x - b.position.x) / k, (a.position.y - b.position.y) / k,
                  (a.position.z - b.position.z) / k};
  const float bend = 1.0f - dot(a.normal, b.normal);
  return dot(d, d) + bend * bend;
}

AgaaClusters define_aggregates(const std::vector<AgaaSample>& samples, const AgaaSettings& settings) {
  AgaaClusters out;
  out.aggregate.assign(samples.size(), -1);
  const int n = int(samples.size());
  AgaaSample average;
  average.position = average.normal = {0, 0, 0};
  int valid = 0;
  for (const AgaaSample& s : samples) {
    if (!s.valid) continue;
    ++valid;
    average.position = {average.position.x + s.position.x, average.position.y + s.position.y,
                        average.position.z + s.position.z};
    average.normal = {average.normal.x + s.normal.x, average.normal.y + s.normal.y, average.normal.z + s.normal.z};
  }
  if (valid == 0) return out;
  average.position = {average.position.x / valid, average.position.y / valid, average.position.z / valid};
  const float len = std::sqrt(dot(average.normal, average.normal));
  if (len > 1e-6f) average.normal = {average.normal.x / len, average.normal.y / len, average.normal.z / len};

  const float k = settings.k_per_depth > 0.0f ? settings.k_per_depth * std::abs(average.position.z) : settings.k;
  std::vector<int> seeds;
  const auto farthest = [&](auto&& score) {
    int best = -1;
    float best_score = 0.0f;
    for (int i = 0; i < n; ++i)
      if (samples[i].valid && (best < 0 || score(i) > best_score)) best = i, best_score = score(i);
    return best;
  };
  seeds.push_back(farthest([&](int i) { return agaa_distance(samples[i], average, k); }));
  // Only samples farther than t from every seed may become one (the paper's minimum separation;
  // without it a sample beside an earlier seed could win the sum of squares).
  const auto separated = [&](int i) {
    for (int s : seeds)
      if (!(agaa_distance(samples[i], samples[s], k) > settings.min_separation)) return false;
    return true;
  };
  while (int(seeds.size()) < settings.aggregates) {
    const int candidate = farthest([&](int i) {
      if (!separated(i)) return -1.0f;
      if (seeds.size() == 1) return agaa_distance(samples[i], samples[seeds[0]], k);
      float sum = 0.0f;
      for (int s : seeds) {
        const float d = agaa_distance(samples[i], samples[s], k);
        sum += d * d;
      }
      return sum;
    });
    if (!separated(candidate)) break;
    seeds.push_back(candidate);
  }
  out.count = int(seeds.size());
  for (int i = 0; i < n; ++i) {
    if (!samples[i].valid) continue;
    int best = 0;
    float best_d = agaa_distance(samples[i], samples[seeds[0]], k);
    for (int a = 1; a < out.count; ++a) {
      const float d = agaa_distance(samples[i], samples[seeds[a]], k);
      if (d < best_d) best = a, best_d = d;
    }
    out.aggregate[i] = best;
  }
  return out;
}

float toksvig_exponent(float normal_length, float exponent) {
  const float l = std::clamp(normal_length, 0.0f, 1.0f);
  const float denominator = l + exponent * (1.0f - l);
  // At least 1e-3: pow(0, 0) is undefined in GLSL.
  return std::max(denominator > 0.0f ? l / denominator * exponent : 0.0f, 1e-3f);
}

Rgb agaa_resolve(const std::vector<AgaaAggregateSums>& aggregates, Normal3 pixel_ray, Rgb background,
                 bool filtered_diffuse) {
  Rgb c;
  float covered = 0.0f;
  for (const AgaaAggregateSums& a : aggregates) {
    if (!(a.weight > 1e-6f) || !std::isfinite(a.weight)) continue;
    const Rgb albedo{a.albedo.r / a.weight, a.albedo.g / a.weight, a.albedo.b / a.weight};
    const Normal3 mean{a.normal.x / a.weight, a.normal.y / a.weight, a.normal.z / a.weight};
    const float len = std::sqrt(dot(mean, mean));
    const float z = a.view_z / a.weight;
    const float scale = pixel_ray.z != 0.0f ? z / pixel_ray.z : 1.0f;
    const Normal3 position{pixel_ray.x * scale, pixel_ray.y * scale, z};
    const Normal3 n = len > 1e-6f ? Normal3{mean.x / len, mean.y / len, mean.z / len}
                                  : normalized({-position.x, -position.y, -position.z});
    const float s = toksvig_exponent(len, kSceneSpecularExponent);
    const float diffuse_scale = filtered_diffuse && len > 1e-6f ? std::min(len, 1.0f) : 1.0f;
    const Rgb shaded = shade_surface(albedo, n, position, s,
                                     kSceneSpecularScale * (1.0f + s) / (1.0f + kSceneSpecularExponent), diffuse_scale);
    c = {c.r + a.weight * shaded.r, c.g + a.weight * shaded.g, c.b + a.weight * shaded.b};
    covered += a.weight;
  }
  const float rest = std::clamp(1.0f - covered, 0.0f, 1.0f);
  return {c.r + rest * background.r, c.g + rest * background.g, c.b + rest * background.b};
}

}  // namespace rsaa
