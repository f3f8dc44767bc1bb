// The built-in procedural scenes: each stresses one kind of aliasing. Deterministic.
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "runtime/coplanar_draws.h"
#include "runtime/scene.h"

namespace rsaa {
namespace {

constexpr float kPi = 3.14159265358979f;

class MeshBuilder {
 public:
  explicit MeshBuilder(Scene& scene) : scene_(scene) {}

  // The filter alpha of what is added next (ssaa-filtered kernel 3: 0 = soft, large kernel).
  void set_filter_alpha(float alpha) { filter_alpha_ = alpha; }

  // What is added next goes into a new draw of this material (DrawRange::material). Scenes that
  // never call it are one draw of material 0.
  void begin_draw(std::uint32_t material) {
    scene_.draws.push_back({static_cast<std::uint32_t>(scene_.indices.size()), 0, -1, material});
  }

  void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 albedo) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    add({a, n, {0, 0}, albedo}, {b, n, {1, 0}, albedo}, {c, n, {0, 1}, albedo});
  }

  // a, b, c, d counter-clockwise.
  void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 albedo) {
    triangle(a, b, c, albedo);
    triangle(a, c, d, albedo);
  }

  void box(const glm::mat4& transform, glm::vec3 half, glm::vec3 albedo) {
    glm::vec3 p[8];
    for (int i = 0; i < 8; ++i)
      p[i] = glm::vec3(transform * glm::vec4((i & 1 ? 1 : -1) * half.x, (i & 2 ? 1 : -1) * half.y,
                                             (i & 4 ? 1 : -1) * half.z, 1.0f));
    quad(p[0], p[2], p[3], p[1], albedo);  // -z
    quad(p[4], p[5], p[7], p[6], albedo);  // +z
    quad(p[0], p[4], p[6], p[2], albedo);  // -x
    quad(p[1], p[3], p[7], p[5], albedo);  // +x
    quad(p[0], p[1], p[5], p[4], albedo);  // -y
    quad(p[2], p[6], p[7], p[3], albedo);  // +y
  }

  void sphere(glm::vec3 centre, float radius, int rings, int segments, glm::vec3 albedo) {
    const auto point = [&](int r, int s) {
      const float theta = kPi * r / rings, phi = 2 * kPi * s / segments;
      return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int r = 0; r < rings; ++r)
      for (int s = 0; s < segments; ++s) {
        const glm::vec3 n00 = point(r, s), n01 = point(r, s + 1), n10 = point(r + 1, s),
                        n11 = point(r + 1, s + 1);
        const auto v = [&](glm::vec3 n) { return SceneVertex{centre + radius * n, n, {0, 0}, albedo}; };
        if (r > 0) add(v(n00), v(n01), v(n11));
        if (r + 1 < rings) add(v(n00), v(n11), v(n10));
      }
  }

  // A thin cylinder from a to b (wires, fence posts).
  void cylinder(glm::vec3 a, glm::vec3 b, float radius, int segments, glm::vec3 albedo) {
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), w = glm::cross(axis, u);
    for (int s = 0; s < segments; ++s) {
      const float p0 = 2 * kPi * s / segments, p1 = 2 * kPi * (s + 1) / segments;
      const glm::vec3 n0 = std::cos(p0) * u + std::sin(p0) * w, n1 = std::cos(p1) * u + std::sin(p1) * w;
      const SceneVertex a0{a + radius * n0, n0, {0, 0}, albedo}, a1{a + radius * n1, n1, {0, 0}, albedo};
      const SceneVertex b0{b + radius * n0, n0, {0, 0}, albedo}, b1{b + radius * n1, n1, {0, 0}, albedo};
      add(a0, b0, b1);
      add(a0, b1, a1);
    }
  }

  void checkerboard(float half_size, int cells, float y, glm::vec3 c0, glm::vec3 c1) {
    const float step = 2 * half_size / cells;
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        const float x0 = -half_size + i * step, z0 = -half_size + j * step;
        quad({x0, y, z0}, {x0, y, z0 + step}, {x0 + step, y, z0 + step}, {x0 + step, y, z0},
             (i + j) % 2 ? c1 : c0);
      }
  }

 private:
  void add(SceneVertex a, SceneVertex b, SceneVertex c) {
    const auto base = static_cast<std::uint32_t>(scene_.vertices.size());
    a.filter_alpha = b.filter_alpha = c.filter_alpha = filter_alpha_;
    scene_.vertices.insert(scene_.vertices.end(), {a, b, c});
    scene_.indices.insert(scene_.indices.end(), {base, base + 1, base + 2});
    if (!scene_.draws.empty()) scene_.draws.back().index_count += 3;
  }
  Scene& scene_;
  float filter_alpha_ = 1.0f;
};

