// rsaa view: a GLFW window that shows one technique at a time, switched with keys, with
// screenshots on request. --keys replays key presses (for scripted runs and tests).
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/util/parallel.h"
#include "core/util/colour.h"
#include "image/image_io.h"
#include "runtime/gl_context.h"
#include "runtime/render.h"
#include "runtime/scene.h"
#include "runtime/scene_renderer.h"
#include "runtime/technique_registry.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/technique_options.h"

namespace rsaa::cli {
namespace {

struct ViewArgs {
  std::string scene = "builtin:default";
  TechniqueOptions technique = technique_options("rsaa", 0);
  int width = 800, height = 600;
  std::string camera;
  std::string screenshot = "rsaa-view-%d.png";
  std::string keys;
  float anisotropy = kDefaultTextureAnisotropy;
};

// The screenshot file name: "%d" is the screenshot's number, "%%" a '%'. Expanded here, never
// by printf: a user's "%n" or "%s" would make printf write or read memory.
std::string screenshot_name(const std::string& pattern, int number) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    const char next = i + 1 < pattern.size() ? pattern[i + 1] : '\0';
    if (next == 'd') {
      out += std::to_string(number);
    } else if (next == '%') {
      out += '%';
    } else {
      throw std::invalid_argument("--screenshot: '" + pattern + "': after '%' only 'd' (the number) or "
                                  "'%' may follow");
    }
    ++i;
  }
  return out;
}

const char* kHelp =
    "keys: 1 noaa, 2 msaa 4x, 3 ssaa 8x, 4 ssaa 16x, 5 ssaa 64x, 6 rsaa 8x, 7 rsaa 4x, 8 dcaa, 9 dyncov,\n"
    "      S/D/G similarity sadp/depth/sadp-plane, A cycle auth 0/1/2, P screenshot, Q or Esc quit\n";

class Viewer {
 public:
  // The scene is uploaded with the facet colours only once a technique needs them (rsaa's
  // defaults draw with facet edges; finding the facets takes seconds on millions of triangles):
  // again, with them, on the first switch to such a technique.
  Viewer(const ViewArgs& args, GLFWwindow* window, const Scene& scene, const Camera& camera)
      : args_(args), window_(window), scene_(scene),
        gpu_scene_(std::make_unique<GpuScene>(scene, needs_facet_colours(args.technique))), camera_(camera),
        options_(args.technique), output_(gl::make_texture_2d(GL_RGBA16F, args.width, args.height)),
        present_(make_fullscreen_program("present.frag", "")) {
    rebuild();
  }

  // Returns false when the key asks to quit.
  bool key(int k) {
    TechniqueOptions o = options_;
    switch (k) {
      case GLFW_KEY_1: o = technique_options("noaa", 0); break;
      case GLFW_KEY_2: o = technique_options("msaa", 4); break;
      case GLFW_KEY_3: o = technique_options("ssaa", 8); break;
      case GLFW_KEY_4: o = technique_options("ssaa", 16); break;
      case GLFW_KEY_5: o = technique_options("ssaa", 64); break;
      case GLFW_KEY_6: o.technique = "rsaa"; o.samples = 8; o.pattern.clear(); break;
      case GLFW_KEY_7: o.technique = "rsaa"; o.samples = 4; break;
      case GLFW_KEY_8: o = technique_options("dcaa", 0); break;
      case GLFW_KEY_9: o = technique_options("dyncov", 0); break;
      case GLFW_KEY_S: o.similarity = "sadp"; break;
      case GLFW_KEY_D: o.similarity = "depth"; break;
      case GLFW_KEY_G: o.similarity = "sadp-plane"; break;
      case GLFW_KEY_A: o.auth = (o.auth + 1) % 3; break;
      case GLFW_KEY_P: screenshot(); return true;
      case GLFW_KEY_Q:
      case GLFW_KEY_ESCAPE: return false;
      default: return true;
    }
    if (o.technique != "rsaa") o.similarity = TechniqueOptions().similarity, o.auth = TechniqueOptions().auth;
    options_ = o;
    rebuild();
    return true;
  }

