#include "runtime/render.h"

#include <algorithm>
#include <stdexcept>

#include "runtime/gl_context.h"

namespace rsaa {

void validate_size(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is outside 1.." + std::to_string(kMaxImageSide) + " per side");
}

Image read_back_image(GLuint texture, int width, int height) {
  std::vector<float> rgba(std::size_t(width) * height * 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  gl::check("reading back an image");
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &rgba[(std::size_t(height - 1 - y) * width + x) * 4];
      image.at(x, y) = {p[0], p[1], p[2]};
    }
  return image;
}

std::vector<std::uint32_t> read_back_uints(GLuint texture, int width, int height) {
  std::vector<std::uint32_t> raw(std::size_t(width) * height);
  glGetTextureImage(texture, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(raw.size() * 4), raw.data());
  gl::check("reading back integers");
  std::vector<std::uint32_t> rows(raw.size());
  for (int y = 0; y < height; ++y)
    std::copy_n(&raw[std::size_t(height - 1 - y) * width], width, &rows[std::size_t(y) * width]);
  return rows;
}

Image render_frame(const GpuScene& scene, const Camera& camera, const TechniqueOptions& options,
                   int width, int height, RenderStats* stats) {
  validate_size(width, height);
  auto technique = make_technique(options, width, height);
  const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, width, height);
  const View view = make_view(camera, width, height);
  // A first, untimed frame: llvmpipe compiles shaders at their first draw.
  technique->render(scene, view, output.get());
  technique->take_pass_times();
  technique->render(scene, view, output.get());
  Image image = read_back_image(output.get(), width, height);
  if (stats) {
    stats->label = technique_label(options);
    stats->pass_times = technique->take_pass_times();
    stats->bytes_per_pixel = technique->bytes_per_pixel();
    stats->choices = technique->choices();
  }
  return image;
}

}  // namespace rsaa
