#include "core/rsaa/polygon.h"

#include <cmath>

namespace rsaa {

Polygon pixel_square() { return {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}; }

Polygon clip_to_half_plane(const Polygon& polygon, double a, double b, double c) {
  Polygon out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = polygon[i];
    const Vec2 q = polygon[(i + 1) % n];
    const double fp = a * p.x + b * p.y + c;
    const double fq = a * q.x + b * q.y + c;
    if (fp >= 0) out.push_back(p);
    // The edge crosses the line strictly: add the crossing point. fp != fq here.
    if ((fp > 0 && fq < 0) || (fp < 0 && fq > 0)) {
      const double t = fp / (fp - fq);
      out.push_back(p + t * (q - p));
    }
  }
  return out;
}

double polygon_area(const Polygon& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) twice += cross(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * std::abs(twice);
}

}  // namespace rsaa
