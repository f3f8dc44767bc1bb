// The 3x3 neighbourhood of a pixel and the bilinear estimate of docs/conventions.md section 2: what
// the post-process computes with one bilinear fetch at offset (dx, dy), |dx|, |dy| <= 1.
#pragma once

#include <cstdint>

namespace rsaa {

// Colours (0 or 1 in line cases, any value in general) of the pixel centres (i, j),
// i, j in {-1, 0, 1}, in pixel space (j = +1 is the row below).
struct Neighbourhood3x3 {
  double value[3][3] = {};  // [j + 1][i + 1]

  double at(int i, int j) const { return value[j + 1][i + 1]; }
  double& at(int i, int j) { return value[j + 1][i + 1]; }

  // For 0/1 neighbourhoods: bit (j + 1) * 3 + (i + 1) set = centre (i, j) is white.
  std::uint16_t binary_code() const;
  static Neighbourhood3x3 from_binary_code(std::uint16_t code);
};

// The estimate is bilinear on each of the four unit cells around the centre. Cell (x0, y0),
// x0, y0 in {-1, 0}, spans [x0, x0 + 1] x [y0, y0 + 1]. Templated so that Ceres can
// differentiate it (T = ceres::Jet) while the trainer keeps the cell fixed.
template <typename T>
T bilinear_in_cell(const Neighbourhood3x3& c, int x0, int y0, const T& dx, const T& dy) {
  const T fx = dx - double(x0);
  const T fy = dy - double(y0);
  const T one_fx = 1.0 - fx;
  const T one_fy = 1.0 - fy;
  return one_fx * one_fy * c.at(x0, y0) + fx * one_fy * c.at(x0 + 1, y0) +
         one_fx * fy * c.at(x0, y0 + 1) + fx * fy * c.at(x0 + 1, y0 + 1);
}

// The cell that holds offset component d (d < 0 -> -1, else 0).
inline int bilinear_cell_of(double d) { return d < 0.0 ? -1 : 0; }

inline double bilinear_estimate(const Neighbourhood3x3& c, double dx, double dy) {
  return bilinear_in_cell(c, bilinear_cell_of(dx), bilinear_cell_of(dy), dx, dy);
}

}  // namespace rsaa
