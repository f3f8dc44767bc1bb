// CPU reference of Bertolami's dynamic coverage anti-aliasing (seed 002): per pixel two colours,
// two depths and two 16-bit coverage masks (40 B in the seed's units, against 72 B for 4x MSAA),
// updated once per fragment in primitive order, then resolved by coverage.
//
// Two rule sets (`dyncov --rules seed|surface`, the GL resolve implements both):
//
// Seed: the seed's update and resolve as written. Slots start as the clear colour at DEPTH_MAX
// with full masks; a fragment closer than either slot evicts the farther one (slot 0 on a tie);
// the resolve weights the nearer slot by its whole mask and the farther by the samples the
// nearer does not cover, divided by the samples either covers (TCC). What the seed leaves open:
//  - A fragment that covers no coverage sample (a partial overlap between samples, a thin
//    triangle) is ignored, as hardware coverage would: it never evicts a slot.
//  - Depth ties: "closer" is strict, so an equal-depth fragment is dropped when both slots are
//    at that depth; with equal slot depths the else-branch of the seed replaces slot 0 (and the
//    resolve's else-branch takes slot 1 as the nearer).
//  - Equal within float rounding is equal (seed_closer()): every comparison of two depths (the
//    incoming against each slot, the slots against each other at the eviction and the resolve)
//    counts a difference up to kSeedDepthTie as a tie. The two triangles of a planar quad have
//    equal depths over the reals, but their window depths, computed in float from different
//    vertices, differ in the last bits, and which one comes out nearer changes with anything that
//    moves those bits (the scene's units: 10^3 and 10^-3 gave 46-47 dB against the unscaled
//    image at 640x480, 38-39 at 160x120). Over the reals the rules are the seed's; only
//    differences float cannot resolve are ties.
//  - A non-finite depth or colour: the fragment is ignored (a NaN would never compare closer
//    anyway, and must not reach the output).
//  - Total coverage 0 (TCC = 0) cannot follow from the rules above (slots start with full masks
//    and are only replaced by non-empty ones); should it occur, the nearer colour is output.
//  - Samples neither mask covers do not show the background: the seed divides by TCC.
//  - Many overlaps with equal coverage: the last two closer-than-a-slot fragments win, in
//    primitive order.
// On tessellated models these rules lose against no AA: a pixel touched by three triangles keeps
// the last two closer ones (often two triangles of one surface), the background slot is evicted
// and the division by TCC stretches the two over samples they do not cover.
//
// Surface (the default, `--rules surface`): the same two slots, each also keeping its facet
// normal and depth slopes (+8 B a slot: 2 x 16-bit normal, 2 x 16-bit slopes; 56 B a pixel in
// the seed's units), and these answers to the seed's open questions, each measured on the bench
// (README, "Coverage-based techniques"):
//  1. Slots start empty; samples no slot covers show the clear colour. The background is an
//     implicit surface that never needs a slot (the seed's full-mask background slot is evicted
//     by the second fragment, then the division by TCC hides it).
//  2. One surface, one slot: a fragment whose normal is within pi/16 of a slot's, whose depth
//     interval over the pixel overlaps it (DCAA's test: a continuous depth plane and normal) and
//     which covers none of the slot's samples (triangles of one surface never cover a sample
//     twice; two layers crossing at a small angle do) is merged into it (masks ORed; colour,
//     depth plane and normal averaged by coverage). A tessellated surface fills one slot
//     instead of both; "many overlaps with equal coverage" of one surface add up instead of
//     replacing each other.
//  3. Otherwise it takes an empty slot.
//  4. Both slots full: of the two slots and the fragment, one goes: dropped, or merged into
//     another. Per sample the nearest depth plane covering it shows; dropping a candidate costs
//     each sample it shows (what would show there instead is not known yet), merging two whose
//     depth intervals overlap costs the change of their shown samples' colours when the merged
//     colour is weighted by samples shown (2 s_a s_b / (s_a + s_b) times the largest channel
//     difference on a square-root scale); the cheapest goes, ties to dropping the one showing
//     the fewest samples (ties: the farther at the centre). So a hidden fragment (no sample
//     shown) gives way without a z-prepass, and two facets of one curved surface whose normals
//     differ beyond rule 2's cone share a slot (cost ~0) instead of pushing out the first small
//     fragment of a nearer surface (the far side of a limb, X/BCN_Epileptic.X: +3.1 dB).
//     (Before: the one showing the fewest samples went, merged into the slot overlapping it most
//     or dropped; DcaaSettings::second_merge_least_change = false, DCAA's rule.)
//  5. Resolve: each of the 16 samples takes the nearest slot covering it by its depth plane,
//     uncovered samples the background: C = sum n_i c_i / 16 + (16 - sum n_i) / 16 background.
//     (The seed orders the two slots by one depth each; a fin extrapolated to the pixel centre
//     lies behind the surface it stands on, and the surface wins samples the fin covers.)
//  6. A fragment covering no sample (a partial overlap between samples, a thin triangle below
//     the sampling) and non-finite input are ignored as in the seed rules.
// Rules 2-5 are DCAA's Algorithm 1 (core/reference/dcaa.h) with 2 surfaces over 16 samples, its first
// merge only between disjoint coverage, its second counting visibility per sample and dropping
// hidden surfaces; the GL resolve is DCAA's with those settings
// (dynamic_coverage_surface_settings()).
#pragma once

