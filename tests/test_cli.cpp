// The rsaa command line as a user runs it: outputs, determinism, and errors on bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/rsaa/sample_pattern.h"
#include "runtime/camera.h"
#include "runtime/rsaa_pass.h"
#include "tests/test_util.h"

namespace rsaa {
namespace {

using test::run_rsaa;
using test::TempDir;

std::size_t file_count(const std::string& dir) {
  return std::distance(std::filesystem::directory_iterator(dir),
                       std::filesystem::directory_iterator());
}

TEST(Cli, HelpExitsZero) {
  EXPECT_EQ(run_rsaa("--help").exit_code, 0);
  const auto r = run_rsaa("train --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--two-line-weight"), std::string::npos);
  EXPECT_NE(run_rsaa("").exit_code, 0);
  EXPECT_NE(run_rsaa("frobnicate").exit_code, 0);
  const auto version = run_rsaa("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("rsaa 0."), std::string::npos) << version.output;
}

TEST(Cli, TrainIsByteIdenticalAcrossThreadCounts) {
  TempDir a, b;
  const std::string common = "train --pattern d3d8x --cases 20000 --seed 9 --quiet ";
  const auto ra = run_rsaa(common + "--threads 1 --out-dir " + a.path());
  const auto rb = run_rsaa(common + "--threads 2 --out-dir " + b.path());
  ASSERT_EQ(ra.exit_code, 0) << ra.output;
  ASSERT_EQ(rb.exit_code, 0) << rb.output;
  EXPECT_NE(ra.output.find("explained by one line"), std::string::npos) << ra.output;
  for (const char* ext : {".json", ".glsl", ".hlsl"}) {
    const std::string fa = test::read_text(a.file(std::string("d3d8x") + ext));
    EXPECT_FALSE(fa.empty());
    EXPECT_TRUE(fa == test::read_text(b.file(std::string("d3d8x") + ext))) << ext;
  }
}

TEST(Cli, TrainRejectsBadOptionsWithoutWritingAnything) {
  TempDir dir;
  std::string seventeen_pairs;
  for (int i = 0; i < 17; ++i)
    seventeen_pairs += std::to_string(i % 4 * 0.125 - 0.2) + "," + std::to_string(i / 4 * 0.1 - 0.2) + " ";
  const std::string out = " --out-dir " + dir.path();
  struct Bad {
    std::string args, message;
  };
  for (const Bad& bad : std::vector<Bad>{
           {"train --pattern nope --cases 10", "unknown sample pattern 'nope'"},
           {"train --pattern d3d8x --cases 0", "--cases"},
           {"train --pattern d3d8x --cases ten", "--cases"},
           {"train --pattern d3d8x --two-line-weight 2", "--two-line-weight"},
           {"train --pattern d3d8x --fit best", "--fit"},
           {"train --pattern custom-a --positions '0.1,0.2 0.9,0'", "sample 1"},
           {"train --pattern custom-a --positions '0.1;0.2'", "not an x,y pair"},
           // More pairs than a table holds printed the run's header first; none said 1 to 64.
           {"train --pattern custom-a --positions '" + seventeen_pairs + "'", "17 x,y pairs; tables allow 1 to 16"},
           {"train --pattern custom-a --positions ' '", "0 x,y pairs; tables allow 1 to 16"},
           // Read as 0 and as a denormal number.
           {"train --pattern custom-a --positions '1e-400,0.1'", "sample 0 ('1e-400,0.1'): '1e-400' is too small"},
           {"train --pattern custom-a --positions '0.1,-1e-310'", "sample 0 ('0.1,-1e-310'): '-1e-310' is too small"},
       }) {
    const auto r = run_rsaa(bad.args + out);
    EXPECT_NE(r.exit_code, 0) << bad.args;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << bad.args << "\n" << r.output;
    EXPECT_EQ(r.output.find("rsaa train: pattern"), std::string::npos) << bad.args << "\n" << r.output;
  }
  EXPECT_EQ(file_count(dir.path()), 0u);
  // A missing --out-dir is created; one that cannot be is refused, named.
  const auto r = run_rsaa("train --pattern d3d4x --cases 10 --out-dir /dev/null/dir");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/dev/null/dir"), std::string::npos) << r.output;
}

TEST(Cli, TrainAcceptsPositions) {
  TempDir dir;
  const auto r = run_rsaa("train --pattern custom-diag --positions '-0.25,-0.25 0.25,0.25' "
                          "--cases 2000 --quiet --out-dir " + dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(run_rsaa("eval-table --cases 2000 " + dir.file("custom-diag.json")).exit_code, 0);
}

// --cells trains the cell pattern of a pattern (here the driver's 4x, as the checked-in cell
// tables were): the checked-in tables again, byte for byte; bad cell counts are refused before
// anything is written.
TEST(Cli, TrainCellsOfTheDriversPatternMakesTheCheckedInTables) {
  TempDir dir;
  for (const auto& [cells, stem] : {std::pair{"1x2", "custom-gl4x-tall"}, std::pair{"2x1", "custom-gl4x-wide"}}) {
    const auto r = run_rsaa(std::string("train --pattern gl4x --cells ") + cells + " --quiet --out-dir " + dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* ext : {".json", ".glsl", ".hlsl"})
      EXPECT_TRUE(test::read_text(dir.file(std::string(stem) + ext)) ==
                  test::read_text(std::string(RSAA_SOURCE_DIR) + "/tables/" + stem + ext))
          << stem << ext << " differs from the checked-in file";
  }
  for (const auto& [args, message] :
       {std::pair{"--pattern gl4x --cells 0x2", "is not COLUMNSxROWS"}, std::pair{"--pattern gl4x --cells 12x1", "is not COLUMNSxROWS"},
        std::pair{"--pattern gl4x --cells 1x1", "more than one cell"},
        std::pair{"--pattern d3d16x --cells 2x1", "tables hold at most 16"},
        std::pair{"--from-scene builtin:edges --cells 1x2", "--cells trains a pattern's table"}}) {
    const auto r = run_rsaa(std::string("train ") + args + " --out-dir " + dir.file("refused"));
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("refused"))) << args;
  }
}

TEST(Cli, EvalTableJsonAndErrors) {
  TempDir dir;
  ASSERT_EQ(run_rsaa("train --pattern d3d4x --cases 4000 --quiet --out-dir " + dir.path()).exit_code, 0);
  const auto r = run_rsaa("eval-table --cases 4000 --seed 3 --json " + dir.file("d3d4x.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j.at("cases"), 4000);
  EXPECT_LT(j.at("results").at("mix").at("table").at("rms").get<double>(),
            j.at("results").at("mix").at("zero_offset").at("rms").get<double>());

  const std::string good = test::read_text(dir.file("d3d4x.json"));
  test::write_text(dir.file("truncated.json"), good.substr(0, good.size() - 40));
  test::write_text(dir.file("empty.json"), "");
  std::string nan = good;
  nan.replace(nan.find("\"offsets\": [\n    [") + 18, 1, "NaN, 0");
  test::write_text(dir.file("nan.json"), nan);
  // A hand-edited training object nested 3000 deep (without the set id, which no longer matches):
  // --json echoed it indented, megabytes from a 6 KB table (100,000 deep: 8 GB and a crash).
  std::string deep = good;
  const std::size_t set_id = deep.find("  \"set_id\"");
  ASSERT_NE(set_id, std::string::npos);
  deep.erase(set_id, deep.find('\n', set_id) + 1 - set_id);
  deep.replace(deep.find("\"training\": {") + 12, 1, "{\"x\": " + std::string(3000, '[') + std::string(3000, ']') + ", ");
  test::write_text(dir.file("deep.json"), deep);
  for (const std::string name : {"truncated.json", "empty.json", "nan.json", "missing.json", "deep.json"}) {
    const auto e = run_rsaa("eval-table --cases 1000 --json " + dir.file(name));
    EXPECT_NE(e.exit_code, 0) << name;
    EXPECT_NE(e.output.find(dir.file(name)), std::string::npos) << e.output.substr(0, 1000);
    EXPECT_EQ(e.output.find("terminate"), std::string::npos) << e.output.substr(0, 1000);
  }
  EXPECT_NE(run_rsaa("eval-table " + dir.file("deep.json")).output.find("deep.json: training: expected an object of at most"),
            std::string::npos);
}


// Found by an adversarial review of the command line: each was accepted, or cost gigabytes, or
// wrote a non-number where a number goes.
TEST(Cli, HostileOptionsAreRefusedWithAReason) {
  TempDir dir;
  // 2^32 fresh cases keep 400 GiB of errors: refused at once, not killed by the kernel later.
  auto r = run_rsaa("eval-table --cases 4294967296 " + std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("needs about 400.0 GiB"), std::string::npos) << r.output;
  // Under ulimit -v the address space runs out first: refused at once, not after generating
  // every case (4 * 10^7 cases under 4 GB: 43 s, then "out of memory").
  r = test::run_command("ulimit -v 600000 && " + std::string(RSAA_BINARY) + " eval-table --cases 6000000 --threads 2 " +
                        std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("the address-space limit (ulimit -v) leaves"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("generating"), std::string::npos) << r.output;
  // A split cap that rounds to the paper's 0 or to 1 as a float.
  for (const char* cap : {"1e-320", "0.9999999999"}) {
    r = run_rsaa("shaders --split-cap " + std::string(cap) + " --out-dir " + dir.file(cap));
    EXPECT_NE(r.exit_code, 0) << cap;
    EXPECT_FALSE(std::filesystem::exists(dir.file(cap) + "/rsaa_post.frag")) << cap;
  }
  // A unit past what every GL 4.5 driver has.
  r = run_rsaa("shaders --first-unit 1000 --out-dir " + dir.file("units"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--first-unit"), std::string::npos) << r.output;
  // A driver pattern's name with another count of positions.
  r = run_rsaa("train --pattern gl8x --positions \"0.1,0.1 0.2,-0.2 -0.3,0.3 -0.1,-0.4\" --cases 100 --out-dir " +
               dir.file("gl8x"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("gl8x has 8"), std::string::npos) << r.output;
  // --samples 0 stood for "not given": ssaa rendered 64 samples, noaa took it.
  r = run_rsaa("render --technique noaa --samples 0 --width 8 --height 8 --out " + dir.file("a.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--samples"), std::string::npos) << r.output;
  // An option of another technique, and a bench whose scenes would write the same files.
  r = run_rsaa("render --technique noaa --pattern d3d4x --width 8 --height 8 --out " + dir.file("b.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--pattern is an rsaa option"), std::string::npos) << r.output;
  r = run_rsaa("bench --quick --scenes builtin:edges,builtin:edges --out-dir " + dir.file("twice"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("would both write pareto-edges.png"), std::string::npos) << r.output;
  r = run_rsaa("train --pattern custom-a --out-dir " + dir.file("custom"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("needs --positions"), std::string::npos) << r.output;
  // A chart over its own data.
  test::write_text(dir.file("data.png"), "x,y\n1,2\n2,3\n");
  r = run_rsaa("plot " + dir.file("data.png") + " --x x --y y --out " + dir.file("data.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("is the CSV file itself"), std::string::npos) << r.output;
  EXPECT_EQ(test::read_text(dir.file("data.png")), "x,y\n1,2\n2,3\n");
}

// The recorded command line makes the same files again: options equal to a default were left out,
// so --split-cap 0 became the default cap when run again.
TEST(Cli, ShadersRecordACommandThatMakesThemAgain) {
  TempDir dir;
  const std::string first = dir.file("first"), again = dir.file("again");
  auto r = run_rsaa("shaders --split-cap 0 --fetch-check off --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string post = test::read_text(first + "/rsaa_post.frag");
  const std::string marker = "// Generated by: rsaa ";
  const std::size_t at = post.find(marker);
  ASSERT_NE(at, std::string::npos);
  const std::string command = post.substr(at + marker.size(), post.find('\n', at) - at - marker.size());
  EXPECT_NE(command.find("--split-cap 0"), std::string::npos) << command;
  r = run_rsaa(command.substr(0, command.find("--out-dir")) + " --out-dir " + again);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"rsaa_post.frag", "rsaa_prepass.glsl", "rsaa_post.hlsl"})
    EXPECT_EQ(test::read_text(first + "/" + file), test::read_text(again + "/" + file)) << file;
}

// An option given is never dropped without a word: an empty value, a measuring option beside
// --from-json (the file's run is redrawn as it was), --growth with --from-json, and --quick's
// sizes where the user gave their own.
TEST(Cli, GivenBenchAndFiguresOptionsAreNeverIgnored) {
  TempDir dir;
  struct Refused {
    std::string args, message;
  };
  int runs = 0;
  for (const Refused& bad : std::vector<Refused>{
           {"bench --techniques ''", "--techniques: an empty value names nothing"},
           {"bench --lights ''", "--lights: an empty value names nothing"},
           {"figures --scenes ''", "--scenes: an empty value names nothing"},
           {"bench --from-json " + dir.file("b.json") + " --width 100", "--width belongs to a measurement"},
           {"bench --from-json " + dir.file("b.json") + " --scenes builtin:edges", "--scenes belongs to a measurement"},
           {"bench --growth --from-json " + dir.file("b.json"), "--growth belongs to a measurement"},
           {"bench --from-json " + dir.file("b.json") + " --anisotropy 4", "--anisotropy belongs to a measurement"},
           {"bench --anisotropy 0", "--anisotropy: '0' is not a finite number within [1, 16]"},
           // Refused after the directory was made (found as the scene loads), or once it was.
           {"bench --lights 66", "--lights: '66' is not a light count within 1..65"},
           {"bench --quick --scenes builtin:nonexistent", "unknown built-in scene 'builtin:nonexistent'"},
           {"train --from-scene builtin:nonexistent", "unknown built-in scene 'builtin:nonexistent'"},
       }) {
    const std::string out = dir.file("out" + std::to_string(++runs));
    const auto r = run_rsaa(bad.args + " --out-dir " + out + "/inner");
    EXPECT_NE(r.exit_code, 0) << bad.args;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << bad.args << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << bad.args;
  }
  // A directory that was there stays, with what it held.
  std::filesystem::create_directories(dir.file("mine/empty"));
  EXPECT_NE(run_rsaa("bench --quick --scenes builtin:nonexistent --out-dir " + dir.file("mine/empty/new")).exit_code, 0);
  EXPECT_TRUE(std::filesystem::exists(dir.file("mine/empty")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("mine/empty/new")));
  const auto anisotropy = run_rsaa("view --anisotropy 17");
  EXPECT_NE(anisotropy.exit_code, 0);
  EXPECT_NE(anisotropy.output.find("--anisotropy: '17' is not a finite number within [1, 16]"), std::string::npos)
      << anisotropy.output;
  const auto keys = run_rsaa("view --keys ''");
  EXPECT_NE(keys.exit_code, 0);
  EXPECT_NE(keys.output.find("--keys: an empty value names nothing"), std::string::npos) << keys.output;
  const auto r = run_rsaa("figures --quick --figure memory --width 40 --height 30 --out-dir " + dir.file("figures"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("at 40x30"), std::string::npos) << "--quick kept the given size:\n" << r.output;
}

// A bench report is a set (JSON, CSV, Markdown, plots): a run that fails while writing it leaves
// the directory's previous report as it was, never new files beside old ones.
TEST(Cli, ABenchReportIsWrittenWholeOrNotAtAll) {
  TempDir dir;
  const std::string first = dir.file("first");
  auto r = run_rsaa("bench --quick --scenes builtin:edges --techniques noaa,fxaa --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"bench.json", "bench.csv", "report.md", "pareto-edges.png", "passes-edges.png"}) {
    EXPECT_TRUE(std::filesystem::exists(first + "/" + file)) << file;
    EXPECT_NE(r.output.find(file), std::string::npos) << "the files written are named: " << file;
  }
  // A previous report, then a redraw from the JSON whose plot cannot replace its file (a
  // directory stands there): the commit fails, and every previous file is as it was.
  const std::string second = dir.file("second");
  std::filesystem::create_directories(second + "/passes-edges.png");
  for (const char* file : {"report.md", "pareto-edges.png"}) test::write_text(second + "/" + file, "previous");
  r = run_rsaa("bench --from-json " + first + "/bench.json --out-dir " + second);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("passes-edges.png"), std::string::npos) << "the error names the file: " << r.output;
  for (const char* file : {"report.md", "pareto-edges.png"}) EXPECT_EQ(test::read_text(second + "/" + file), "previous");
  for (const auto& entry : std::filesystem::directory_iterator(second)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "report.md" || name == "pareto-edges.png" || name == "passes-edges.png") << "left behind: " << name;
  }
  // A new report replaces the previous one whole: redrawn over the measured run with another
  // scene, the measured run's crops and plots go, its data is the redrawn run's, and a file the
  // reports never wrote stays.
  nlohmann::json moved = nlohmann::json::parse(test::read_text(first + "/bench.json"));
  for (auto& row : moved["results"]) row["scene"] = "builtin:star";
  test::write_text(dir.file("moved.json"), moved.dump());
  test::write_text(first + "/notes.txt", "mine");
  r = run_rsaa("bench --from-json " + dir.file("moved.json") + " --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* gone : {"crops-edges.png", "pareto-edges.png", "passes-edges.png"})
    EXPECT_FALSE(std::filesystem::exists(first + "/" + gone)) << gone;
  for (const char* kept : {"pareto-star.png", "passes-star.png", "report.md", "bench.csv", "notes.txt"})
    EXPECT_TRUE(std::filesystem::exists(first + "/" + kept)) << kept;
  EXPECT_EQ(nlohmann::json::parse(test::read_text(first + "/bench.json"))["results"][0]["scene"], "builtin:star");
  // A redraw of the same scenes in place keeps their crops, which it cannot make again.
  test::write_text(first + "/crops-star.png", "measured crops");
  r = run_rsaa("bench --from-json " + first + "/bench.json --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::read_text(first + "/crops-star.png"), "measured crops");
  // A scene name with a control character (a newline in a model's path, or a hand-edited file)
  // names no other file: the set list holds one name a line.
  test::write_text(first + "/photo.png", "precious");
  for (auto& row : moved["results"]) row["scene"] = "builtin:x\nphoto";
  test::write_text(dir.file("newline.json"), moved.dump());
  r = run_rsaa("bench --from-json " + dir.file("newline.json") + " --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(first + "/pareto-x_photo.png"));
  r = run_rsaa("bench --from-json " + first + "/bench.json --out-dir " + first);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::read_text(first + "/photo.png"), "precious");
}

// `rsaa shaders` into a directory holds one configuration's files: the record passes of an earlier
// --prepass msaa run go when a configuration without them is written there.
TEST(Cli, ShadersLeaveNoFilesOfAnEarlierConfiguration) {
  TempDir dir;
  auto r = run_rsaa("shaders --pattern gl4x --prepass msaa --out-dir " + dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(std::filesystem::exists(dir.file("rsaa_prepass_codes.comp")));
  r = run_rsaa("shaders --pattern d3d8x --out-dir " + dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* gone : {"rsaa_prepass_list.comp", "rsaa_prepass_codes.comp", "rsaa_post_list_size.comp"})
    EXPECT_FALSE(std::filesystem::exists(dir.file(gone))) << gone;
  EXPECT_TRUE(std::filesystem::exists(dir.file("rsaa_post.frag")));
}

// The pre-pass text of `rsaa shaders` is the pass's own: an engine may draw an RsaaPass of the
// same settings with a program built from the file (it carries the pass's signature).
TEST(Cli, ShadersPrepassCarriesThePassesSignature) {
  TempDir dir;
  const auto r = run_rsaa("shaders --pattern d3d8x --out-dir " + dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RsaaSettings settings;
  settings.prepass = "jittered";
  const std::string expected =
      "#define RSAA_PREPASS_SIGNATURE " + rsaa_prepass_signature(rsaa_shader_defines(settings, 8, false)) + "\n";
  EXPECT_NE(test::read_text(dir.file("rsaa_prepass.glsl")).find(expected), std::string::npos) << expected;
}

// The generated files' host recipe gives, per subsample, the jitter the pass itself draws with
// (an engine following it with the y sign flipped got an image a little wrong, without an error).
TEST(Cli, ShadersGiveTheHostThePassesJitterPerSubsample) {
  TempDir dir;
  const auto r = run_rsaa("shaders --pattern d3d8x --out-dir " + dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const SamplePattern d3d8x = builtin_pattern("d3d8x");
  std::istringstream text(test::read_text(dir.file("rsaa_prepass.glsl")));
  std::string line;
  int rows = 0;
  while (std::getline(text, line)) {
    int i = 0, nx = 0, ny = 0, zero1 = -1, zero2 = -1;
    double x = 0, y = 0, jx = 0, jy = 0;
    if (std::sscanf(line.c_str(), "// %d: (%lf, %lf) jitter (%lf / width, %lf / height) neighbours ivec4(%d, %d, %d, %d)", &i,
                    &x, &y, &jx, &jy, &nx, &ny, &zero1, &zero2) != 9)
      continue;
    ASSERT_LT(i, d3d8x.size());
    EXPECT_EQ(x, d3d8x.positions[i].x);
    EXPECT_EQ(y, d3d8x.positions[i].y);
    // The pass's jitter for a 1 x 1 image is the recipe's numerators.
    const glm::vec2 jitter = jitter_ndc_for_sample(x, y, 1, 1);
    EXPECT_FLOAT_EQ(float(jx), jitter.x) << line;
    EXPECT_FLOAT_EQ(float(jy), jitter.y) << line;
    const PixelStep step = outside_pixel_towards(d3d8x.positions[i]);
    EXPECT_EQ(nx, step.i) << line;
    EXPECT_EQ(ny, -step.j) << line;  // window space, +y up
    ++rows;
  }
  EXPECT_EQ(rows, 8);
}

// The bench renders with the texture filter it is given (--anisotropy, as render and diagnose):
// on the textured truck no AA's PSNR moves between trilinear filtering and the default 16 probes.
TEST(Cli, TheBenchFiltersTexturesAsItIsTold) {
  const std::string truck = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";
  if (!std::filesystem::exists(truck)) GTEST_SKIP() << truck << " not installed";
  TempDir dir;
  const auto psnr_with = [&](const std::string& anisotropy) {
    const std::string out = dir.file("a" + anisotropy);
    const auto r = run_rsaa("bench --scenes " + truck + " --techniques noaa --width 96 --height 72 --frames 1"
                            " --orbit-frames 2 --anisotropy " + anisotropy + " --out-dir " + out);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto json = nlohmann::json::parse(test::read_text(out + "/bench.json"), nullptr, false);
    if (json.is_discarded() || !json.contains("results") || json["results"].empty()) return -1.0;
    return json["results"][0].value("psnr_db", -1.0);
  };
  const double trilinear = psnr_with("1"), anisotropic = psnr_with("16");
  ASSERT_GT(trilinear, 0.0);
  ASSERT_GT(anisotropic, 0.0);
  EXPECT_GT(std::abs(trilinear - anisotropic), 0.01) << trilinear << " vs " << anisotropic;
}

// Text from input files never becomes code or terminal control (found by an adversarial review):
// a newline in a table's path ended the generated shaders' "Generated by" comment (exit 0, an
// #error line in every file), and a table's recorded command or a model's texture name reached
// the terminal raw (escape sequences clear the screen or fake lines).
TEST(Cli, TextFromInputsStaysText) {
  TempDir dir;
  const std::string table = test::read_text(std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json");
  const std::string injected = dir.file("nl\n#error injected\n.json");
  test::write_text(injected, table);
  auto r = run_rsaa("shaders --table '" + injected + "' --out-dir " + dir.file("shaders"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"rsaa_post.frag", "rsaa_prepass.glsl", "rsaa_post.hlsl"}) {
    const std::string text = test::read_text(dir.file("shaders") + "/" + file);
    EXPECT_EQ(text.find("\n#error injected"), std::string::npos) << file;
    EXPECT_NE(text.find("nl\\x0a#error injected\\x0a.json"), std::string::npos) << file;
  }
  auto j = nlohmann::json::parse(table);
  j["training"]["command"] = "x\x1b[2J\a\r\nFAKE";
  j.erase("set_id");  // (the contents changed)
  test::write_text(dir.file("escape.json"), j.dump());
  r = run_rsaa("eval-table --cases 200 " + dir.file("escape.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("made by: x\\x1b[2J\\x07\\x0d\\x0aFAKE"), std::string::npos) << r.output;
  test::write_text(dir.file("tex.mtl"), "newmtl m\nmap_Kd \x1b[2Jevil.png\n");
  test::write_text(dir.file("tex.obj"), "mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl m\nf 1/1 2/1 3/1\n");
  r = run_rsaa("render --scene " + dir.file("tex.obj") + " --width 16 --height 12 --out " + dir.file("tex.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\\x1b[2Jevil.png"), std::string::npos) << r.output;
}

// Models whose triangles cannot all be drawn: triangles with a vertex that is not finite are left
// out with a warning naming how many and the first (they were dropped silently), and a model of
// zero-area triangles only is refused like one with no triangles (it drew an empty image, and
// `train --from-scene` wrote a table of no masks, with exit 0).
TEST(Cli, ModelsWithUndrawableTrianglesSaySo) {
  TempDir dir;
  test::write_text(dir.file("inf.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv inf 0 0\nf 1 2 3\nf 1 2 4\n");
  auto r = run_rsaa("render --scene " + dir.file("inf.obj") + " --width 16 --height 12 --out " + dir.file("inf.png"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 triangle left out: a vertex not finite or out of range (the first mesh 0 face 1)"),
            std::string::npos) << r.output;
  test::write_text(dir.file("flat.obj"), "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 2 3 4\n");
  for (const std::string& command : {"render --width 16 --height 12 --out " + dir.file("flat.png") + " --scene ",
                                    "train --out-dir " + dir.file("tables") + " --from-scene "}) {
    r = run_rsaa(command + dir.file("flat.obj"));
    EXPECT_NE(r.exit_code, 0) << command;
    EXPECT_NE(r.output.find("have zero area)"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("flat.png")));
}

}  // namespace
}  // namespace rsaa