  void draw() {
    technique_->render(*gpu_scene_, make_view(camera_, args_.width, args_.height), output_.get());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, args_.width, args_.height);
    glUseProgram(present_.get());
    glProgramUniform1i(present_.get(), glGetUniformLocation(present_.get(), "u_image"), 0);
    glBindTextureUnit(0, output_.get());
    draw_fullscreen_triangle();
    gl::check("presenting a frame");
  }

  // Reads the window's back buffer (what is shown) into a PNG.
  void screenshot() {
    draw();
    std::vector<std::uint8_t> rgb(std::size_t(args_.width) * args_.height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, args_.width, args_.height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    Image image(args_.width, args_.height);
    for (int y = 0; y < args_.height; ++y)
      for (int x = 0; x < args_.width; ++x) {
        const std::uint8_t* p = &rgb[(std::size_t(args_.height - 1 - y) * args_.width + x) * 3];
        image.at(x, y) = {srgb_to_linear(p[0] / 255.0f), srgb_to_linear(p[1] / 255.0f),
                          srgb_to_linear(p[2] / 255.0f)};
      }
    const std::string name = screenshot_name(args_.screenshot, ++screenshots_);
    write_image(name, image);
    std::printf("screenshot %s: %s\n", name.c_str(), technique_label(options_).c_str());
    std::fflush(stdout);
  }

 private:
  void rebuild() {
    if (needs_facet_colours(options_) && !gpu_scene_->has_facet_colours()) {
      std::printf("finding the scene's facets for facet edges\n");
      gpu_scene_ = std::make_unique<GpuScene>(scene_, /*with_facet_colours=*/true);
    }
    technique_ = make_technique(options_, args_.width, args_.height);
    const std::string title = "rsaa view: " + technique_label(options_);
    glfwSetWindowTitle(window_, title.c_str());
    std::printf("showing %s\n", technique_label(options_).c_str());
    std::fflush(stdout);
  }

  const ViewArgs& args_;
  GLFWwindow* window_;
  const Scene& scene_;
  std::unique_ptr<GpuScene> gpu_scene_;
  Camera camera_;
  TechniqueOptions options_;
  std::unique_ptr<Technique> technique_;
  gl::Texture output_;
  gl::Program present_;
  int screenshots_ = 0;
};

int key_of(char c) {
  if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
  if (c >= 'a' && c <= 'z') return GLFW_KEY_A + (c - 'a');
  if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
  throw std::invalid_argument(std::string("--keys: no key '") + c + "'");
}

int run_view(const ViewArgs& a) {
  validate(a.technique);
  validate_size(a.width, a.height);
  screenshot_name(a.screenshot, 1);  // refuses a bad pattern before any window opens
  for (char c : a.keys)
    if (c != ' ' && c != ',') key_of(c);
  Scene scene = load_scene_within(a.scene, kSceneLoadSeconds);
  scene.texture_anisotropy = a.anisotropy;
  std::optional<Camera> requested;
  if (!a.camera.empty()) requested = parse_camera(a.camera, scene.bounds_min(), scene.bounds_max());
  fit_llvmpipe_threads_to_process_limit(5);  // see runtime/gl_context.cpp
  if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW (is there a display? try xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(a.width, a.height, "rsaa view", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("cannot open a " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + " OpenGL 4.5 window");
  }
  glfwMakeContextCurrent(window);
  {
    gl::require_gl45();
    std::printf("%s", kHelp);
    Viewer viewer(a, window, scene, choose_camera(scene, requested));
    static std::vector<int> pressed;
    glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int) {
      if (action == GLFW_PRESS) pressed.push_back(key);
    });
    std::vector<int> scripted;
    for (char c : a.keys)
      if (c != ' ' && c != ',') scripted.push_back(key_of(c));
    std::size_t next = 0;
    bool running = true;
    while (running && !glfwWindowShouldClose(window)) {
      viewer.draw();
      glfwSwapBuffers(window);
      glfwPollEvents();
      if (next < scripted.size()) pressed.push_back(scripted[next++]);
      for (int k : pressed) running = running && viewer.key(k);
      pressed.clear();
      if (!a.keys.empty() && next == scripted.size() && running) running = false;  // script done
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace

Action add_view_command(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", std::string("Open a window showing a scene; switch techniques with keys\n") + kHelp);
  cmd->add_option("--scene", args->scene, "builtin:NAME or a model file")->capture_default_str();
  add_technique_options(cmd, args->technique);
  cmd->add_option("--width", args->width, "Window width")->capture_default_str();
  cmd->add_option("--height", args->height, "Window height")->capture_default_str();
  cmd->add_option("--camera", args->camera, "ex,ey,ez,tx,ty,tz[,fov]");
  cmd->add_option("--screenshot", args->screenshot, "Screenshot file pattern: %d = the screenshot's number, %% = '%'")
      ->capture_default_str();
  cmd->add_option("--keys", args->keys,
                  "Press these keys one per frame, then quit (e.g. \"6P2PQ\"); for scripted runs");
  add_anisotropy_option(cmd, args->anisotropy);
  return [args] { return run_view(*args); };
}

}  // namespace rsaa::cli
