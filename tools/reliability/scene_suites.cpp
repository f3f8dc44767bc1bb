// Scene files, image files and command lines: broken inputs must be refused with an error that
// names them, and whatever loads must be a drawable scene (finite, with triangles).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/util/atomic_file.h"
#include "image/image_io.h"
#include "runtime/scene.h"
#include "tools/reliability/mutate.h"
#include "tools/reliability/suite.h"

namespace rsaa::reliability {
namespace {

namespace fs = std::filesystem;

const std::string kModels = "/usr/share/assimp/models";

Outcome feed_scene(const std::string& path, std::string& detail) {
  try {
    const Scene s = load_scene_within(path, 10.0);
    if (s.triangle_count() == 0) return detail = "loaded without triangles", Outcome::kFailed;
    const glm::vec3 lo = s.bounds_min(), hi = s.bounds_max();
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(lo[k]) || !std::isfinite(hi[k])) return detail = "non-finite bounds", Outcome::kFailed;
    for (std::uint32_t i : s.indices)
      if (i >= s.vertices.size()) return detail = "index out of range", Outcome::kFailed;
    return Outcome::kAccepted;
  } catch (const std::runtime_error& e) {
    detail = e.what();
    return detail.find(path) != std::string::npos ? Outcome::kRejectedClearly : Outcome::kFailed;
  } catch (const std::exception& e) {
    detail = std::string("unexpected exception: ") + e.what();
    return Outcome::kFailed;
  }
}

}  // namespace

SuiteResult scene_corpus(const Options&) {
  const ScratchDir dir;
  const std::string glb = read_whole_file(kModels + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
  const std::string obj = read_whole_file(kModels + "/OBJ/box.obj");
  std::vector<std::pair<std::string, std::string>> corpus = {
      {"empty.obj", ""},
      {"empty.glb", ""},
      {"empty.gltf", ""},
      {"junk.obj", std::string("\x7f\x45\x4c\x46\x02\x01\x01\x00 binary junk \xff\xfe", 30)},
      {"text.gltf", "{ this is not gltf"},
      {"nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"inf.obj", "v 1e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"out-of-range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"},
      {"points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n"},
      {"lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"},
      {"no-faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"ply-header-only.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n"},
      {"ply-cut-in-property-list.ply", read_whole_file(kModels + "/PLY/cube.ply").substr(0, 200)},
      {"unknown.xyz", "whatever"},
      {"missing-bin.gltf", read_whole_file(kModels + "/glTF2/MissingBin/BoxTextured.gltf")},
  };
  for (std::size_t cut : {12, 20, 100, 1000}) corpus.push_back({"truncated-" + std::to_string(cut) + ".glb", glb.substr(0, cut)});
  for (std::size_t cut : {3, 40}) corpus.push_back({"truncated-" + std::to_string(cut) + ".obj", obj.substr(0, cut)});
  SuiteResult r{"scene files: corpus of broken models", 0, 0, 0, 0, {}};
  for (const auto& [name, bytes] : corpus) {
    std::string detail;
    const Outcome o = feed_scene(dir.write(name, bytes), detail);
    r.add(o == Outcome::kAccepted ? Outcome::kFailed : o, name, o == Outcome::kAccepted ? "a broken model loaded" : detail);
  }
  for (const std::string& name : {std::string("/no/such/model.obj"), std::string("builtin:nope"), std::string("/tmp")}) {
    std::string detail;
    r.add(feed_scene(name, detail), name, detail);
  }
  return r;
}

SuiteResult scene_fuzz(const Options& options) {
  const ScratchDir dir;
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"obj", read_whole_file(kModels + "/OBJ/box.obj")},
      {"gltf", read_whole_file(kModels + "/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf")},
      // Formats whose importers crash (segfault or assert) on mutations: the import's child
      // process must turn each crash into a refusal naming the file.
      {"ASE", read_whole_file(kModels + "/ASE/ThreeCubesGreen.ASE")},
      {"off", read_whole_file(kModels + "/OFF/Cube.off")},
      {"3mf", read_whole_file(kModels + "/3MF/box.3mf")},
      {"md5mesh", read_whole_file(kModels + "/MD5/SimpleCube.md5mesh")},
      {"dae", read_whole_file(kModels + "/Collada/ConcavePolygon.dae")},
      {"smd", read_whole_file(kModels + "/SMD/triangle.smd")},
  };
  // PLY is left out: assimp 5.2.4 loops forever on some truncated PLY headers (see the corpus).
  SuiteResult r{"scene files: mutations of OBJ, glTF, ASE, OFF, 3MF, MD5, Collada and SMD models", 0, 0, 0, 0, {}};
  for (std::uint64_t i = 0; i < options.iterations; ++i) {
    const auto& [extension, bytes] = seeds[i % seeds.size()];
    const std::string path = dir.write("mutation-" + std::to_string(i) + "." + extension, mutate(bytes, options.seed, i));
    std::string detail;
    r.add(feed_scene(path, detail), path, detail);
    std::remove(path.c_str());
  }
  return r;
}