Camera look(glm::vec3 eye, glm::vec3 target, float fov, float near_plane, float far_plane) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.fov_y_degrees = fov;
  c.near_plane = near_plane;
  c.far_plane = far_plane;
  return c;
}

const glm::vec3 kWhite{0.85f}, kBlack{0.02f}, kRed{0.8f, 0.08f, 0.05f}, kBlue{0.06f, 0.15f, 0.75f},
    kGreen{0.1f, 0.6f, 0.12f}, kYellow{0.85f, 0.7f, 0.1f}, kGrey{0.35f};

// A fan of thin white triangles (spokes) standing `lift` in front of a black disc: a Siemens
// star whose edges are geometric.
void siemens_star(MeshBuilder& m, glm::vec3 centre, float radius, int spokes, float lift) {
  for (int k = 0; k < 2 * spokes; ++k) {
    const float a0 = 2 * kPi * k / (2 * spokes), a1 = 2 * kPi * (k + 1) / (2 * spokes);
    const glm::vec3 z(0, 0, k % 2 ? 0.0f : lift);
    m.triangle(centre + z, centre + z + radius * glm::vec3(std::cos(a0), std::sin(a0), 0),
               centre + z + radius * glm::vec3(std::cos(a1), std::sin(a1), 0), k % 2 ? kBlack : kWhite);
  }
}

Scene showcase() {
  Scene s;
  MeshBuilder m(s);
  // Checker tiles whose colour edges are also geometric edges (every other tile is raised),
  // as material boundaries usually are in real scenes: RSAA sees geometry only.
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      const bool light = (i + j) % 2 == 0;
      const float top = light ? 0.04f : 0.0f;
      m.box(glm::translate(glm::mat4(1), {-5.5f + i, top / 2 - 0.05f, -5.5f + j}),
            {0.5f, top / 2 + 0.05f, 0.5f}, light ? glm::vec3(0.7f, 0.7f, 0.65f) : glm::vec3(0.12f, 0.12f, 0.14f));
    }
  m.sphere({-1.8f, 1.0f, 0.3f}, 1.0f, 24, 48, kRed);
  m.box(glm::rotate(glm::translate(glm::mat4(1), {1.6f, 0.8f, -0.2f}), 0.6f, glm::vec3(0, 1, 0)),
        {0.8f, 0.8f, 0.8f}, kBlue);
  for (int i = 0; i < 7; ++i) {  // a wire fence behind
    const float x = -4.5f + 1.5f * i;
    m.cylinder({x, 0, -3.0f}, {x, 2.6f, -3.0f}, 0.05f, 8, kGrey);
  }
  m.set_filter_alpha(0.0f);  // the wires are soft for ssaa-filtered --kernel 3
  for (int j = 0; j < 4; ++j)
    m.cylinder({-4.6f, 0.5f + 0.6f * j, -3.0f}, {4.6f, 0.8f + 0.6f * j, -3.0f}, 0.03f, 6, kWhite);
  m.set_filter_alpha(1.0f);
  siemens_star(m, {0.0f, 2.9f, -2.9f}, 0.9f, 18, 0.05f);
  s.camera = look({0.3f, 2.6f, 7.0f}, {0.0f, 1.0f, -0.5f}, 45.0f, 0.5f, 40.0f);
  return s;
}

Scene fence() {
  Scene s;
  MeshBuilder m(s);
  m.quad({-6, -1, -4}, {6, -1, -4}, {6, 5, -4}, {-6, 5, -4}, {0.3f, 0.45f, 0.6f});
  m.set_filter_alpha(0.0f);  // soft wires for ssaa-filtered --kernel 3
  for (int i = 0; i <= 24; ++i) {
    const float x = -4.0f + 8.0f * i / 24;
    m.cylinder({x - 0.3f, -0.5f, 0}, {x + 0.3f, 4.5f, 0}, 0.015f, 6, kYellow);
    m.cylinder({x + 0.3f, -0.5f, 0}, {x - 0.3f, 4.5f, 0}, 0.015f, 6, kYellow);
  }
  s.camera = look({0.5f, 2.0f, 6.0f}, {0.0f, 2.0f, 0.0f}, 50.0f, 0.5f, 30.0f);
  return s;
}

Scene star() {
  Scene s;
  MeshBuilder m(s);
  m.quad({-3, -3, -0.5f}, {3, -3, -0.5f}, {3, 3, -0.5f}, {-3, 3, -0.5f}, kGrey);
  siemens_star(m, {0, 0, 0}, 2.4f, 36, 0.1f);
  s.camera = look({0, 0, 6.5f}, {0, 0, 0}, 45.0f, 1.0f, 20.0f);
  return s;
}

