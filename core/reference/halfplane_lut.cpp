#include "core/reference/halfplane_lut.h"

#include <cmath>
#include <stdexcept>

namespace rsaa {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// The Line of the trainer whose side() is n.p - d for the half-plane's normal n.
Line line_of(const HalfPlane& h) {
  const Vec2 n{std::cos(h.theta), std::sin(h.theta)};
  // side(p) = cross(direction, p - point); direction (sin, -cos) makes it n.(p - point).
  return Line{h.distance * n, std::atan2(-n.x, n.y)};
}

}  // namespace

HalfPlane inner_half_plane(Vec2 a, Vec2 b, double orientation) {
  const Vec2 e = b - a;
  const double len = length(e);
  const Vec2 n = (orientation / len) * Vec2{-e.y, e.x};  // cross(e, c - a) has the sign of orientation
  return {std::atan2(n.y, n.x), dot(n, a)};
}

Mask half_plane_mask_direct(const SamplePattern& pattern, const HalfPlane& h) {
  const Line line = line_of(h);
  Mask mask = 0;
  for (int i = 0; i < pattern.size(); ++i)
    if (line.side(pattern.positions[i]) > 0.0) mask = with_similar(mask, i);
  return mask;
}

double HalfPlaneLut::max_distance() { return std::sqrt(0.5); }

HalfPlaneLut::HalfPlaneLut(SamplePattern pattern, int angle_bins, int distance_bins)
    : pattern_(std::move(pattern)), angle_bins_(angle_bins), distance_bins_(distance_bins) {
  if (angle_bins < 4 || angle_bins % 2 || distance_bins < 2 || distance_bins % 2)
    throw std::invalid_argument("HalfPlaneLut: bins must be even, angles >= 4 and distances >= 2");
  entries_.resize(std::size_t(angle_bins) * distance_bins);
  const double r = max_distance();
  for (int a = 0; a < angle_bins; ++a)
    for (int d = 0; d < distance_bins; ++d)
      entries_[std::size_t(a) * distance_bins + d] = half_plane_mask_direct(
          pattern_, {a * kTwoPi / angle_bins, -r + (d + 0.5) * 2.0 * r / distance_bins});
}

Mask HalfPlaneLut::lookup(const HalfPlane& h) const {
  const double r = max_distance();
  if (!std::isfinite(h.theta) || !std::isfinite(h.distance)) return 0;
  if (h.distance <= -r) return pattern_.all_similar();
  if (h.distance >= r) return 0;
  // Nearest angle bin (bin a is centred on a * 2 pi / bins, so theta and theta + pi land on
  // bins half a turn apart: opposite edges of two triangles get complementary masks).
  double turns = h.theta / kTwoPi;
  turns -= std::floor(turns);
  const int a = int(std::lround(turns * angle_bins_)) % angle_bins_;
  const int d = std::min(distance_bins_ - 1, int((h.distance + r) / (2.0 * r) * distance_bins_));
  return entries_[std::size_t(a) * distance_bins_ + d];
}

Mask HalfPlaneLut::triangle_coverage(Vec2 a, Vec2 b, Vec2 c) const {
  if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return 0;
  const double area2 = cross(b - a, c - a);
  if (!(area2 != 0.0)) return 0;
  const double o = area2 > 0.0 ? 1.0 : -1.0;
  return lookup(inner_half_plane(a, b, o)) & lookup(inner_half_plane(b, c, o)) &
         lookup(inner_half_plane(c, a, o));
}

double HalfPlaneLut::max_error() const {
  // Rounding theta to the nearest bin turns n by at most pi / bins, which changes n.p by at most
  // that angle times |p| <= R; the distance bin centre is at most R / bins from d.
  const double r = max_distance();
  return kTwoPi / angle_bins_ / 2.0 * r + r / distance_bins_;
}

SamplePattern dcaa_coverage_pattern() {
  std::vector<Vec2> positions;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int x = 8 * i + j, y = 8 * j + (3 * i) % 8;  // all x distinct, all y distinct
      positions.push_back({(x + 0.5) / 64.0 - 0.5, (y + 0.5) / 64.0 - 0.5});
    }
  return pattern_from_positions("dcaa64", positions);
}

}  // namespace rsaa
