#include "tools/bench/growth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "runtime/gpu_scene.h"
#include "runtime/render.h"
#include "tools/bench/copy_pass.h"

namespace rsaa::bench {
namespace {

SceneVertex midpoint(const SceneVertex& a, const SceneVertex& b) {
  // Not renormalised: the normal stays the linear interpolation the rasteriser would give, so
  // the shading matches the unsplit triangle.
  SceneVertex m;
  m.position = 0.5f * (a.position + b.position);
  m.normal = 0.5f * (a.normal + b.normal);
  m.uv = 0.5f * (a.uv + b.uv);
  m.albedo = 0.5f * (a.albedo + b.albedo);
  m.filter_alpha = 0.5f * (a.filter_alpha + b.filter_alpha);
  return m;
}

// Slope of the least-squares line through (x, y).
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double d = n * sxx - sx * sx;
  return d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

const char* const kMsaaLabel = "msaa 4x";

// The pairs light_crossings() compares (cheaper, than), of the techniques among `labels`: RSAA 8x
// with the defaults against 4x MSAA and 8x SSAA, RSAA 4x against 4x MSAA, and every --table row
// (a union or cell pattern: 8 subsamples from 4x draws) against 4x MSAA.
std::vector<std::pair<std::string, std::string>> crossing_pairs(const std::vector<std::string>& labels) {
  const std::string rsaa8 = technique_label(technique_options("rsaa", 8));
  const std::string rsaa4 = technique_label(technique_options("rsaa", 4));
  std::vector<std::pair<std::string, std::string>> pairs = {{rsaa8, kMsaaLabel}, {rsaa8, "ssaa 8x"}, {rsaa4, kMsaaLabel}};
  for (const std::string& label : labels)
    if (label.rfind("rsaa table ", 0) == 0 &&
        std::find(pairs.begin(), pairs.end(), std::make_pair(label, std::string(kMsaaLabel))) == pairs.end())
      pairs.emplace_back(label, kMsaaLabel);
  return pairs;
}

}  // namespace

Scene subdivide(const Scene& scene, int levels) {
  Scene out = scene;
  for (int level = 0; level < levels; ++level) {
    Scene next = out;
    next.indices.clear();
    next.draws.clear();
    for (const DrawRange& d : out.draws) {
      DrawRange split{std::uint32_t(next.indices.size()), d.index_count * 4, d.texture, d.material};
      for (std::uint32_t i = d.first_index; i < d.first_index + d.index_count; i += 3) {
        const std::uint32_t a = out.indices[i], b = out.indices[i + 1], c = out.indices[i + 2];
        const auto ab = std::uint32_t(next.vertices.size());
        next.vertices.push_back(midpoint(out.vertices[a], out.vertices[b]));
        next.vertices.push_back(midpoint(out.vertices[b], out.vertices[c]));
        next.vertices.push_back(midpoint(out.vertices[c], out.vertices[a]));
        const std::uint32_t bc = ab + 1, ca = ab + 2;
        // Same winding as (a, b, c).
        next.indices.insert(next.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
      }
      next.draws.push_back(split);
    }
    out = std::move(next);
  }
  return out;
}

const char* to_string(GrowthAxis axis) {
  return axis == GrowthAxis::Pixels ? "pixels" : axis == GrowthAxis::Triangles ? "triangles" : "lights";
}

Scene with_lights(const Scene& scene, const Camera& camera, int lights) {
  if (lights < 1 || lights > kMaxScenePointLights + 1)
    throw std::invalid_argument("--lights must be within 1.." + std::to_string(kMaxScenePointLights + 1));
  Scene out = scene;
  out.point_lights.clear();
  const glm::vec3 lo = scene.bounds_min(), hi = scene.bounds_max();
  const glm::vec3 centre = glm::vec3(camera.view() * glm::vec4(0.5f * (lo + hi), 1.0f));
  const float radius = 0.5f * glm::length(hi - lo);
  const int n = lights - 1;
  for (int k = 0; k < n; ++k) {
    // A ring in the view's x-z plane, a little above the centre, alternately warm and cool.
    const float angle = 6.2831853f * (float(k) + 0.5f) / float(n);
    PointLight p;
    p.position = {centre.x + 0.8f * radius * std::cos(angle), centre.y + 0.5f * radius,
                  centre.z + 0.8f * radius * std::sin(angle)};
    p.radius = radius;
    const float intensity = 1.5f / float(n);
    p.colour = k % 2 ? Rgb{0.8f * intensity, 0.9f * intensity, intensity} : Rgb{intensity, 0.9f * intensity, 0.75f * intensity};
    out.point_lights.push_back(p);
  }
  return out;
}

GrowthResults run_growth(const GrowthOptions& o, const Progress& progress) {
  if (o.techniques.empty() || o.techniques.front().technique != "noaa")
    throw std::invalid_argument("bench --growth: the first technique must be noaa");
  if (o.frames < 1) throw std::invalid_argument("bench --growth: --frames must be >= 1");
  for (const auto& [w, h] : o.sizes) validate_size(w, h);
  validate_size(o.width, o.height);
  for (const TechniqueOptions& t : o.techniques) validate(t);
  Scene scene = load_scene_within(o.scene, 120.0);
  scene.texture_anisotropy = o.texture_anisotropy;
  const Camera camera = choose_camera(scene, std::nullopt);
  GrowthResults results;
  results.scene = scene.name;
  results.base_triangles = scene.triangle_count();
  const int total =
      int(o.techniques.size() * (o.sizes.size() + o.subdivision_levels.size() + o.light_counts.size()));
  int done = 0;

  // One (size, scene) point for every technique: the techniques of one point are timed in
  // rounds (time_rounds(): every technique one frame a round), so that a change of load on the
  // shared machine shifts a point, not a technique. At most kRoundSize techniques are made at
  // once (their buffers at 2560x1440: about 2 GB for six); the first group holds the baselines
  // (no AA, 4x MSAA) and the techniques light_crossings() compares (crossing_pairs()), so that
  // those comparisons are paired; further groups, timed after, hold the rest.
  constexpr std::size_t kRoundSize = 6;
  std::vector<std::string> labels;
  for (const TechniqueOptions& t : o.techniques) labels.push_back(technique_label(t));
  std::vector<std::string> compared = {"noaa", kMsaaLabel};  // in this order of priority
  for (const auto& [a, b] : crossing_pairs(labels))
    for (const std::string& label : {a, b})
      if (std::find(compared.begin(), compared.end(), label) == compared.end()) compared.push_back(label);
  std::vector<std::size_t> first_group, rest;
  for (const std::string& label : compared)
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == label && first_group.size() < kRoundSize) first_group.push_back(i);
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (std::find(first_group.begin(), first_group.end(), i) == first_group.end())
      (first_group.size() < kRoundSize ? first_group : rest).push_back(i);
  std::vector<std::vector<std::size_t>> groups = {first_group};
  for (std::size_t k = 0; k < rest.size(); k += kRoundSize)
    groups.emplace_back(rest.begin() + std::ptrdiff_t(k), rest.begin() + std::ptrdiff_t(std::min(rest.size(), k + kRoundSize)));
  const auto measure = [&](const Scene& s, int w, int h, GrowthAxis axis, int lights) {
    const GpuScene gpu(s, needs_facet_colours(o.techniques));
    const gl::Texture output = gl::make_texture_2d(GL_RGBA16F, w, h);
    CopyPass copy(w, h);
    copy.time_ms(output.get());  // warm-up
    const View view = make_view(camera, w, h);
    std::vector<GrowthPoint> points(o.techniques.size());
    for (const std::vector<std::size_t>& group : groups) {
      if (group.empty()) continue;
      if (progress)
        progress(std::string(to_string(axis)) + ": " + std::to_string(w) + "x" + std::to_string(h) + ", " +
                     std::to_string(s.triangle_count()) + " triangles, " + std::to_string(lights) + " lights: " +
                     std::to_string(group.size()) + " techniques in rounds",
                 done, total);
      std::vector<std::unique_ptr<Technique>> techniques;
      std::vector<Technique*> round;
      for (std::size_t i : group) {
        techniques.push_back(make_technique(o.techniques[i], w, h));
        round.push_back(techniques.back().get());
      }
      const std::vector<FrameTiming> timings = time_rounds(round, gpu, view, output.get(), o.frames, copy);
      for (std::size_t k = 0; k < group.size(); ++k) {
        const std::size_t i = group[k];
        GrowthPoint& p = points[i];
        p.label = technique_label(o.techniques[i]);
        p.options = o.techniques[i];
        p.axis = axis;
        p.width = w, p.height = h;
        p.triangles = s.triangle_count();
        p.lights = lights;
        p.frame_ms = timings[k].frame_ms;
        p.copy_ms = timings[k].copy_ms;
        ++done;
      }
    }
    results.points.insert(results.points.end(), points.begin(), points.end());
  };
  for (const auto& [w, h] : o.sizes) measure(scene, w, h, GrowthAxis::Pixels, 1);
  for (int level : o.subdivision_levels)
    measure(subdivide(scene, level), o.width, o.height, GrowthAxis::Triangles, 1);
  for (int lights : o.light_counts)
    measure(with_lights(scene, camera, lights), o.width, o.height, GrowthAxis::Lights, lights);
  if (progress) progress("done", done, total);
  return results;
}

std::vector<GrowthSlope> growth_slopes(const GrowthResults& results) {
  std::vector<GrowthSlope> out;
  for (GrowthAxis axis : {GrowthAxis::Pixels, GrowthAxis::Triangles, GrowthAxis::Lights}) {
    std::vector<std::string> labels;
    for (const GrowthPoint& p : results.points)
      if (p.axis == axis && std::find(labels.begin(), labels.end(), p.label) == labels.end()) labels.push_back(p.label);
    for (const std::string& label : labels) {
      std::vector<double> x, y, log_x, log_y;
      GrowthSlope s;
      for (const GrowthPoint& p : results.points) {
        if (p.axis != axis || p.label != label) continue;
        s.options = p.options;
        x.push_back(p.x() / (axis == GrowthAxis::Pixels ? 1e6 : axis == GrowthAxis::Triangles ? 1e5 : 1.0));
        y.push_back(p.frame_ms);
        log_x.push_back(std::log(p.x()));
        log_y.push_back(std::log(std::max(p.frame_ms, 1e-6)));
      }
      s.label = label;
      s.axis = axis;
      s.exponent = least_squares_slope(log_x, log_y);
      s.ms_per_unit = least_squares_slope(x, y);
      double mean_x = 0, mean_y = 0;
      for (std::size_t i = 0; i < x.size(); ++i) mean_x += x[i] / double(x.size()), mean_y += y[i] / double(y.size());
      s.intercept_ms = mean_y - s.ms_per_unit * mean_x;
      out.push_back(s);
    }
  }
  return out;
}

LightCrossing light_crossing(const GrowthResults& results, const std::string& a, const std::string& b) {
  LightCrossing out{a, b, 0, 0.0};
  std::map<int, std::pair<double, double>> ms;  // lights -> (a, b)
  for (const GrowthPoint& p : results.points) {
    if (p.axis != GrowthAxis::Lights) continue;
    if (p.label == a) ms[p.lights].first = p.frame_ms;
    if (p.label == b) ms[p.lights].second = p.frame_ms;
  }
  for (const auto& [lights, pair] : ms)
    if (pair.first > 0 && pair.second > 0 && pair.first < pair.second) {
      out.measured = lights;
      break;
    }
  const GrowthSlope *sa = nullptr, *sb = nullptr;
  const auto slopes = growth_slopes(results);
  for (const GrowthSlope& s : slopes)
    if (s.axis == GrowthAxis::Lights) {
      if (s.label == a) sa = &s;
      if (s.label == b) sb = &s;
    }
  // a's line below b's from N on: N = 1 if it already is and b grows faster.
  if (sa && sb && sb->ms_per_unit > sa->ms_per_unit) {
    const double n = (sa->intercept_ms - sb->intercept_ms) / (sb->ms_per_unit - sa->ms_per_unit);
    out.fitted = std::max(n, 1.0);
  }
  return out;
}

std::vector<LightCrossing> light_crossings(const GrowthResults& results) {
  const auto measured = [&](const std::string& label) {
    return std::any_of(results.points.begin(), results.points.end(),
                       [&](const GrowthPoint& p) { return p.axis == GrowthAxis::Lights && p.label == label; });
  };
  std::vector<std::string> labels;
  for (const GrowthPoint& p : results.points)
    if (p.axis == GrowthAxis::Lights) labels.push_back(p.label);
  std::vector<LightCrossing> out;
  for (const auto& [a, b] : crossing_pairs(labels))
    if (measured(a) && measured(b)) out.push_back(light_crossing(results, a, b));
  return out;
}

std::string growth_json(const GrowthOptions& o, const GrowthResults& results) {
  nlohmann::json out = {{"format", "rsaa-bench-growth"},
                        {"version", 1},
                        {"scene", results.scene},
                        {"base_triangles", results.base_triangles},
                        {"timed_frames", o.frames},
                        {"triangle_series_size", {o.width, o.height}},
                        {"subdivision", "every triangle split into 4 at its edge midpoints per level"},
                        {"points", nlohmann::json::array()},
                        {"slopes", nlohmann::json::array()}};
  for (const GrowthPoint& p : results.points)
    out["points"].push_back({{"technique", p.label},
                             {"axis", to_string(p.axis)},
                             {"width", p.width},
                             {"height", p.height},
                             {"triangles", p.triangles},
                             {"lights", p.lights},
                             {"frame_ms", p.frame_ms},
                             {"copy_ms", p.copy_ms}});
  for (const GrowthSlope& s : growth_slopes(results))
    out["slopes"].push_back({{"technique", s.label},
                             {"axis", to_string(s.axis)},
                             {"exponent", s.exponent},
                             {s.axis == GrowthAxis::Pixels      ? "ms_per_megapixel"
                              : s.axis == GrowthAxis::Triangles ? "ms_per_100k_triangles"
                                                                : "ms_per_light",
                              s.ms_per_unit},
                             {"intercept_ms", s.intercept_ms}});
  for (const LightCrossing& x : light_crossings(results)) {
    if (o.light_counts.empty()) break;
    out["light_crossings"].push_back({{"cheaper", x.a}, {"than", x.b}, {"first_measured_lights", x.measured},
                                      {"fitted_lights", x.fitted}});
  }
  return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string growth_csv(const GrowthResults& results) {
  std::ostringstream s;
  s << "technique,axis,width,height,triangles,lights,frame_ms,copy_ms\n";
  for (const GrowthPoint& p : results.points)
    s << '"' << p.label << "\"," << to_string(p.axis) << ',' << p.width << ',' << p.height << ',' << p.triangles
      << ',' << p.lights << ',' << p.frame_ms << ',' << p.copy_ms << '\n';
  return s.str();
}

std::string growth_markdown(const GrowthOptions& o, const GrowthResults& results) {
  std::ostringstream s;
  char line[256];
  const auto slopes = growth_slopes(results);
  for (GrowthAxis axis : {GrowthAxis::Pixels, GrowthAxis::Triangles, GrowthAxis::Lights}) {
    std::vector<const GrowthPoint*> first_row;  // the points of this axis, in order
    for (const GrowthPoint& p : results.points)
      if (p.axis == axis && p.label == results.points.front().label) first_row.push_back(&p);
    if (first_row.empty()) continue;
    if (axis == GrowthAxis::Pixels) {
      s << "Frame ms against the image size (" << scene_short_name(results.scene) << ", "
        << results.base_triangles << " triangles, median of " << o.frames
        << " timed frames; exponent = slope of log ms against log pixels, 1 = proportional):\n\n";
      s << "| technique |";
      for (const auto* p : first_row) s << ' ' << p->width << 'x' << p->height << " |";
      s << " exponent | ms per Mpx |\n";
    } else if (axis == GrowthAxis::Triangles) {
      s << "\nFrame ms against the triangle count (" << scene_short_name(results.scene) << " subdivided, " << o.width
        << "x" << o.height << "; exponent = slope of log ms against log triangles):\n\n";
      s << "| technique |";
      for (const auto* p : first_row) s << ' ' << p->triangles << " tris |";
      s << " exponent | ms per 100k tris |\n";
    } else {
      s << "\nFrame ms against the number of lights (" << scene_short_name(results.scene) << ", " << o.width << "x"
        << o.height << "; the fixed light plus N - 1 point lights, shaded where each technique shades):\n\n";
      s << "| technique |";
      for (const auto* p : first_row) s << " N = " << p->lights << " |";
      s << " exponent | ms per light |\n";
    }
    s << "| --- |";
    for (std::size_t i = 0; i < first_row.size() + 2; ++i) s << " --- |";
    s << '\n';
    for (const GrowthSlope& slope : slopes) {
      if (slope.axis != axis) continue;
      s << "| " << slope.label << " |";
      for (const GrowthPoint& p : results.points)
        if (p.axis == axis && p.label == slope.label) {
          std::snprintf(line, sizeof line, " %.1f |", p.frame_ms);
          s << line;
        }
      std::snprintf(line, sizeof line, axis == GrowthAxis::Lights ? " %.2f | %.2f |\n" : " %.2f | %.1f |\n",
                    slope.exponent, slope.ms_per_unit);
      s << line;
    }
    if (axis == GrowthAxis::Lights) {
      s << '\n';
      for (const LightCrossing& x : light_crossings(results)) {
        s << "- " << x.a << " cheaper than " << x.b << ": "
          << (x.measured ? "from N = " + std::to_string(x.measured) + " measured" : std::string("at no measured N"));
        if (x.fitted > 0) {
          std::snprintf(line, sizeof line, "; its least-squares line is below from N = %.1f", x.fitted);
          s << line;
        } else {
          s << "; its least-squares line grows at least as fast, so not for large N";
        }
        s << "\n";
      }
    }
  }
  return s.str();
}

}  // namespace rsaa::bench
