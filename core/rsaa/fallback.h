// The paper's fallback offset for masks that no training case explains (RSAA section 2.3).
//
// Direction: towards the dissimilar subsample farthest from the pixel centre (the lowest index
// wins a tie). Length t along that unit direction u: one bilinear fetch at t*u keeps the weight
// (1 - t|ux|)(1 - t|uy|) of the pixel's own colour; t is chosen so that this weight equals the
// similar fraction s = popcount(mask) / n, i.e. the resampled colour approximates the blend by
// coverage area. t lies in [0, 1 / max(|ux|, |uy|)], so |dx|, |dy| <= 1.
// The all-similar mask, and a mask whose dissimilar subsamples all sit on the centre, give (0, 0).
#pragma once

#include "core/rsaa/mask.h"
#include "core/rsaa/sample_pattern.h"
#include "core/util/vec2.h"

namespace rsaa {

Vec2 fallback_offset(const SamplePattern& pattern, Mask mask);

// The length t above for a unit direction u and similar fraction s in [0, 1].
double fallback_length(Vec2 unit_direction, double similar_fraction);

}  // namespace rsaa
