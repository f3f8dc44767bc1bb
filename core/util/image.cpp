#include "core/util/image.h"

#include <algorithm>
#include <cmath>

namespace rsaa {

Rgb bilinear_fetch(const Image& image, double x, double y) {
  const double fx0 = std::floor(x), fy0 = std::floor(y);
  const double tx = x - fx0, ty = y - fy0;
  const auto clamp_x = [&](double v) { return int(std::clamp(v, 0.0, double(image.width - 1))); };
  const auto clamp_y = [&](double v) { return int(std::clamp(v, 0.0, double(image.height - 1))); };
  const int x0 = clamp_x(fx0), x1 = clamp_x(fx0 + 1), y0 = clamp_y(fy0), y1 = clamp_y(fy0 + 1);
  const Rgb& a = image.at(x0, y0);
  const Rgb& b = image.at(x1, y0);
  const Rgb& c = image.at(x0, y1);
  const Rgb& d = image.at(x1, y1);
  const auto mix = [&](float va, float vb, float vc, float vd) {
    return float((1 - tx) * (1 - ty) * va + tx * (1 - ty) * vb + (1 - tx) * ty * vc + tx * ty * vd);
  };
  return {mix(a.r, b.r, c.r, d.r), mix(a.g, b.g, c.g, d.g), mix(a.b, b.b, c.b, d.b)};
}

}  // namespace rsaa