SuiteResult image_corpus(const Options& options) {
  const ScratchDir dir;
  Image tiny(4, 3);
  const std::string good_path = dir.write("good.png", "");
  write_image(good_path, tiny);
  const std::string png = read_whole_file(good_path);
  std::vector<std::pair<std::string, std::string>> corpus = {
      {"empty.png", ""}, {"text.png", "not an image"}, {"junk.exr", "\x76\x2f\x31\x01 junk"}};
  for (std::size_t cut : {8, 20, 40}) corpus.push_back({"truncated-" + std::to_string(cut) + ".png", png.substr(0, cut)});
  for (std::uint64_t i = 0; i < options.iterations / 4; ++i)
    corpus.push_back({"mutation-" + std::to_string(i) + ".png", mutate(png, options.seed, i)});
  SuiteResult r{"image files: broken and mutated PNG/EXR", 0, 0, 0, 0, {}};
  for (const auto& [name, bytes] : corpus) {
    const std::string path = dir.write(name, bytes);
    try {
      const DisplayImage d = read_display_image(path);
      const bool ok = d.width > 0 && d.height > 0 && d.rgb.size() == std::size_t(d.width) * d.height * 3;
      r.add(ok ? Outcome::kAccepted : Outcome::kFailed, name, "invalid image accepted");
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      r.add(what.find(path) != std::string::npos ? Outcome::kRejectedClearly : Outcome::kFailed, name, what);
    }
  }
  return r;
}

SuiteResult command_line_corpus(const Options& options) {
  SuiteResult r{"command-line options: bad invocations of rsaa", 0, 0, 0, 0, {}};
  if (options.rsaa_binary.empty()) return r;
  const ScratchDir dir;
  const std::string out = dir.write("placeholder", "");
  std::remove(out.c_str());
  const std::string table = std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json";
  const std::vector<std::string> invocations = {
      "", "nonsense", "train", "train --pattern", "train --pattern d3d8x --cases -5",
      "train --pattern d3d8x --cases 1e3", "train --pattern d3d8x --seed x", "train --pattern d3d8x --threads -1",
      "train --pattern d3d8x --out-dir /dev/null/dir", "train --pattern custom-x --positions '2,2'",
      "eval-table", "eval-table /no/such.json", "eval-table " + table + " --cases 0",
      "render --out", "render --technique rsaa --auth 9 --out " + out, "render --width -3 --out " + out,
      "render --width 1e9 --out " + out, "render --camera ,,,,, --out " + out,
      "render --scene '' --out " + out, "render --threshold nan --technique rsaa --out " + out,
      "compare", "compare a.png", "compare --luma-threshold 2 " + table + " " + table,
  };
  for (const std::string& args : invocations) {
    const RunResult run = run_limited({"/bin/sh", "-c", options.rsaa_binary + " " + args});
    const std::string& output = run.output;
    const bool failed = run.exit_code > 0;
    const bool explained = output.find("error") != std::string::npos || output.find("--") != std::string::npos ||
                           output.find("required") != std::string::npos || output.find("Usage") != std::string::npos;
    const bool no_output = !fs::exists(out);
    if (failed && explained && no_output)
      r.add(Outcome::kRejectedClearly, args, "");
    else
      r.add(Outcome::kFailed, "rsaa " + args, failed ? (no_output ? "no explanation: " + output : "left an output file") : "exit code 0");
  }
  return r;
}

}  // namespace rsaa::reliability
