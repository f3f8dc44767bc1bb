#include "trainer/offset_fit.h"

#include <algorithm>
#include <cmath>

#include <ceres/ceres.h>

namespace rsaa {

EstimateMinusCoverage::EstimateMinusCoverage(const FitCase& c, int x, int y)
    : neighbourhood(c.neighbourhood),
      coverage(c.coverage),
      scale(std::sqrt(c.weight)),
      cell_x(x),
      cell_y(y) {}

double fit_cost(const std::vector<FitCase>& cases, Vec2 offset) {
  double cost = 0.0;
  for (const FitCase& c : cases) {
    const double e = bilinear_estimate(c.neighbourhood, offset.x, offset.y) - c.coverage;
    cost += c.weight * e * e;
  }
  return cost;
}

namespace {

// Best point of a 5x5 grid on the cell: a start that keeps Ceres away from poor local minima.
Vec2 coarse_start(const std::vector<FitCase>& cases, int x0, int y0) {
  Vec2 best{x0 + 0.5, y0 + 0.5};
  double best_cost = fit_cost(cases, best);
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      const Vec2 p{x0 + i / 4.0, y0 + j / 4.0};
      const double c = fit_cost(cases, p);
      if (c < best_cost) best_cost = c, best = p;
    }
  return best;
}

Vec2 solve_in_cell(const std::vector<FitCase>& cases, int x0, int y0) {
  const Vec2 start = coarse_start(cases, x0, y0);
  double offset[2] = {start.x, start.y};
  ceres::Problem problem;
  for (const FitCase& c : cases) {
    if (c.weight <= 0.0) continue;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<EstimateMinusCoverage, 1, 2>(
            new EstimateMinusCoverage(c, x0, y0)),
        nullptr, offset);
  }
  if (problem.NumResidualBlocks() == 0) return start;
  for (int k = 0; k < 2; ++k) {
    problem.SetParameterLowerBound(offset, k, k == 0 ? x0 : y0);
    problem.SetParameterUpperBound(offset, k, (k == 0 ? x0 : y0) + 1.0);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;  // masks are fitted in parallel instead
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return {offset[0], offset[1]};
}

}  // namespace

OffsetFit fit_offset(const std::vector<FitCase>& cases) {
  OffsetFit best{{0.0, 0.0}, fit_cost(cases, {0.0, 0.0})};
  bool first = true;
  for (int y0 : {-1, 0})
    for (int x0 : {-1, 0}) {
      const Vec2 p = solve_in_cell(cases, x0, y0);
      const double c = fit_cost(cases, p);
      if (first || c < best.cost) best = {p, c};
      first = false;
    }
  return best;
}

OffsetFit grid_search_offset(const std::vector<FitCase>& cases, int steps, int refinements) {
  Vec2 centre{0.0, 0.0};
  double half_width = 1.0;
  OffsetFit best{centre, fit_cost(cases, centre)};
  for (int round = 0; round <= refinements; ++round) {
    const double step = 2.0 * half_width / (steps - 1);
    const Vec2 origin = centre;
    for (int j = 0; j < steps; ++j)
      for (int i = 0; i < steps; ++i) {
        const Vec2 p{std::clamp(origin.x - half_width + i * step, -1.0, 1.0),
                     std::clamp(origin.y - half_width + j * step, -1.0, 1.0)};
        const double c = fit_cost(cases, p);
        if (c < best.cost) best = {p, c};
      }
    centre = best.offset;
    half_width = 10.0 * step;
  }
  return best;
}

}  // namespace rsaa
