// Sample patterns: ordered subsample positions in pixel space (see conventions.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/rsaa/mask.h"
#include "core/util/vec2.h"

namespace rsaa {

struct SamplePattern {
  std::string name;
  std::vector<Vec2> positions;  // pixel space, y down; index i = mask bit i

  int size() const { return static_cast<int>(positions.size()); }
  Mask all_similar() const { return full_mask(size()); }
  // Number of masks, i.e. entries of an offset table for this pattern (2^n).
  std::size_t mask_count() const { return std::size_t{1} << positions.size(); }
};

// Names of the patterns with fixed positions (docs/conventions.md section 1).
const std::vector<std::string>& builtin_pattern_names();
bool is_builtin_pattern(const std::string& name);
// Throws std::invalid_argument naming the known patterns when `name` is not one of them.
SamplePattern builtin_pattern(const std::string& name);

// A pattern name is 1 to 64 letters, digits, '-' or '_': it becomes file names and shader
// identifiers, so it can neither leave a directory nor add lines to generated code.
constexpr std::size_t kMaxPatternNameLength = 64;
bool is_valid_pattern_name(const std::string& name);

// Two samples closer than this in both coordinates, or a coordinate nonzero but smaller, make
// a degenerate pattern (coincident or subnormal positions): refused.
constexpr double kMinSampleSpacing = 1.0 / 1024.0;

// Validates and wraps positions given in pixel space. Throws std::invalid_argument when the
// name is invalid, a position is not finite, lies outside the pixel [-0.5, 0.5]^2, is
// degenerate (see kMinSampleSpacing), or the count is not 1..64.
SamplePattern pattern_from_positions(const std::string& name, const std::vector<Vec2>& positions);

// The cell pattern of `base` (docs/conventions.md, section 1): the pixel split into `columns` x
// `rows` cells (row by row from the top-left), each holding base's positions scaled into it;
// subsample i is base's i % m in cell i / m (m = base's count). A driver with m samples draws it
// in one multisample draw at columns x rows times the image's size. Named custom-BASE-wide
// (2 x 1), -tall (1 x 2), -quad (2 x 2), else custom-BASE-cellsCxR. Throws std::invalid_argument
// for cells below 1 or more subsamples than a pattern has.
SamplePattern cell_pattern(const SamplePattern& base, int columns, int rows);

// Positions as glGetMultisamplefv reports them (origin bottom-left, y up, in [0,1]^2).
SamplePattern pattern_from_gl_positions(const std::string& name,
                                        const std::vector<Vec2>& gl_positions);

// The neighbouring pixel (i, j) != (0, 0) that lies in a subsample's direction: the subsample
// scaled onto the boundary of the square max(|x|, |y|) = 1, each coordinate rounded (half away
// from zero). Pixel space, y down. RSAA's authentication compares a subsample with this pixel;
// for d3d8x it reproduces the paper's sampleOffset[] table (tested). A subsample at the centre
// has no direction: (1, 0).
struct PixelStep {
  int i = 0, j = 0;
};
PixelStep outside_pixel_towards(Vec2 sample);

// The representative of a mask's dissimilar cluster, for post-pass authentication: the
// dissimilar subsample farthest from the pixel centre and, of equally distant ones, the last in
// pattern order, as Listing 3 of the paper (it keeps the last dissimilar subsample it meets; the
// d3d8x order is by increasing distance). -1 when every subsample is similar.
int representative_dissimilar(const SamplePattern& pattern, Mask mask);

// Names a table may carry besides the built-ins: patterns whose positions come from the
// table itself ("gl2x", "gl4x", "gl8x", "gl16x", read from a GL driver, and "custom-..." patterns).
bool is_known_pattern_name(const std::string& name);
// The sample count of a driver pattern name "glNx" (N = 2, 4, 8 or 16), 0 for any other name.
int gl_pattern_samples(const std::string& name);

}  // namespace rsaa
