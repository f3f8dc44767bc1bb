#include "core/line_case.h"

#include <cmath>

#include "core/polygon.h"
#include "core/random.h"

namespace rsaa {

Vec2 Line::direction() const { return {std::cos(angle), std::sin(angle)}; }

double Line::side(Vec2 p) const { return cross(direction(), p - point); }

bool LineCase::in_centre_cell(Vec2 p) const {
  for (int k = 0; k < line_count; ++k) {
    const double centre_side = lines[k].side({0.0, 0.0});
    const double p_side = lines[k].side(p);
    if (!(centre_side * p_side > 0.0)) return false;
  }
  return true;
}

Mask LineCase::mask(const SamplePattern& pattern) const {
  Mask m = 0;
  for (int i = 0; i < pattern.size(); ++i)
    if (in_centre_cell(pattern.positions[i])) m = with_similar(m, i);
  return m;
}

double LineCase::coverage() const {
  Polygon cell = pixel_square();
  for (int k = 0; k < line_count && !cell.empty(); ++k) {
    // side(p) = -d.y * p.x + d.x * p.y + (d.y * q.x - d.x * q.y); keep the centre's sign.
    const Vec2 d = lines[k].direction();
    const Vec2 q = lines[k].point;
    const double s = lines[k].side({0.0, 0.0}) > 0.0 ? 1.0 : -1.0;
    cell = clip_to_half_plane(cell, -s * d.y, s * d.x, s * (d.y * q.x - d.x * q.y));
  }
  return polygon_area(cell);
}

Neighbourhood3x3 LineCase::neighbourhood() const {
  Neighbourhood3x3 n;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) n.at(i, j) = in_centre_cell({double(i), double(j)}) ? 1.0 : 0.0;
  return n;
}

LineCase draw_line_case(std::uint64_t seed, std::uint64_t case_index, int line_count) {
  CaseRandom random(seed, case_index);
  LineCase c;
  c.line_count = line_count;
  for (int k = 0; k < line_count; ++k) {
    do {
      c.lines[k].point = {random.uniform() - 0.5, random.uniform() - 0.5};
      c.lines[k].angle = random.uniform() * M_PI;
    } while (c.lines[k].side({0.0, 0.0}) == 0.0);
  }
  return c;
}

}  // namespace rsaa
