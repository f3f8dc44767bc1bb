#include "core/rsaa/line_case.h"

#include <cmath>

#include "core/rsaa/polygon.h"
#include "core/util/random.h"

namespace rsaa {

Vec2 Line::direction() const { return {std::cos(angle), std::sin(angle)}; }

double Line::side(Vec2 p) const { return cross(direction(), p - point); }

namespace {

// The centre cell with each line's direction and centre side computed once: mask() and
// neighbourhood() test up to 25 points, and Line::side() costs a cos and a sin per call (the
// trainer's case generation was mostly that). Same expressions as Line::side, so same bits.
class CentreCell {
 public:
  explicit CentreCell(const LineCase& c) : count_(c.line_count) {
    for (int k = 0; k < count_; ++k) {
      point_[k] = c.lines[k].point;
      direction_[k] = c.lines[k].direction();
      centre_side_[k] = cross(direction_[k], Vec2{0.0, 0.0} - point_[k]);
    }
  }
  bool contains(Vec2 p) const {
    for (int k = 0; k < count_; ++k)
      if (!(centre_side_[k] * cross(direction_[k], p - point_[k]) > 0.0)) return false;
    return true;
  }

 private:
  int count_;
  Vec2 point_[2], direction_[2];
  double centre_side_[2] = {0.0, 0.0};
};

}  // namespace

bool LineCase::in_centre_cell(Vec2 p) const { return CentreCell(*this).contains(p); }

Mask LineCase::mask(const SamplePattern& pattern) const {
  const CentreCell cell(*this);
  Mask m = 0;
  for (int i = 0; i < pattern.size(); ++i)
    if (cell.contains(pattern.positions[i])) m = with_similar(m, i);
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
  const CentreCell cell(*this);
  Neighbourhood3x3 n;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) n.at(i, j) = cell.contains({double(i), double(j)}) ? 1.0 : 0.0;
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
