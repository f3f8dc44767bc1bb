// Smoothing groups: which triangles of a mesh shade as one smooth surface, found from the
// shading normals the mesh carries, so that RSAA's facet edges (RsaaSettings::facet_materials)
// mark where shading is discontinuous and nowhere else.
//
// Two triangles of one draw that share a side (by vertex position, bit for bit: flat-shading
// exporters repeat a corner once per facet) are in one group unless their shading normals differ
// at both ends of the side (by more than kSmoothingNormalDegrees); where they do, the side is a
// crease: flat shading draws a colour step there, which SADP cannot see when the facets meet at
// a gentle angle. A group is a facet when a crease parts it from another group, or when its
// shading is one normal throughout (a flat floor or wall: told apart from the objects on it,
// which SADP cannot do at grazing angles). A facet gets a colour in 1..127: a flat one its
// normal's (a hash), unless a facet it meets across a crease has that colour, then the next
// free one; a curved one the first free one from a hash of the group (one meeting 127 or more
// others reuses one). Other groups (a smooth mesh; a flat face continued by a smooth bevel, whose
// normals carry on across the edge) keep their draw's material.
//
// Deterministic (the order of the triangles decides), O(n log n) in the triangles (it sorts the
// vertices by position and the triangles' sides by their ends), a few dozen bytes per triangle
// while it runs. GpuScene(scene, true) computes it, for the techniques that need it only.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/scene.h"

namespace rsaa {

// Normals that differ by less than this at a shared side are one smooth surface. Measured on
// flat-shaded models at 640x480 (the facet-edges step of tools/readme_figures.sh): material
// edges along creases of a few degrees cost more than the colour step they resolve (0.5 degrees:
// a sphere's nearly coplanar quads -0.1 dB, 3DSMaxExport.STL -0.2; 5 degrees: both gain, and the
// earth sphere +1.9 dB more); from 8 degrees the facet sphere loses 0.6 dB.
constexpr double kSmoothingNormalDegrees = 5.0;

// A triangle's facet value: 0 = not a facet (keeps its draw's material), else 0x80 | colour.
constexpr std::uint8_t kNotAFacet = 0;
constexpr std::uint8_t kFacetBit = 0x80;

// Per triangle of scene.indices (in order), its facet value.
std::vector<std::uint8_t> facet_colours(const Scene& scene);

}  // namespace rsaa
