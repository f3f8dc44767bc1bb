// CPU reference of Bertolami's dynamic coverage anti-aliasing (seed 002): per pixel two colours,
// two depths and two 16-bit coverage masks (40 B in the seed's units, against 72 B for 4x MSAA);
// each fragment either evicts the farther slot or is dropped; the resolve weights the nearer
// slot by its whole mask and the farther one by the samples the nearer does not cover.
//
// The seed leaves some cases open; the choices (tested in tests/test_coverage_techniques.cpp):
//  - A fragment that covers no coverage sample (a partial overlap between samples, a thin
//    triangle) is ignored, as hardware coverage would: it never evicts a slot.
//  - Depth ties: "closer" is strict, so an equal-depth fragment is dropped when both slots are
//    at that depth; with equal slot depths the else-branch of the seed replaces slot 0.
//  - A non-finite depth or colour: the fragment is ignored (a NaN would never compare closer
//    anyway, and must not reach the output).
//  - Total coverage 0 (TCC = 0) cannot follow from the rules above (slots start with full masks
//    and are only replaced by non-empty ones); should it occur, the nearer colour is output.
//  - Samples neither mask covers do not show the background: the seed divides by TCC.
//  - Many overlaps with equal coverage: the last two closer-than-a-slot fragments win, in
//    primitive order.
#pragma once

#include <cstdint>

#include "core/coverage_fragment.h"

namespace rsaa {

class DynamicCoveragePixel {
 public:
  // At the start of a frame: masks 0xFFFF, colours the clear colour, depths DEPTH_MAX (1).
  explicit DynamicCoveragePixel(Rgb clear);

  // The seed's update with IC = colour, ID = depth at the pixel centre, IM = the fragment's 16
  // coverage bits. Returns false when the fragment was ignored or dropped.
  bool insert(const CoverageFragment& fragment);
  Rgb resolve() const;

  Rgb colour[2];
  float depth[2];
  std::uint16_t mask[2];
};

constexpr double kDynamicCoveragePaperBytesPerPixel = 40.0;     // 2 x (16 B colour + 2 B depth + 2 B mask)
constexpr double kDynamicCoveragePaperMsaaBytesPerPixel = 72.0;  // 4x MSAA in the same units

}  // namespace rsaa
