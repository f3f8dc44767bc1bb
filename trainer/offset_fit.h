// Fitting one resampling offset to the cases of one mask: minimise the sum of weighted squared
// case errors (bilinear estimate - exact coverage) over (dx, dy), |dx|, |dy| <= 1, with Ceres.
#pragma once

#include <vector>

#include "core/rsaa/bilinear.h"
#include "core/util/vec2.h"

namespace rsaa {

// A case as the fit sees it. `weight` multiplies its squared error. Cases with the same
// neighbourhood may be merged into one with the summed weight and the weighted mean coverage:
// the cost then changes by a constant only, so the minimiser is exactly the same.
struct FitCase {
  Neighbourhood3x3 neighbourhood;
  double coverage = 0.0;
  double weight = 1.0;
};

// The residual of one case, Ceres-style: sqrt(weight) * (estimate(dx, dy) - coverage).
// The estimate is bilinear on each unit cell around the centre, so the functor is given the cell
// it works in; the fitter solves each cell separately with bounds.
struct EstimateMinusCoverage {
  EstimateMinusCoverage(const FitCase& c, int cell_x, int cell_y);

  template <typename T>
  bool operator()(const T* offset, T* residual) const {
    residual[0] =
        scale * (bilinear_in_cell(neighbourhood, cell_x, cell_y, offset[0], offset[1]) - coverage);
    return true;
  }

  Neighbourhood3x3 neighbourhood;
  double coverage;
  double scale;
  int cell_x, cell_y;
};

struct OffsetFit {
  Vec2 offset;
  double cost = 0.0;  // sum of weight * error^2 at `offset`
};

// Sum of weight * (estimate - coverage)^2 at `offset`.
double fit_cost(const std::vector<FitCase>& cases, Vec2 offset);

// Ceres, once per cell (x0, y0) in {-1, 0}^2 with bounds [x0, x0 + 1] x [y0, y0 + 1], each
// started from the best point of a coarse grid on that cell; the best of the four wins (first
// cell in the order (-1,-1), (0,-1), (-1,0), (0,0) on a tie).
OffsetFit fit_offset(const std::vector<FitCase>& cases);

// Brute force for tests: a `steps` x `steps` grid over [-1, 1]^2, then `refinements` rounds of a
// finer grid around the best point (each 20x finer).
OffsetFit grid_search_offset(const std::vector<FitCase>& cases, int steps = 201,
                             int refinements = 2);

}  // namespace rsaa
