// Convex polygons: half-plane clipping and exact area, for coverage by polygon clipping.
#pragma once

#include <vector>

#include "core/util/vec2.h"

namespace rsaa {

using Polygon = std::vector<Vec2>;

// The pixel square [-0.5, 0.5]^2, counter-clockwise in a y-up frame.
Polygon pixel_square();

// Keeps the part of a convex polygon where f(p) = a*p.x + b*p.y + c >= 0 (Sutherland-Hodgman
// against one edge). The result is convex; it may be empty.
Polygon clip_to_half_plane(const Polygon& polygon, double a, double b, double c);

// Absolute area by the shoelace formula.
double polygon_area(const Polygon& polygon);

}  // namespace rsaa
