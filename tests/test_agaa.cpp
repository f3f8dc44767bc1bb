// The AGAA CPU reference: eq. 1 against closed forms, the clustering of Algorithm 1 on hand-made
// sample sets, Toksvig's factor, and the resolve at its extremes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/reference/agaa.h"
#include "core/reference/scene_shading.h"

namespace rsaa {
namespace {

AgaaSample at(float x, float y, float z, Normal3 n) { return {true, {x, y, z}, n}; }
const Normal3 kFacing{0, 0, 1}, kSideways{1, 0, 0};

TEST(Agaa, DistanceIsEquationOne) {
  EXPECT_FLOAT_EQ(agaa_distance(at(0, 0, -1, kFacing), at(0, 0, -1, kFacing), 0.1f), 0.0f);
  EXPECT_NEAR(agaa_distance(at(0, 0, -1, kFacing), at(0.1f, 0, -1, kFacing), 0.1f), 1.0f, 1e-5f);  // k apart
  EXPECT_FLOAT_EQ(agaa_distance(at(0, 0, -1, kFacing), at(0, 0, -1, {0, 0, -1}), 0.1f), 4.0f);     // opposite
  EXPECT_FLOAT_EQ(agaa_distance(at(0, 0, -1, kFacing), at(0, 0, -1, kSideways), 0.1f), 1.0f);      // 90 degrees
}

TEST(Agaa, OneSurfaceMakesOneAggregate) {
  std::vector<AgaaSample> s;
  for (int i = 0; i < 8; ++i) s.push_back(at(0.001f * i, 0, -1, kFacing));
  const AgaaClusters c = define_aggregates(s, {});
  EXPECT_EQ(c.count, 1);
  for (int a : c.aggregate) EXPECT_EQ(a, 0);
}

TEST(Agaa, TwoSurfacesSplitExactly) {
  std::vector<AgaaSample> s;
  for (int i = 0; i < 8; ++i) s.push_back(i % 2 ? at(0.001f * i, 0, -2, kSideways) : at(0.001f * i, 0, -1, kFacing));
  const AgaaClusters c = define_aggregates(s, {});
  ASSERT_EQ(c.count, 2);
  for (int i = 2; i < 8; ++i) EXPECT_EQ(c.aggregate[i], c.aggregate[i % 2]);
  EXPECT_NE(c.aggregate[0], c.aggregate[1]);
}

TEST(Agaa, BackgroundSamplesJoinNoAggregate) {
  std::vector<AgaaSample> s(4);
  EXPECT_EQ(define_aggregates(s, {}).count, 0);
  s[2] = at(0, 0, -1, kFacing);
  const AgaaClusters c = define_aggregates(s, {});
  EXPECT_EQ(c.count, 1);
  EXPECT_EQ(c.aggregate, (std::vector<int>{-1, -1, 0, -1}));
}

TEST(Agaa, TheCharacteristicLengthDecidesWhatIsOneSurface) {
  // Two parallel layers 5 cm apart: with k = 10 cm, eq. 1 gives 0.25, not above t: one
  // aggregate; with k = 1 cm, 25: two.
  std::vector<AgaaSample> s = {at(0, 0, -1, kFacing), at(0, 0, -1.05f, kFacing), at(0, 0, -1, kFacing),
                               at(0, 0, -1.05f, kFacing)};
  EXPECT_EQ(define_aggregates(s, {2, 0.1f, 0.25f}).count, 1);
  EXPECT_EQ(define_aggregates(s, {2, 0.01f, 0.25f}).count, 2);
}

TEST(Agaa, ThreeAggregatesWhenAskedAndPresent) {
  std::vector<AgaaSample> s = {at(0, 0, -1, kFacing), at(0, 0, -2, kSideways), at(0, 0, -3, {0, 1, 0}),
                               at(0, 0, -1, kFacing), at(0, 0, -2, kSideways), at(0, 0, -3, {0, 1, 0})};
  const AgaaClusters c = define_aggregates(s, {3, 0.1f, 0.25f});
  ASSERT_EQ(c.count, 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(c.aggregate[i], c.aggregate[i + 3]);
  EXPECT_NE(c.aggregate[0], c.aggregate[1]);
  EXPECT_NE(c.aggregate[1], c.aggregate[2]);
}

TEST(Agaa, ToksvigFactor) {
  EXPECT_FLOAT_EQ(toksvig_exponent(1.0f, 32.0f), 32.0f);
  EXPECT_NEAR(toksvig_exponent(0.9f, 32.0f), 0.9f / (0.9f + 3.2f) * 32.0f, 1e-5f);
  EXPECT_FLOAT_EQ(toksvig_exponent(0.0f, 32.0f), 1e-3f);
  EXPECT_FLOAT_EQ(toksvig_exponent(std::nanf(""), 32.0f), 1e-3f);
}

TEST(Agaa, ResolveOfOneFullAggregateIsTheSurfaceShading) {
  const Normal3 ray{0.1f, -0.2f, -1.0f};
  AgaaAggregateSums a;
  a.albedo = {0.5f, 0.25f, 0.125f};
  a.normal = normalized({0.3f, 0.4f, 0.8f});
  a.view_z = -2.0f;
  a.weight = 1.0f;
  const Rgb c = agaa_resolve({a}, ray, {1, 1, 1});
  const Rgb expected = shade_surface(a.albedo, a.normal, {0.2f, -0.4f, -2.0f}, 32.0f, 0.25f);
  EXPECT_NEAR(c.r, expected.r, 1e-5f);
  EXPECT_NEAR(c.b, expected.b, 1e-5f);
  // Half the pixel: half the background.
  AgaaAggregateSums half = a;
  half.albedo = {0.25f, 0.125f, 0.0625f};
  half.normal = {a.normal.x / 2, a.normal.y / 2, a.normal.z / 2};
  half.view_z = -1.0f;
  half.weight = 0.5f;
  const Rgb h = agaa_resolve({half}, ray, {1, 1, 1});
  EXPECT_NEAR(h.g, 0.5f * expected.g + 0.5f, 1e-5f);
}

TEST(Agaa, FilteredDiffuseIsTheMeanLambertTermOfTheAggregate) {
  // Two facets of a ridge, both lit and both facing the viewer, half the pixel each, no
  // specular (exponent high enough that the lobe is nowhere near): the exact diffuse of the
  // pixel is the mean of their two Lambert terms, which the filtered term reproduces and the
  // normalised mean normal overestimates.
  const Normal3 light = normalized({-0.4f, 0.7f, 0.6f});
  const Normal3 n1 = normalized({-0.6f, 0.2f, 0.77f}), n2 = normalized({0.2f, 0.8f, 0.57f});
  AgaaAggregateSums a;
  a.albedo = {1, 1, 1};
  a.normal = {0.5f * (n1.x + n2.x), 0.5f * (n1.y + n2.y), 0.5f * (n1.z + n2.z)};
  a.view_z = -2.0f;
  a.weight = 1.0f;
  const Normal3 ray{0, 0, -1};
  const float mean_lambert = 0.5f * (std::max(dot(n1, light), 0.0f) + std::max(dot(n2, light), 0.0f));
  ASSERT_GT(dot(n1, light), 0.0f);
  ASSERT_GT(dot(n2, light), 0.0f);
  // Diffuse part of the result: remove the (small, identical) specular of both by comparing the
  // blue channel of a white albedo against the red channel of a black one.
  const auto diffuse_of = [&](bool filtered) {
    AgaaAggregateSums black = a;
    black.albedo = {0, 0, 0};
    return agaa_resolve({a}, ray, {0, 0, 0}, filtered).b - agaa_resolve({black}, ray, {0, 0, 0}, filtered).r;
  };
  EXPECT_NEAR(diffuse_of(true), 0.12f + 0.88f * mean_lambert, 1e-5f);
  EXPECT_GT(diffuse_of(false), 0.12f + 0.88f * mean_lambert + 0.01f);
}

TEST(Agaa, ResolveExtremesStayFinite) {
  AgaaAggregateSums zero_normal;
  zero_normal.albedo = {0.5f, 0.5f, 0.5f};
  zero_normal.view_z = -1.0f;
  zero_normal.weight = 1.0f;
  AgaaAggregateSums nan_weight;
  nan_weight.weight = std::nanf("");
  for (const auto& list : std::vector<std::vector<AgaaAggregateSums>>{{}, {zero_normal}, {nan_weight}, {zero_normal, zero_normal}}) {
    const Rgb c = agaa_resolve(list, {0, 0, -1}, {0.2f, 0.3f, 0.4f});
    EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
  }
  EXPECT_FLOAT_EQ(agaa_resolve({}, {0, 0, -1}, {0.2f, 0.3f, 0.4f}).g, 0.3f);
}

}  // namespace
}  // namespace rsaa
