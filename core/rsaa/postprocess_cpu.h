// CPU reference of the RSAA post-process: mask -> offset from the table -> one bilinear fetch.
// It is the oracle that the GL pass is tested against.
#pragma once

#include <vector>

#include "core/util/image.h"
#include "core/rsaa/mask.h"
#include "core/rsaa/offset_table.h"

namespace rsaa {

// masks[y * width + x] is the similarity mask of pixel (x, y) in the table's pattern order.
// Pixels whose mask is all-similar keep their colour (the runtime skips them). Colours are
// linear and unbounded: HDR (> 1) and negative values pass through the bilinear fetch as they
// are. When the fetch meets a NaN or infinite neighbour the pixel keeps its own colour, so a
// bad value never spreads (a bad pixel itself stays as it is). Throws
// std::invalid_argument when the sizes disagree or a mask does not fit the pattern.
Image apply_offset_table(const Image& colour, const std::vector<Mask>& masks,
                         const OffsetTable& table);

}  // namespace rsaa
