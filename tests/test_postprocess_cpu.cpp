// The CPU reference post-process on hand-made images whose results are known exactly.
#include <gtest/gtest.h>

#include "core/rsaa/postprocess_cpu.h"

#include <cmath>

namespace rsaa {
namespace {

Image two_colour_image() {
  // 4 x 3; columns 0-1 red, 2-3 blue; row 2 is green (rows grow downwards).
  Image img(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      img.at(x, y) = y == 2 ? Rgb{0, 1, 0} : x < 2 ? Rgb{1, 0, 0} : Rgb{0, 0, 1};
  return img;
}

TEST(PostprocessCpu, OneFetchAtTheMaskOffset) {
  const Image img = two_colour_image();
  OffsetTable t = fallback_table(builtin_pattern("d3d4x"));
  t.offsets[0b0101] = {0.5, 0.0};   // halfway to the right neighbour
  t.offsets[0b0011] = {0.0, 0.25};  // a quarter towards the row below (+y down)
  t.offsets[0b1000] = {1.0, -1.0};  // off the image: clamped to the edge
  std::vector<Mask> masks(12, 0b1111);
  masks[1 * 4 + 1] = 0b0101;
  masks[1 * 4 + 0] = 0b0011;
  masks[0 * 4 + 3] = 0b1000;
  const Image out = apply_offset_table(img, masks, t);
  EXPECT_FLOAT_EQ(out.at(1, 1).r, 0.5f);
  EXPECT_FLOAT_EQ(out.at(1, 1).b, 0.5f);
  EXPECT_FLOAT_EQ(out.at(0, 1).r, 0.75f);
  EXPECT_FLOAT_EQ(out.at(0, 1).g, 0.25f);
  EXPECT_FLOAT_EQ(out.at(3, 0).b, 1.0f);  // clamped: itself
  // All-similar pixels are untouched.
  EXPECT_FLOAT_EQ(out.at(2, 1).b, 1.0f);
  EXPECT_FLOAT_EQ(out.at(0, 2).g, 1.0f);
}

TEST(PostprocessCpu, RejectsMismatchedMasks) {
  const Image img = two_colour_image();
  const OffsetTable t = fallback_table(builtin_pattern("d3d4x"));
  EXPECT_THROW(apply_offset_table(img, std::vector<Mask>(11, 15), t), std::invalid_argument);
  std::vector<Mask> masks(12, 15);
  masks[5] = 16;  // a fifth subsample d3d4x does not have
  EXPECT_THROW(apply_offset_table(img, masks, t), std::invalid_argument);
}

TEST(BilinearFetch, OneByOneImageAndExactCentres) {
  Image one(1, 1);
  one.at(0, 0) = {0.2f, 0.4f, 0.6f};
  EXPECT_FLOAT_EQ(bilinear_fetch(one, 0.7, -0.9).g, 0.4f);
  const Image img = two_colour_image();
  EXPECT_FLOAT_EQ(bilinear_fetch(img, 2.0, 1.0).b, 1.0f);
  EXPECT_FLOAT_EQ(bilinear_fetch(img, 1.5, 0.0).r, 0.5f);
}

}  // namespace
}  // namespace rsaa

namespace rsaa {
namespace {

TEST(PostprocessCpu, NonFiniteColoursNeverSpreadAndHdrPassesThrough) {
  Image img(3, 1);
  img.at(0, 0) = {std::nanf(""), 0, 0};
  img.at(1, 0) = {0.5f, 0.5f, 0.5f};
  img.at(2, 0) = {4.0f, -1.0f, 2.0f};  // HDR and negative
  OffsetTable t = fallback_table(builtin_pattern("d3d4x"));
  t.offsets[1] = {-0.5, 0.0};  // towards the NaN pixel
  t.offsets[2] = {0.5, 0.0};   // towards the HDR pixel
  std::vector<Mask> masks = {15, 1, 15};
  Image out = apply_offset_table(img, masks, t);
  EXPECT_FLOAT_EQ(out.at(1, 0).r, 0.5f);  // kept its own colour
  masks[1] = 2;
  out = apply_offset_table(img, masks, t);
  EXPECT_FLOAT_EQ(out.at(1, 0).r, 2.25f);
  EXPECT_FLOAT_EQ(out.at(1, 0).g, -0.25f);
  EXPECT_TRUE(std::isnan(out.at(0, 0).r));  // a bad pixel stays itself, untouched
}

}  // namespace
}  // namespace rsaa

#include "core/reference/filtered_downsample.h"

namespace rsaa {
namespace {

Image one_bright_texel(int w, int h, int bx, int by) {
  Image img(w, h);
  img.at(bx, by) = {1, 1, 1};
  return img;
}

TEST(FilteredDownsample, KernelWeightsMatchTheirDefinition) {
  // Output pixel (2, 2) owns supersampled texels (4..5, 4..5).
  const Image hi = one_bright_texel(12, 12, 5, 5);
  const std::vector<float> sharp(144, 1.0f), soft(144, 0.0f);
  EXPECT_FLOAT_EQ(filtered_downsample(hi, sharp, 1).at(2, 2).r, 0.25f);  // 2x2 box
  EXPECT_FLOAT_EQ(filtered_downsample(hi, sharp, 2).at(2, 2).r, 0.15f);  // 3/5 over 4 own texels
  EXPECT_FLOAT_EQ(filtered_downsample(hi, sharp, 3).at(2, 2).r, 0.15f);  // alpha 1: kernel 2
  EXPECT_FLOAT_EQ(filtered_downsample(hi, soft, 3).at(2, 2).r, 0.05f);   // alpha 0: large kernel
  // Every kernel keeps a uniform image uniform (weights sum to 1), borders included.
  Image grey(8, 6);
  for (Rgb& p : grey.pixels) p = {0.5f, 0.25f, 2.0f};
  for (int k = 1; k <= 3; ++k)
    for (const Rgb& p : filtered_downsample(grey, std::vector<float>(48, 0.5f), k).pixels) {
      EXPECT_FLOAT_EQ(p.r, 0.5f);
      EXPECT_FLOAT_EQ(p.b, 2.0f);
    }
}

TEST(FilteredDownsample, RejectsBadInput) {
  EXPECT_THROW(filtered_downsample(Image(3, 4), std::vector<float>(12), 1), std::invalid_argument);
  EXPECT_THROW(filtered_downsample(Image(4, 4), std::vector<float>(15), 1), std::invalid_argument);
  EXPECT_THROW(filtered_downsample(Image(4, 4), std::vector<float>(16), 4), std::invalid_argument);
}

}  // namespace
}  // namespace rsaa
