// rsaa bench --growth: how each technique's frame time grows with the image size and with the
// triangle count (issue 12, item 5). Times only (no reference images), wall clock as the bench.
#pragma once

#include <string>
#include <vector>

#include "runtime/scene.h"
#include "tools/bench/bench.h"

namespace rsaa::bench {

// Every triangle split into 4 at its edge midpoints, `levels` times (x4^levels triangles). The
// surface, its interpolated attributes and so the image stay the same: only the triangle count
// (and the edges between coplanar triangles inside surfaces) changes.
Scene subdivide(const Scene& scene, int levels);

// `scene` lit by `lights` lights as the bench's --lights: the fixed directional light plus
// lights - 1 point lights on a ring above the scene's centre in view space (of `camera`), their
// total intensity fixed so that more lights cost more but do not brighten the image.
Scene with_lights(const Scene& scene, const Camera& camera, int lights);

struct GrowthOptions {
  std::string scene = "builtin:default";
  std::vector<TechniqueOptions> techniques;  // the first must be noaa
  std::vector<std::pair<int, int>> sizes = {{640, 480}, {1280, 720}, {1920, 1080}, {2560, 1440}};
  std::vector<int> subdivision_levels = {0, 1, 2};  // 1x, 4x, 16x triangles
  int width = 640, height = 480;                    // the size of the triangle and light series
  std::vector<int> light_counts;                     // empty: no light series
  int frames = 3;
  float texture_anisotropy = kDefaultTextureAnisotropy;  // Scene::texture_anisotropy
};

enum class GrowthAxis { Pixels, Triangles, Lights };
const char* to_string(GrowthAxis axis);  // "pixels", "triangles", "lights"

struct GrowthPoint {
  std::string label;
  TechniqueOptions options;
  GrowthAxis axis = GrowthAxis::Pixels;
  int width = 0, height = 0;
  std::size_t triangles = 0;
  int lights = 1;
  double frame_ms = 0.0, copy_ms = 0.0;
  double x() const {
    return axis == GrowthAxis::Pixels ? double(width) * height
           : axis == GrowthAxis::Triangles ? double(triangles) : double(lights);
  }
};

// Least squares over one technique's points on one axis.
struct GrowthSlope {
  std::string label;
  TechniqueOptions options;
  GrowthAxis axis = GrowthAxis::Pixels;
  double exponent = 0.0;  // of log(frame ms) against log(x): 1 = proportional
  // The least-squares line frame ms = intercept + ms_per_unit x, x in megapixels, 100k triangles
  // or lights.
  double ms_per_unit = 0.0, intercept_ms = 0.0;
};

// Where technique `a` becomes cheaper than `b` on the light axis: the first measured light count
// (0 if none), and the N from which a's least-squares line stays below b's (1 if it starts
// below; 0 if b's line does not grow faster, so a is not cheaper for large N).
struct LightCrossing {
  std::string a, b;
  int measured = 0;
  double fitted = 0.0;
};

struct GrowthResults {
  std::string scene;
  std::size_t base_triangles = 0;
  std::vector<GrowthPoint> points;  // technique order within a point; pixels, triangles, lights
};

LightCrossing light_crossing(const GrowthResults& results, const std::string& a, const std::string& b);
// The crossings the report states: RSAA 8x (default options) against MSAA 4x and SSAA 8x, and
// RSAA 4x against MSAA 4x.
std::vector<LightCrossing> light_crossings(const GrowthResults& results);

// Needs a current GL context.
GrowthResults run_growth(const GrowthOptions& options, const Progress& progress);
std::vector<GrowthSlope> growth_slopes(const GrowthResults& results);

std::string growth_json(const GrowthOptions& options, const GrowthResults& results);
std::string growth_csv(const GrowthResults& results);
std::string growth_markdown(const GrowthOptions& options, const GrowthResults& results);
// Log-log frame time against megapixels or triangles, one line per technique, with its exponent.
void plot_growth(const GrowthResults& results, GrowthAxis axis, const std::string& path);

}  // namespace rsaa::bench
