// Line cases (docs/conventions.md section 2): one or two random lines cross the pixel; the cell of
// their arrangement that holds the pixel centre is white, the rest black.
#pragma once

#include <array>
#include <cstdint>

#include "core/rsaa/bilinear.h"
#include "core/rsaa/mask.h"
#include "core/rsaa/sample_pattern.h"
#include "core/util/vec2.h"

namespace rsaa {

struct Line {
  Vec2 point;          // a point of the line, pixel space
  double angle = 0.0;  // direction (cos angle, sin angle), in [0, pi)

  Vec2 direction() const;
  // Signed distance-like side value: > 0 on one side, < 0 on the other, 0 on the line.
  double side(Vec2 p) const;
};

struct LineCase {
  int line_count = 1;  // 1 or 2
  std::array<Line, 2> lines{};

  // True when p is strictly inside the centre cell (a point on a line belongs to no cell).
  bool in_centre_cell(Vec2 p) const;
  // Bit i set when subsample i lies in the centre cell.
  Mask mask(const SamplePattern& pattern) const;
  // Exact area of (centre cell intersected with the pixel square), by polygon clipping.
  double coverage() const;
  // 1 for each of the 3x3 pixel centres inside the centre cell, else 0.
  Neighbourhood3x3 neighbourhood() const;
};

// The training/evaluation distribution: lines through a uniform point of the pixel square with
// a uniform angle in [0, pi); a draw whose line passes through the centre is redrawn.
LineCase draw_line_case(std::uint64_t seed, std::uint64_t case_index, int line_count);

// Case sets alternate: even indices are one-line cases, odd indices two-line cases.
constexpr int line_count_of_case(std::uint64_t case_index) { return case_index % 2 == 0 ? 1 : 2; }

}  // namespace rsaa