#include <cstdint>
#include <string>

#include "core/reference/coverage_fragment.h"
#include "core/reference/dcaa.h"

namespace rsaa {

enum class DynamicCoverageRules { Seed, Surface };

// The seed rules' tie bound in window depth (0 near, 1 far): 16 float steps of a depth in
// [0.5, 1), 2^-20. Window depths come out of z / w * 0.5 + 0.5, whose last step rounds at 2^-24
// whatever the depth, and the plane evaluated at the pixel centre adds a few such steps: one
// fragment rendered at 10^3, 1 and 10^-3 times the default scene's units has depths within
// 5 steps of each other for 99.9% of fragments, within 55 for 99.99% (tiny or sliver triangles
// extrapolated far from their vertices; tests/test_coverage_units.cpp). 16 steps are 9.5 x 10^-7; a surface 1 cm in front of
// another at 10 m is 5 x 10^-5 nearer in window depth with the default scene's 0.5 near plane.
constexpr float kSeedDepthTie = 0x1p-20f;
// `a` is closer than `b` beyond float rounding (shaders/coverage_resolve.frag computes the same).
inline bool seed_closer(float a, float b) { return b - a > kSeedDepthTie; }

// The surface rules as DCAA settings (what the GL resolve is given too).
DcaaSettings dynamic_coverage_surface_settings();
// The 16 coverage samples (the d3d16x positions).
const SamplePattern& dynamic_coverage_pattern();

// "seed" | "surface"; throws std::invalid_argument otherwise.
DynamicCoverageRules dynamic_coverage_rules(const std::string& name);

class DynamicCoveragePixel {
 public:
  static constexpr int kSamples = 16;

  // Seed rules: masks 0xFFFF, colours the clear colour, depths DEPTH_MAX (1). Surface rules:
  // no slot in use.
  DynamicCoveragePixel(Rgb clear, DynamicCoverageRules rules);

  // One fragment: IC = colour, ID = depth at the pixel centre, IM = its 16 coverage bits.
  // Returns false when the fragment was ignored or dropped (seed rules) or ignored (surface).
  bool insert(const CoverageFragment& fragment);
  Rgb resolve() const;

  // The seed rules' slots.
  Rgb colour[2];
  float depth[2];
  std::uint16_t mask[2];
  // The surface rules' slots (at most 2).
  const std::vector<DcaaSurface>& surfaces() const { return surfaces_.surfaces(); }

 private:
  DynamicCoverageRules rules_;
  Rgb clear_;
  DcaaPixel surfaces_;
};

constexpr double kDynamicCoveragePaperBytesPerPixel = 40.0;     // 2 x (16 B colour + 2 B depth + 2 B mask)
constexpr double kDynamicCoverageSurfaceBytesPerPixel = 56.0;   // + 2 x (4 B normal + 4 B depth slopes)
constexpr double kDynamicCoveragePaperMsaaBytesPerPixel = 72.0;  // 4x MSAA in the same units

}  // namespace rsaa
