// rsaa render: one frame of one technique, headless, written as an image.
#include <cstdio>
#include <memory>
#include <optional>

#include "image/image_io.h"
#include "runtime/gl_context.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/technique_options.h"

namespace rsaa::cli {
namespace {

struct RenderArgs {
  std::string scene = "builtin:default";
  TechniqueOptions technique;
  int width = 640, height = 480;
  std::string camera;
  std::string out;
  float scene_scale = 1.0f;
  float anisotropy = kDefaultTextureAnisotropy;
};

int run_render(const RenderArgs& a) {
  validate(a.technique);
  validate_size(a.width, a.height);
  Scene scene = scaled_scene(load_scene_within(a.scene, kSceneLoadSeconds), a.scene_scale);
  scene.texture_anisotropy = a.anisotropy;
  std::optional<Camera> camera;
  if (!a.camera.empty()) camera = parse_camera(a.camera, scene.bounds_min(), scene.bounds_max());
  require_image_module();  // its images are written at the end: said now if they cannot be
  gl::HeadlessContext context;
  const GpuScene gpu_scene(scene, needs_facet_colours(a.technique));
  RenderStats stats;
  const Image image = render_frame(gpu_scene, choose_camera(scene, camera), a.technique, a.width,
                                   a.height, &stats);
  write_image(a.out, image);
  std::printf("%s: %s, %dx%d, %zu triangles -> %s\n", stats.label.c_str(), scene.name.c_str(),
              a.width, a.height, scene.triangle_count(), a.out.c_str());
  for (const PassTime& t : stats.pass_times) {
    char query[48] = "n/a";
    if (t.milliseconds != kNoTimerQuery) std::snprintf(query, sizeof query, "%.2f ms", t.milliseconds);
    std::printf("  %-13s %8.2f ms (GL timer query %s)\n", t.pass.c_str(), t.wall_milliseconds, query);
  }
  std::printf("  memory        %8.1f bytes/pixel\n", stats.bytes_per_pixel);
  if (!stats.choices.empty()) std::printf("  %s\n", stats.choices.c_str());
  return 0;
}

}  // namespace

Action add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render one image of a scene with one technique (headless)");
  std::string builtins;
  for (const std::string& name : builtin_scene_names()) builtins += (builtins.empty() ? "" : "|") + name;
  cmd->add_option("--scene", args->scene,
                  "builtin:" + builtins + ", or a model file assimp reads (OBJ, glTF, PLY, 3DS, ...)")
      ->capture_default_str();
  add_technique_options(cmd, args->technique);
  cmd->add_option("--width", args->width, "Image width")->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")->capture_default_str();
  cmd->add_option("--camera", args->camera,
                  "ex,ey,ez,tx,ty,tz[,fov]: eye, target, vertical fov in degrees (default: the "
                  "scene's view, or framing the model's bounds)");
  cmd->add_option("--scene-scale", args->scene_scale, "Multiply the scene's positions and camera by this (units test)");
  add_anisotropy_option(cmd, args->anisotropy);
  cmd->add_option("--out", args->out, "Output image by its extension: PNG (8-bit sRGB) or EXR (linear) for measuring; other formats OpenImageIO writes (TIFF, HDR: linear; JPEG: lossy, not for measuring) also work")->required();
  return [args, cmd] {
    validate(args->technique);
    refuse_options_of_other_techniques(*cmd, args->technique.technique);
    return run_render(*args);
  };
}

}  // namespace rsaa::cli
