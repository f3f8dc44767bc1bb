// Coplanar overlaps between draws (z-fighting in the asset), resolved by draw order.
//
// Two draws whose triangles lie in one plane and overlap (a rafter's end flush with a roof's
// gable, a decal modelled in its wall) tie over the reals; in float the interpolated depths
// differ by rounding, so which one a depth test keeps changes with the units, the camera and the
// rasteriser (the IFC house at 10^3 scale: 251 pixels changed surface). A depth test keeps the
// first draw on an exact tie; draw_depth_ranks() makes that hold for near ties too: a draw that
// overlaps an earlier draw in one plane gets a rank one above the earlier draw's, and the vertex
// stage (shaders/scene.vert, u_depth_bias) moves its vertices back along their view rays by
// kCoplanarDepthStep window-depth units per rank: more than the rounding of coplanar depths (at
// most 55 steps of 2^-24 for 99.99% of a scene's fragments between scales; README, *Held-out
// models*), small against the gaps scenes model (a surface modelled closer than rank x 2^-18 of
// window depth in front of an overlapped one would be crossed).
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/scene.h"

namespace rsaa {

// Window depth (0..1) added per rank.
constexpr float kCoplanarDepthStep = 1.0f / 262144.0f;  // 2^-18

// Bounds of the search (it is a load-time convenience, not a guarantee): two triangles are
// coplanar when their unit normals differ by less than kCoplanarNormalTolerance and their planes'
// offsets by less than kCoplanarDistanceTolerance of the scene's extent; they overlap when their
// projections share more than kCoplanarOverlapTolerance of the extent across every separating
// axis (so triangles that only touch along an edge do not). At most kCoplanarPairTests pairs are
// compared (about a tenth of a second here; the IFC house's 36k triangles in 177 draws take 0.8
// million pairs, 16 ms); past that the ranks found so far stand. Scenes of one draw cost nothing.
constexpr double kCoplanarNormalTolerance = 1e-5;
constexpr double kCoplanarDistanceTolerance = 1e-6;
constexpr double kCoplanarOverlapTolerance = 1e-6;
constexpr std::uint64_t kCoplanarPairTests = 5'000'000;

struct CoplanarRanks {
  std::vector<std::uint32_t> rank;  // per draw; 0 = overlaps no earlier draw in a plane
  std::uint64_t pair_tests = 0;     // triangle pairs compared
  bool complete = true;             // false: stopped at kCoplanarPairTests
};

CoplanarRanks draw_depth_ranks(const Scene& scene, std::uint64_t max_pair_tests = kCoplanarPairTests);

// Sets every draw's DrawRange::depth_rank from draw_depth_ranks(); says on stderr when the search
// stopped at its bound.
void rank_coplanar_draws(Scene& scene);

}  // namespace rsaa