Scene edges() {
  // Large quads whose edges run at near-horizontal, near-vertical and diagonal angles.
  Scene s;
  MeshBuilder m(s);
  const float angles[] = {0.5f, 2.0f, 10.0f, 45.0f, 80.0f, 88.0f, 89.5f};
  const glm::vec3 colours[] = {kWhite, kRed, kGreen, kYellow, kBlue, kWhite, kRed};
  for (int i = 0; i < 7; ++i) {
    const glm::mat4 t = glm::rotate(glm::translate(glm::mat4(1), {-3.0f + i, 0.0f, 0.01f * i}),
                                    glm::radians(angles[i]), glm::vec3(0, 0, 1));
    const auto p = [&](float x, float y) { return glm::vec3(t * glm::vec4(x, y, 0, 1)); };
    m.quad(p(-0.4f, -2.2f), p(0.4f, -2.2f), p(0.4f, 2.2f), p(-0.4f, 2.2f), colours[i]);
  }
  s.camera = look({0, 0, 7.0f}, {0, 0, 0}, 50.0f, 1.0f, 20.0f);
  return s;
}

Scene distant() {
  // Many small boxes far away: sub-pixel geometry.
  Scene s;
  MeshBuilder m(s);
  m.checkerboard(40.0f, 8, -1.0f, {0.5f, 0.5f, 0.45f}, {0.2f, 0.25f, 0.2f});
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 30; ++i) {
      const float x = -15.0f + i, z = -15.0f - 1.5f * j;
      const float angle = 0.37f * float((i * 7 + j * 13) % 17);
      m.box(glm::rotate(glm::translate(glm::mat4(1), {x, -0.7f, z}), angle, glm::vec3(0, 1, 0)),
            {0.12f, 0.3f, 0.12f}, (i + j) % 3 == 0 ? kRed : (i + j) % 3 == 1 ? kWhite : kBlue);
    }
  s.camera = look({0, 1.5f, 12.0f}, {0, -0.5f, -20.0f}, 40.0f, 1.0f, 120.0f);
  return s;
}

