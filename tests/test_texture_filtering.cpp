// Scene textures are filtered anisotropically (Scene::texture_anisotropy, scene_texture() of
// shaders/scene_shading.glsl): on a floor seen at a grazing angle, stripes running away from the
// eye keep their contrast, where trilinear filtering alone picks the mip level of the compressed
// direction and blurs them to grey.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

#include "runtime/camera.h"
#include "runtime/gpu_scene.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/techniques/techniques.h"
#include "tests/gl_test.h"

namespace rsaa {
namespace {

// A floor (y = 0) 40 units wide and 60 deep, textured with stripes along z: 8 black and white
// pairs across a 64-texel texture repeated every 4 units of x and of z.
Scene striped_floor(float anisotropy) {
  Scene scene;
  scene.name = "striped floor";
  TextureImage stripes;
  stripes.width = stripes.height = 64;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const std::uint8_t level = (x / 4) % 2 ? 255 : 0;
      stripes.rgba.insert(stripes.rgba.end(), {level, level, level, 255});
    }
  scene.textures.push_back(stripes);
  for (auto [x, z] : {std::pair{-20.0f, 0.0f}, {20.0f, 0.0f}, {20.0f, -60.0f}, {-20.0f, -60.0f}}) {
    SceneVertex v;
    v.position = {x, 0.0f, z};
    v.normal = {0.0f, 1.0f, 0.0f};
    v.uv = {x / 4.0f, z / 4.0f};
    v.albedo = glm::vec3(1.0f);
    scene.vertices.push_back(v);
  }
  scene.indices = {0, 1, 2, 0, 2, 3};
  DrawRange draw;
  draw.index_count = 6;
  draw.texture = 0;
  scene.draws.push_back(draw);
  scene.camera = Camera{{0.0f, 0.3f, 0.0f}, {0.0f, 0.0f, -8.0f}, {0.0f, 1.0f, 0.0f}, 30.0f, 0.05f, 100.0f};
  scene.texture_anisotropy = anisotropy;
  return scene;
}

// Mean over the image rows from `first` to `last` of the standard deviation of the red channel
// along the row: the stripes' contrast.
double stripe_contrast(const Image& image, int first, int last) {
  double sum = 0.0;
  for (int y = first; y <= last; ++y) {
    double mean = 0.0, square = 0.0;
    for (int x = 0; x < image.width; ++x) {
      const double r = image.at(x, y).r;
      mean += r, square += r * r;
    }
    mean /= image.width, square /= image.width;
    sum += std::sqrt(std::max(0.0, square - mean * mean));
  }
  return sum / (last - first + 1);
}

class TextureFiltering : public test::GlTest {};

TEST_F(TextureFiltering, StripesAwayFromTheEyeKeepTheirContrastOnAGrazingFloor) {
  constexpr int kWidth = 256, kHeight = 128;
  const auto render = [&](float anisotropy) {
    const Scene scene = striped_floor(anisotropy);
    const GpuScene gpu(scene);
    return render_frame(gpu, *scene.camera, technique_options("noaa"), kWidth, kHeight);
  };
  const Image trilinear = render(1.0f), anisotropic = render(kDefaultTextureAnisotropy);
  // The floor's far rows: from two rows below the horizon (the view looks 2.1 degrees down: the
  // horizon is 9 rows above the centre) to the centre, 36 to 8 units away, where a pixel spans
  // about 300 to 14 texels along z and 2 to 0.5 across the stripes.
  const int horizon = kHeight / 2 - 9;
  const double far_trilinear = stripe_contrast(trilinear, horizon + 2, kHeight / 2);
  const double far_anisotropic = stripe_contrast(anisotropic, horizon + 2, kHeight / 2);
  // Near rows, where both filters sample the finest levels, are alike.
  const double near_trilinear = stripe_contrast(trilinear, kHeight - 10, kHeight - 1);
  const double near_anisotropic = stripe_contrast(anisotropic, kHeight - 10, kHeight - 1);
  std::printf("stripe contrast far: trilinear %.4f, anisotropic %.4f; near: %.4f, %.4f\n", far_trilinear,
              far_anisotropic, near_trilinear, near_anisotropic);
  EXPECT_GT(far_anisotropic, 3.0 * far_trilinear);
  EXPECT_NEAR(near_anisotropic, near_trilinear, 0.1 * near_trilinear);
}

TEST_F(TextureFiltering, AnAnisotropyOutsideOneToSixteenOrNotANumberIsRefused) {
  for (float bad : {0.5f, 0.0f, -1.0f, 16.5f, NAN, INFINITY}) {
    const Scene scene = striped_floor(bad);
    EXPECT_THROW(GpuScene{scene}, std::invalid_argument) << bad;
  }
}

// Texture coordinates that are not finite or far beyond the texture (broken files) give finite
// colours with every number of probes, and a floor seen edge-on (derivatives without bound).
TEST_F(TextureFiltering, BrokenTextureCoordinatesGiveFiniteColours) {
  for (float anisotropy : {1.0f, kDefaultTextureAnisotropy}) {
    Scene scene = striped_floor(anisotropy);
    scene.vertices[0].uv = {NAN, 0.0f};
    scene.vertices[1].uv = {1e30f, -INFINITY};
    scene.vertices[2].uv = {-3e38f, 7.0f};
    for (const Camera& camera : {*scene.camera, Camera{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -8.0f}, {0.0f, 1.0f, 0.0f}, 30.0f, 0.05f, 100.0f}}) {
      const GpuScene gpu(scene);
      for (const char* technique : {"noaa", "dcaa", "agaa"}) {
        const Image image = render_frame(gpu, camera, technique_options(technique), 64, 32);
        for (const auto& p : image.pixels)
          ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b)) << technique << " anisotropy " << anisotropy;
      }
    }
  }
}

}  // namespace
}  // namespace rsaa
