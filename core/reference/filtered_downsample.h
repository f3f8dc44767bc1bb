// Filtered SSAA downsampling (NVIDIA SDK sample, seed 003): a 2x2-supersampled image (4 samples
// a pixel) brought down to the output size with bilinear taps. The seed gives no tap offsets;
// ours, in supersampled texels from the output pixel's centre (which is the corner shared by its
// four texels), pixel space (y down):
//   kernel 1: one tap at (0, 0): the plain 2x2 box.
//   kernel 2: five taps, (0, 0) and the pinwheel (0.5, 1), (1, -0.5), (-0.5, -1), (-1, 0.5):
//             each outer tap sits on a texel column/row and between two rows/columns, so it takes
//             half from one of the pixel's own texels and half from a neighbour: the centre
//             texels get 3/5 of the weight, as the seed's figure 2 says; the pinwheel (a rotated
//             grid) avoids the axis-aligned artefacts a symmetric cross would give.
//   large:    five taps at texel corners, (0, 0) and (1, 2), (2, -1), (-1, -2), (-2, 1): five
//             2x2 blocks that tile without overlapping (the seed's figure 3), 3x3 output pixels.
//   kernel 3: lerp(large, kernel 2, alpha), alpha being the object's filter alpha through
//             kernel 2: objects marked soft (alpha 0) get the large kernel.
#pragma once

#include <array>
#include <vector>

#include "core/util/image.h"
#include "core/util/vec2.h"

namespace rsaa {

using FilterTaps = std::array<Vec2, 5>;
const FilterTaps& small_filter_taps();  // kernel 2
const FilterTaps& large_filter_taps();  // the large kernel of kernel 3

// `supersampled` is 2W x 2H (linear RGB), `alpha` its filter alpha (2W x 2H values); the
// result is W x H. Throws std::invalid_argument for odd sizes, a size mismatch or a kernel
// outside 1..3.
Image filtered_downsample(const Image& supersampled, const std::vector<float>& alpha, int kernel);

}  // namespace rsaa
