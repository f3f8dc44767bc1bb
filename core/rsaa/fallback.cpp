#include "core/rsaa/fallback.h"

#include <algorithm>
#include <cmath>

namespace rsaa {

double fallback_length(Vec2 u, double s) {
  // Solve (1 - a t)(1 - b t) = s for the smaller root; written to avoid dividing by a*b = 0.
  const double a = std::abs(u.x);
  const double b = std::abs(u.y);
  const double keep = 1.0 - std::clamp(s, 0.0, 1.0);
  const double discriminant = (a - b) * (a - b) + 4.0 * a * b * (1.0 - keep);
  return 2.0 * keep / ((a + b) + std::sqrt(discriminant));
}

Vec2 fallback_offset(const SamplePattern& pattern, Mask mask) {
  int farthest = -1;
  double farthest_distance = 0.0;
  for (int i = 0; i < pattern.size(); ++i) {
    if (is_similar(mask, i)) continue;
    const double d = length(pattern.positions[i]);
    if (d > farthest_distance) {
      farthest = i;
      farthest_distance = d;
    }
  }
  if (farthest < 0) return {0.0, 0.0};
  const Vec2 u = (1.0 / farthest_distance) * pattern.positions[farthest];
  const double s = double(similar_count(mask & pattern.all_similar())) / pattern.size();
  return fallback_length(u, s) * u;
}

}  // namespace rsaa