Scene interpenetrating() {
  // Surfaces that cross at shallow angles: depth alone separates them poorly.
  Scene s;
  MeshBuilder m(s);
  const glm::mat4 tilt = glm::rotate(glm::mat4(1), glm::radians(6.0f), glm::vec3(1, 0, 0));
  m.quad({-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {0.75f, 0.7f, 0.6f});
  const auto p = [&](float x, float z) { return glm::vec3(tilt * glm::vec4(x, 0.0f, z, 1)); };
  m.quad(p(-3, -4), p(-3, 4), p(3, 4), p(3, -4), kBlue);
  m.sphere({-1.5f, 0.2f, 1.0f}, 0.8f, 20, 40, kRed);
  m.box(glm::rotate(glm::translate(glm::mat4(1), {1.6f, 0.1f, 0.5f}), 0.5f, glm::vec3(1, 1, 0)),
        {0.6f, 0.6f, 0.6f}, kGreen);
  s.camera = look({0.5f, 2.2f, 6.5f}, {0, 0.2f, 0}, 45.0f, 0.5f, 30.0f);
  return s;
}

Scene grazing() {
  // Objects resting on a large plain floor seen from a low camera: most of the floor lies under
  // 15 degrees of elevation, so a silhouette over it has both surfaces nearly edge-on along the
  // view ray (where SADP alone finds no edge). The floor is one colour: its edges are the objects'.
  Scene s;
  MeshBuilder m(s);
  m.quad({-40, 0, -60}, {-40, 0, 20}, {40, 0, 20}, {40, 0, -60}, {0.7f, 0.66f, 0.55f});
  m.sphere({-1.6f, 0.7f, 0.0f}, 0.7f, 24, 48, kRed);
  m.sphere({1.2f, 0.45f, -3.0f}, 0.45f, 20, 40, kGreen);
  m.sphere({-0.6f, 0.3f, -7.0f}, 0.3f, 16, 32, kYellow);
  m.box(glm::rotate(glm::translate(glm::mat4(1), {1.4f, 0.5f, 1.2f}), 0.5f, glm::vec3(0, 1, 0)),
        {0.5f, 0.5f, 0.5f}, kBlue);
  m.box(glm::rotate(glm::translate(glm::mat4(1), {-3.2f, 0.25f, -4.5f}), 0.3f, glm::vec3(0, 1, 0)),
        {1.2f, 0.25f, 0.4f}, kGrey);
  m.cylinder({2.8f, 0.0f, -1.5f}, {2.8f, 1.6f, -1.5f}, 0.25f, 24, kWhite);
  m.cylinder({-4.0f, 0.15f, -0.5f}, {-1.0f, 0.15f, 2.5f}, 0.15f, 16, kGreen);  // a log lying down
  s.camera = look({0.0f, 0.75f, 5.5f}, {0.0f, 0.35f, -4.0f}, 45.0f, 0.3f, 100.0f);
  return s;
}

Scene coplanar() {
  // Colour edges with no geometric edge: a floor of tiles, a wall of painted bands with a window
  // set flush, a roof of boards; each colour its own material (draw), neighbours coplanar and
  // sharing their edges exactly. Only a material test (RsaaSettings::material_edges) sees them.
  Scene s;
  MeshBuilder m(s);
  const glm::vec3 kCream{0.8f, 0.75f, 0.6f}, kBrown{0.35f, 0.2f, 0.1f}, kTile{0.55f, 0.5f, 0.45f};
  // Floor: 8 x 8 tiles, two materials.
  for (int colour = 0; colour < 2; ++colour) {
    m.begin_draw(std::uint32_t(colour));
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i)
        if ((i + j) % 2 == colour) {
          const float x0 = -4.0f + i, z0 = -4.0f + j;
          m.quad({x0, 0, z0}, {x0, 0, z0 + 1}, {x0 + 1, 0, z0 + 1}, {x0 + 1, 0, z0}, colour ? kTile : kWhite);
        }
  }
  // Wall, turned 20 degrees about the vertical: six bands of two materials, a window in band 2-3.
  const glm::mat4 wall = glm::rotate(glm::translate(glm::mat4(1), {-0.5f, 0.0f, -3.0f}), glm::radians(20.0f),
                                     glm::vec3(0, 1, 0));
  const auto w = [&](float x, float y) { return glm::vec3(wall * glm::vec4(x, y, 0.0f, 1.0f)); };
  const auto panel = [&](float x0, float y0, float x1, float y1, glm::vec3 albedo) {
    m.quad(w(x0, y0), w(x1, y0), w(x1, y1), w(x0, y1), albedo);
  };
  for (int colour = 0; colour < 2; ++colour) {
    m.begin_draw(2 + std::uint32_t(colour));
    for (int band = colour; band < 6; band += 2) {
      const float y0 = 0.5f * band, y1 = y0 + 0.5f;
      if (band == 2 || band == 3) {  // around the window, x in [-0.6, 0.6]
        panel(-3.0f, y0, -0.6f, y1, colour ? kCream : kRed);
        panel(0.6f, y0, 3.0f, y1, colour ? kCream : kRed);
      } else {
        panel(-3.0f, y0, 3.0f, y1, colour ? kCream : kRed);
      }
    }
  }
  m.begin_draw(4);  // in two halves: every vertex of the bands beside it is one of its own
  panel(-0.6f, 1.0f, 0.6f, 1.5f, kBlue);
  panel(-0.6f, 1.5f, 0.6f, 2.0f, kBlue);
  // Roof on the right, sloping 35 degrees towards the camera: boards of two materials.
  const glm::mat4 roof = glm::rotate(glm::translate(glm::mat4(1), {2.2f, 1.2f, 0.3f}), glm::radians(35.0f),
                                     glm::vec3(1, 0, 0));
  const auto r = [&](float x, float z) { return glm::vec3(roof * glm::vec4(x, 0.0f, z, 1.0f)); };
  for (int colour = 0; colour < 2; ++colour) {
    m.begin_draw(5 + std::uint32_t(colour));
    for (int board = colour; board < 10; board += 2) {
      const float x0 = -1.5f + 0.3f * board, x1 = -1.5f + 0.3f * (board + 1);  // as the next board's x0
      m.quad(r(x0, -1.2f), r(x0, 1.2f), r(x1, 1.2f), r(x1, -1.2f), colour ? kBrown : kYellow);
    }
  }
  s.camera = look({-0.5f, 3.4f, 7.0f}, {0.5f, 0.8f, -1.0f}, 45.0f, 0.5f, 40.0f);
  return s;
}

const std::map<std::string, std::function<Scene()>>& generators() {
  static const std::map<std::string, std::function<Scene()>> g = {
      {"default", showcase}, {"fence", fence},     {"star", star},
      {"edges", edges},      {"distant", distant}, {"interpenetrating", interpenetrating},
      {"grazing", grazing},  {"coplanar", coplanar},
  };
  return g;
}

}  // namespace

const std::vector<std::string>& builtin_scene_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, make] : generators()) n.push_back(name);
    return n;
  }();
  return names;
}

Scene builtin_scene(const std::string& name) {
  const auto it = generators().find(name);
  if (it == generators().end()) {
    std::string known;
    for (const auto& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::runtime_error("unknown built-in scene 'builtin:" + name + "' (known: " + known + ")");
  }
  Scene s = it->second();
  s.name = "builtin:" + name;
  if (s.draws.empty()) s.draws = {{0, static_cast<std::uint32_t>(s.indices.size()), -1}};
  rank_coplanar_draws(s);
  return s;
}

}  // namespace rsaa
