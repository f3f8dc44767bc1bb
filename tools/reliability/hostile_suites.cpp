// Issue 15's hostile inputs and environments, class by class, fed to the rsaa binary as a user
// would, each within 60 s and 6 GiB of address space. An input is handled when rsaa refuses it
// (exit status 1 or 2, a message naming what was refused, no output file) or, where the input is
// valid, does the job correctly. A crash, a signal, a timeout, an unnamed refusal, an output file
// left behind, a mixed table set or a file outside the output directory is mishandled.
#include <sys/wait.h>
#include <unistd.h>

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <thread>

#include <OpenImageIO/imageio.h>
#include <zlib.h>

#include "core/util/atomic_file.h"
#include "image/image_io.h"
#include "core/rsaa/offset_table.h"
#include "tools/reliability/suite.h"

namespace rsaa::reliability {
namespace {

namespace fs = std::filesystem;

const std::string kModels = "/usr/share/assimp/models";

// One hostile input: the arguments, the text the refusal must name, and a check of the result.
struct Feed {
  std::string label;
  std::vector<std::string> args;
  std::string must_name;  // refusal: the output names this; empty: success expected
  std::string output;     // a file that must not exist after a refusal (or must, after success)
  // After the run, given its output: empty if right, else what is wrong.
  std::function<std::string(const std::string& output)> check;
  std::uint64_t address_space = kInputAddressSpace;
  std::uint64_t max_processes = 0;
  std::vector<std::string> environment{};  // run_limited's changes: "NAME=VALUE", or "NAME" to unset
  std::uint64_t file_size_limit = 0;       // RLIMIT_FSIZE: writes beyond fail as on a full disk
  // Either outcome is right: success with the output, or a refusal naming must_name (where it
  // depends on what else runs, as the room a process limit leaves).
  bool success_or_refusal = false;
};

Outcome judge(const Feed& f, const std::string& rsaa, std::string& detail) {
  std::vector<std::string> argv = {rsaa};
  argv.insert(argv.end(), f.args.begin(), f.args.end());
  const RunResult r = run_limited(argv, kInputSeconds, f.address_space, f.max_processes, f.environment, f.file_size_limit);
  const std::string tail = r.output.substr(0, 300);
  if (r.timed_out) return detail = "still running after 60 s", Outcome::kFailed;
  if (r.signal) return detail = "killed by signal " + std::to_string(r.signal) + ": " + tail, Outcome::kFailed;
  if (f.must_name.empty() || (f.success_or_refusal && r.exit_code == 0)) {
    if (r.exit_code != 0) return detail = "a valid input failed: " + tail, Outcome::kFailed;
    if (!f.output.empty() && !fs::exists(f.output)) return detail = "no output " + f.output, Outcome::kFailed;
    if (f.check) detail = f.check(r.output);
    return detail.empty() ? Outcome::kAccepted : Outcome::kFailed;
  }
  if (r.exit_code <= 0)
    return detail = "exit status " + std::to_string(r.exit_code) + ": " + tail, Outcome::kFailed;
  if (r.output.find(f.must_name) == std::string::npos)
    return detail = "the message does not name '" + f.must_name + "': " + tail, Outcome::kFailed;
  if (!f.output.empty() && fs::exists(f.output)) return detail = "left " + f.output, Outcome::kFailed;
  if (f.check && !(detail = f.check(r.output)).empty()) return Outcome::kFailed;
  return Outcome::kRejectedClearly;
}

SuiteResult run_class(const std::string& what, const std::vector<Feed>& feeds, const Options& options) {
  SuiteResult r{what, 0, 0, 0, 0, {}};
  for (const Feed& f : feeds) {
    std::string detail;
    r.add(judge(f, options.rsaa_binary, detail), f.label, detail);
  }
  return r;
}

// --- inputs --------------------------------------------------------------------------------

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string big_endian(std::uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG that declares width x height in its header and holds no pixels: what the size check
// must refuse before anything is allocated.
std::string png_declaring(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = "IHDR" + big_endian(width) + big_endian(height) + std::string("\x08\x02\x00\x00\x00", 5);
  const std::string idat = std::string("IDAT") + "\x78\x9c";  // the start of a zlib stream
  return std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(crc32(ihdr)) +
         big_endian(2) + idat + big_endian(crc32(idat)) + big_endian(0) + "IEND" + big_endian(crc32("IEND"));
}

void write_float_image(const std::string& path, int w, int h, int channels, float value) {
  auto out = OIIO::ImageOutput::create(path);
  std::vector<float> pixels(std::size_t(w) * h * channels, value);
  if (!out || !out->open(path, OIIO::ImageSpec(w, h, channels, OIIO::TypeDesc::FLOAT)) ||
      !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
    throw std::runtime_error(path + ": cannot write test image");
}

// A glTF whose one triangle hangs below a chain of `depth` nodes.
std::string gltf_chain(int depth) {
  std::string nodes;
  for (int i = 0; i + 1 < depth; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "]},";
  nodes += "{\"mesh\":0}";
  // Three vertices (0,0,0), (1,0,0), (0,1,0) as little-endian floats, base64.
  return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[" + nodes +
         "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"buffers\":[{\"byteLength\":36,"
         "\"uri\":\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],"
         "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
         "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[1,1,0]}]}";
}

// A tetrahedron scaled by `scale` and moved by `offset` along every axis, after `header`.
std::string tetrahedron_obj(double scale, double offset = 0.0, const std::string& header = "") {
  std::string s = header;
  char line[200];
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", offset + p[0] * scale, offset + p[1] * scale,
                  offset + p[2] * scale);
    s += line;
  }
  return s + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/2\nf 1/1 2/2 4/3\n";
}

// A compressed XGL model (.zgl: two bytes, then raw deflate) whose XML is `repeats` times
// "<a/>x" inside <WORLD>: a few hundred KB that inflate to 5 bytes per repeat, which the XML
// parser inside assimp (pugixml) turns into two 64-byte nodes, allocated with malloc: about 26
// bytes per inflated byte that only a budget counting malloc sees.
std::string zgl_of_empty_elements(std::uint64_t repeats) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("deflateInit2 failed");
  std::string out(2, '\0'), block;
  for (int k = 0; k < 65536; ++k) block += "<a/>x";
  const std::string head = "<WORLD>", tail = "</WORLD>";
  std::vector<unsigned char> buffer(1 << 16);
  const auto feed = [&](const std::string& text, int flush) {
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    z.avail_in = uInt(text.size());
    do {
      z.next_out = buffer.data();
      z.avail_out = uInt(buffer.size());
      deflate(&z, flush);
      out.append(reinterpret_cast<const char*>(buffer.data()), buffer.size() - z.avail_out);
    } while (z.avail_out == 0);
  };
  feed(head, Z_NO_FLUSH);
  for (std::uint64_t done = 0; done < repeats; done += 65536) feed(block, Z_NO_FLUSH);
  feed(tail, Z_FINISH);
  deflateEnd(&z);
  return out;
}

bool make_fifo(const std::string& path) { return ::mkfifo(path.c_str(), 0600) == 0; }

// The three table files agree: GLSL and HLSL are what the JSON's table gives.
std::string table_set_consistent(const std::string& dir, const std::string& stem) {
  try {
    const OffsetTable t = read_offset_table(dir + "/" + stem + ".json");
    if (read_whole_file(dir + "/" + stem + ".glsl") != offset_table_glsl(t)) return "GLSL from another run";
    if (read_whole_file(dir + "/" + stem + ".hlsl") != offset_table_hlsl(t)) return "HLSL from another run";
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::size_t temporaries_in(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().find(".rsaa-tmp-") != std::string::npos;
  return n;
}

pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

}  // namespace

std::vector<SuiteResult> hostile_suites(const Options& options) {
  if (options.rsaa_binary.empty()) return {};
  const ScratchDir dir;
  const auto f = [&](const std::string& name) { return dir.file(name); };
  const std::string table = std::string(RSAA_SOURCE_DIR) + "/tables/d3d8x.json";
  // Valid inputs for the hostile ones to sit beside.
  Image black(8, 8);
  write_image(f("black.png"), black);
  write_image(f("black.exr"), black);
  make_fifo(f("fifo.png"));
  make_fifo(f("fifo.json"));
  make_fifo(f("fifo.obj"));
  make_fifo(f("fifo.csv"));
  dir.write("chain.gltf", gltf_chain(20000));
  dir.write("fifo-texture.mtl", "newmtl m\nmap_Kd fifo.png\n");
  make_fifo(f("fifo-mtl.mtl"));
  dir.write("fifo-texture.obj", tetrahedron_obj(1.0, 0.0, "mtllib fifo-texture.mtl\nusemtl m\n"));
  dir.write("fifo-mtl.obj", tetrahedron_obj(1.0, 0.0, "mtllib fifo-mtl.mtl\nusemtl m\n"));
  dir.write("huge.png", png_declaring(16384, 16384));
  dir.write("wide.png", png_declaring(100000, 1));
  dir.write("huge-texture.png", png_declaring(16384, 16384));
  dir.write("huge-texture.mtl", "newmtl m\nmap_Kd huge-texture.png\n");
  dir.write("huge-texture.obj", tetrahedron_obj(1.0, 0.0, "mtllib huge-texture.mtl\nusemtl m\n"));
  dir.write("big-table.json", read_whole_file(table) + std::string(17u << 20, ' '));
  dir.write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n");
  dir.write("cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vert");
  dir.write("huge.off", "OFF\n999999999999 1 0\n0 0 0\n");
  // Formats without a pre-scan whose importers trust a declared count (the import's memory budget).
  dir.write("huge.x", "xof 0303txt 0032\nMesh m {\n 1000000000;\n 0.0;0.0;0.0;,\n 1.0;0.0;0.0;,\n 0.0;1.0;0.0;;\n 1;\n 3;0,1,2;;\n}\n");
  dir.write("huge.ase", "*3DSMAX_ASCIIEXPORT 200\n*GEOMOBJECT {\n*NODE_NAME \"a\"\n*MESH {\n*MESH_NUMVERTEX 1000000000\n"
                        "*MESH_NUMFACES 1000000000\n*MESH_VERTEX_LIST {\n*MESH_VERTEX 0 0 0 0\n}\n}\n}\n");
  dir.write("huge.dae", "<?xml version=\"1.0\"?><COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">"
                        "<library_geometries><geometry id=\"g\"><mesh><source id=\"p\"><float_array id=\"pa\" count=\"1000000000\">"
                        "0 0 0 1 0 0 0 1 0</float_array></source><vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/>"
                        "</vertices><triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>0 1 2</p>"
                        "</triangles></mesh></geometry></library_geometries></COLLADA>\n");
  // A texture face referring to texture vertex 99999999: assimp 5.2's ASE importer segfaults.
  dir.write("crash.ase", "*3DSMAX_ASCIIEXPORT 200\n*GEOMOBJECT {\n*NODE_NAME \"a\"\n*MESH {\n*MESH_NUMVERTEX 3\n*MESH_NUMFACES 1\n"
                         "*MESH_VERTEX_LIST {\n*MESH_VERTEX 0 0 0 0\n*MESH_VERTEX 1 1 0 0\n*MESH_VERTEX 2 0 1 0\n}\n"
                         "*MESH_FACE_LIST {\n*MESH_FACE 0: A: 0 B: 1 C: 2\n}\n*MESH_NUMTVERTEX 1\n*MESH_TVERTLIST {\n"
                         "*MESH_TVERT 0 0 0 0\n}\n*MESH_NUMTVFACES 1\n*MESH_TFACELIST {\n*MESH_TFACE 0 0 99999999 5\n}\n}\n}\n");
  // 16 M repeats: 80 MB of XML in a 78 KB file, about 2 GB of pugixml nodes.
  dir.write("elements.zgl", zgl_of_empty_elements(std::uint64_t{1} << 24));
  write_float_image(f("nan.exr"), 8, 8, 3, std::numeric_limits<float>::quiet_NaN());
  write_float_image(f("inf.exr"), 8, 8, 3, std::numeric_limits<float>::infinity());
  for (const char* scale : {"1e30", "1e-30", "1"}) dir.write(std::string("scale-") + scale + ".obj", tetrahedron_obj(std::stod(scale)));
  dir.write("far-offset.obj", tetrahedron_obj(1.0, 1e6));
  {
    // Grey+alpha: grey 1.0 at alpha 0.5 is linear 0.5 over black, the same as RGB (0.5, 0.5, 0.5).
    auto out = OIIO::ImageOutput::create(f("ga.png"));
    OIIO::ImageSpec spec(4, 4, 2, OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 1;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    std::vector<std::uint8_t> ga(32);
    for (std::size_t i = 0; i < ga.size(); i += 2) ga[i] = 255, ga[i + 1] = 128;
    out->open(f("ga.png"), spec);
    out->write_image(OIIO::TypeDesc::UINT8, ga.data());
    out->close();
    Image half(4, 4);
    for (Rgb& p : half.pixels) p = {128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f};
    write_image(f("ga-expected.png"), half);
  }
  {
    // One pattern name, two sets of positions.
    fs::create_directories(f("a")), fs::create_directories(f("b"));
    write_offset_table_files(fallback_table(pattern_from_positions("custom-p", {{-0.25, -0.25}, {0.25, 0.25}})), f("a"));
    write_offset_table_files(fallback_table(pattern_from_positions("custom-p", {{-0.25, 0.25}, {0.25, -0.25}})), f("b"));
    std::string t = read_whole_file(f("a/custom-p.json"));
    dir.write("escape.json", t.replace(t.find("\"custom-p\""), 10, "\"custom-../../x\""));
  }
  dir.write("span.csv", "x,y\n0,1e308\n1,-1e308\n");
  // x values a chart cannot tell apart (their labels were drawn over each other) and a header that
  // names one column twice (the first was drawn, silently).
  dir.write("narrow.csv", "x,y\n1e-320,1\n2e-320,2\n");
  dir.write("twice.csv", "x,y,x\n1,2,3\n2,3,4\n");
  {
    // A table naming its pattern twice (nlohmann kept the last one without a word), and an EXR
    // whose data window is moved off the display window's origin (compared as if unshifted).
    std::string t = read_whole_file(f("a/custom-p.json"));
    dir.write("twice.json", "{\"pattern\": \"d3d4x\", " + t.substr(t.find('{') + 1));
    auto out = OIIO::ImageOutput::create(f("shifted.exr"));
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::FLOAT);
    spec.x = spec.y = 5;
    std::vector<float> black(8 * 8 * 3, 0.0f);
    if (!out || !out->open(f("shifted.exr"), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, black.data()) || !out->close())
      throw std::runtime_error(f("shifted.exr") + ": cannot write test image");
  }
  dir.write("bench.csv", "scene,technique,frame_ms,psnr_db,passes_wall_ms\n"
                         "\"builtin:default\",\"rsaa 8x, sadp\",1.5,30,\"scene=1;post=0.5\"\n"
                         "\"a \"\"quoted\"\" scene\",\"noaa\",0.5,25,\"scene=0.4\"\n");

  const auto refuse = [&](const std::string& label, std::vector<std::string> args, const std::string& name,
                          const std::string& output = "") { return Feed{label, std::move(args), name, output, {}}; };

  // At most 6 processes (threads) of the user: most of the 64 worker threads cannot start. Below
  // 5, rsaa cannot start at all: liblog4cplus (loaded with OpenImageIO's OpenVDB) starts threads
  // in its static initialiser, before main, and aborts when it cannot.
  fs::create_directories(f("threads"));
  fs::permissions(f("threads"), fs::perms::all);
  Feed threads_feed{"train --threads 64 with RLIMIT_NPROC 6 (threads fail to start)",
                    {"train", "--pattern", "d3d4x", "--cases", "4000", "--threads", "64", "--quiet", "--out-dir", f("threads")},
                    "", f("threads/d3d4x.json"), [&](const std::string&) { return table_set_consistent(f("threads"), "d3d4x"); }};
  threads_feed.max_processes = 6;
  // Below 5 the program used to abort before main (OpenImageIO's logger starting threads in a
  // static initialiser); now OpenImageIO is loaded only to read or write an image.
  Feed nproc_1{"eval-table with RLIMIT_NPROC 1 (no thread can start)", {"eval-table", "--cases", "2000", table}, "", "", {}};
  nproc_1.max_processes = 1;
  Feed nproc_3{"render with RLIMIT_NPROC 3 (renders on one thread; the PNG writer cannot load)",
               {"render", "--scene", "builtin:edges", "--technique", "rsaa", "--width", "32", "--height", "24", "--out", f("nproc.png")},
               "ulimit -u", f("nproc.png"), {}};
  nproc_3.max_processes = 3;

  // An address-space limit too small for llvmpipe's context: it crashed inside the driver
  // (SIGSEGV, 300-500 MB) or failed without naming the limit.
  Feed small_address_space{"render with RLIMIT_AS 400 MiB (llvmpipe crashed creating its context)",
                           {"render", "--scene", "builtin:edges", "--width", "32", "--height", "24", "--out", f("as.png")},
                           "ulimit -v", f("as.png"), {}};
  small_address_space.address_space = std::uint64_t{400} << 20;

  // LP_NUM_THREADS beyond the process limit: llvmpipe waited forever for its missing threads.
  Feed lp_threads{"LP_NUM_THREADS=32 with RLIMIT_NPROC 8 (llvmpipe waited forever)",
                  {"render", "--scene", "builtin:edges", "--technique", "rsaa", "--width", "32", "--height", "24", "--out", f("threads/lp.png")},
                  "ulimit -u", f("threads/lp.png"), {}};
  lp_threads.max_processes = 8;
  lp_threads.environment = {"LP_NUM_THREADS=32"};
  // The room RLIMIT_NPROC leaves counts every process of the user (nobody, under root): with
  // other runs as nobody (parallel tests) rsaa renders with one llvmpipe thread, else it may refuse.
  lp_threads.success_or_refusal = true;
  // A file-size limit (ulimit -f 8 KiB) stands for a full disk: writes fail (EFBIG as ENOSPC).
  const auto full_disk = [&](const std::string& label, std::vector<std::string> args, const std::string& name,
                             const std::string& output, const std::string& dir) {
    Feed feed{label, std::move(args), name, output, [dir](const std::string&) -> std::string {
                return fs::exists(dir) && temporaries_in(dir) ? "temporaries left" : "";
              }};
    feed.file_size_limit = 8 << 10;
    return feed;
  };
  fs::create_directories(f("full"));

  std::vector<SuiteResult> suites;
  suites.push_back(run_class(
      "hostile 1, crashes: format strings, thread and process limits, deep nesting, broken importer scenes, importer crashes",
      {
          refuse("view --screenshot 'x%n.png'", {"view", "--screenshot", "x%n.png", "--keys", "Q"}, "--screenshot"),
          refuse("view --screenshot '%s%s%s'", {"view", "--screenshot", "%s%s%s", "--keys", "Q"}, "--screenshot"),
          refuse("view --screenshot 'shot-%'", {"view", "--screenshot", "shot-%", "--keys", "Q"}, "--screenshot"),
          Feed{"glTF node chain 20,000 deep", {"render", "--scene", f("chain.gltf"), "--width", "32", "--height", "24", "--out", f("chain.png")}, "", f("chain.png"), {}},
          threads_feed,
          nproc_1,
          nproc_3,
          refuse("assimp's RAW/WithTexture.raw (null child nodes; PreTransformVertices segfaulted)",
                 {"render", "--scene", kModels + "/RAW/WithTexture.raw", "--out", f("raw.png")}, "WithTexture.raw", f("raw.png")),
          refuse("ASE whose texture face refers to texture vertex 99999999 (assimp segfaulted)",
                 {"render", "--scene", f("crash.ase"), "--out", f("crash.png")}, "crashed on it (signal 11", f("crash.png")),
          Feed{"assimp's OpenGEX/camera.ogex (lights without nodes; an assertion aborted)",
               {"render", "--scene", kModels + "/OpenGEX/camera.ogex", "--width", "32", "--height", "24", "--out", f("ogex.png")}, "", f("ogex.png"), {}},
      },
      options));

  suites.push_back(run_class(
      "hostile 2, hangs and driver crashes: devices and FIFOs where files are read, a cut PLY header, LP_NUM_THREADS beyond the process limit, an address space too small for llvmpipe",
      {
          refuse("compare /dev/zero", {"compare", "/dev/zero", f("black.png")}, "/dev/zero"),
          refuse("compare a FIFO", {"compare", f("black.png"), f("fifo.png")}, "fifo.png"),
          refuse("eval-table /dev/zero", {"eval-table", "--cases", "100", "/dev/zero"}, "/dev/zero"),
          refuse("eval-table /dev/urandom", {"eval-table", "--cases", "100", "/dev/urandom"}, "/dev/urandom"),
          refuse("eval-table a FIFO", {"eval-table", "--cases", "100", f("fifo.json")}, "fifo.json"),
          refuse("render --scene a FIFO", {"render", "--scene", f("fifo.obj"), "--out", f("out-1.png")}, "fifo.obj", f("out-1.png")),
          refuse("render --scene /dev/zero", {"render", "--scene", "/dev/zero", "--out", f("out-2.png")}, "/dev/zero", f("out-2.png")),
          refuse("a model whose texture is a FIFO", {"render", "--scene", f("fifo-texture.obj"), "--out", f("out-3.png")}, "fifo.png", f("out-3.png")),
          refuse("a model whose material file is a FIFO", {"render", "--scene", f("fifo-mtl.obj"), "--out", f("out-4.png")}, "fifo-mtl.mtl", f("out-4.png")),
          refuse("plot a FIFO", {"plot", f("fifo.csv"), "--x", "a", "--y", "b", "--out", f("out-5.png")}, "fifo.csv", f("out-5.png")),
          lp_threads,
          small_address_space,
          refuse("PLY header cut inside a property list (assimp looped forever)", {"render", "--scene", f("cut.ply"), "--out", f("out-cut.png")}, "end_header", f("out-cut.png")),
          refuse("train --generic a FIFO", {"train", "--from-scene", "builtin:edges", "--generic", f("fifo.json"), "--out-dir", f("tables-fifo")}, "fifo.json"),
      },
      options));

  suites.push_back(run_class(
      "hostile 3, memory: small files declaring huge sizes",
      {
          refuse("PNG declaring 16384x16384 (compare)", {"compare", f("huge.png"), f("black.png")}, "16384x16384"),
          refuse("PNG declaring 100000x1 (compare)", {"compare", f("wide.png"), f("black.png")}, "100000x1"),
          refuse("table over 16 MiB (eval-table)", {"eval-table", "--cases", "100", f("big-table.json")}, "big-table.json"),
          refuse("assimp's OutOfMemory.off (render)", {"render", "--scene", kModels + "/invalid/OutOfMemory.off", "--out", f("out-6.png")}, "OutOfMemory.off", f("out-6.png")),
          refuse("OFF declaring 10^12 vertices", {"render", "--scene", f("huge.off"), "--out", f("out-7.png")}, "huge.off", f("out-7.png")),
          refuse("PLY declaring 4e9 vertices", {"render", "--scene", f("huge.ply"), "--out", f("out-8.png")}, "huge.ply", f("out-8.png")),
          refuse("texture declaring 16384x16384", {"render", "--scene", f("huge-texture.obj"), "--out", f("out-9.png")}, "huge-texture.png", f("out-9.png")),
          refuse("DirectX .x declaring 10^9 vertices", {"render", "--scene", f("huge.x"), "--out", f("out-9x.png")}, "huge.x", f("out-9x.png")),
          refuse("ASE declaring 10^9 vertices", {"render", "--scene", f("huge.ase"), "--out", f("out-9a.png")}, "huge.ase", f("out-9a.png")),
          refuse("Collada float_array of 10^9", {"render", "--scene", f("huge.dae"), "--out", f("out-9d.png")}, "huge.dae", f("out-9d.png")),
          refuse("compressed XGL inflating to 16M XML elements (pugixml's malloc)", {"render", "--scene", f("elements.zgl"), "--out", f("out-9z.png")}, "more memory than its budget", f("out-9z.png")),
      },
      options));

  // Class 4: two trains at once into one directory, a target that cannot be replaced, and the
  // temporaries of a run killed with -9.
  {
    SuiteResult r{"hostile 4, mixed or stray output: concurrent trains, failing replace, dead runs' temporaries, readers of a mixed or half-renamed set, full disk, a linked output", 0, 0, 0, 0, {}};
    const std::string shared = f("shared");
    fs::create_directories(shared);
    const pid_t dead = dead_pid();
    const std::string stale = shared + "/.d3d4x.rsaa-tmp-" + std::to_string(dead) + "-0.json";
    std::ofstream(stale) << "half a table";
    std::vector<RunResult> runs(2);
    std::vector<std::thread> both;
    for (int k = 0; k < 2; ++k)
      both.emplace_back([&, k] {
        runs[k] = run_limited({options.rsaa_binary, "train", "--pattern", "d3d4x", "--cases", "60000", "--seed",
                               std::to_string(k + 1), "--quiet", "--out-dir", shared});
      });
    for (auto& t : both) t.join();
    int succeeded = 0;
    std::string detail;
    for (const RunResult& run : runs) {
      if (run.exit_code == 0) ++succeeded;
      else if (run.exit_code != 1 || run.output.find(shared) == std::string::npos) detail = "a train failed unclearly: " + run.output.substr(0, 200);
    }
    if (succeeded == 0 && detail.empty()) detail = "neither train succeeded";
    if (detail.empty()) detail = table_set_consistent(shared, "d3d4x");
    if (detail.empty() && fs::exists(stale)) detail = "a dead run's temporary was left";
    if (detail.empty() && temporaries_in(shared) != 0) detail = "temporaries left";
    r.add(detail.empty() ? (succeeded == 2 ? Outcome::kAccepted : Outcome::kRejectedClearly) : Outcome::kFailed,
          "two trains into one --out-dir, a dead run's temporary beside them", detail);

    // The last of the three files cannot be replaced (a directory is in its place).
    const std::string blocked = f("blocked");
    fs::create_directories(blocked + "/d3d4x.hlsl/inside");
    std::ofstream(blocked + "/d3d4x.json") << "previous json";
    std::ofstream(blocked + "/d3d4x.glsl") << "previous glsl";
    Feed feed{"train where d3d4x.hlsl is a directory", {"train", "--pattern", "d3d4x", "--cases", "2000", "--quiet", "--out-dir", blocked},
              "d3d4x.hlsl", "", [&](const std::string&) -> std::string {
                if (read_whole_file(blocked + "/d3d4x.json") != "previous json" ||
                    read_whole_file(blocked + "/d3d4x.glsl") != "previous glsl")
                  return "the other two files were replaced: a mixed set";
                return temporaries_in(blocked) ? "temporaries left" : "";
              }};
    std::string d;
    r.add(judge(feed, options.rsaa_binary, d), feed.label, d);

    // A reader of a set: a .glsl of another write beside the JSON is refused, naming it.
    const std::string mixed = f("mixed");
    fs::create_directories(mixed);
    OffsetTable one = fallback_table(builtin_pattern("d3d4x")), two = one;
    two.offsets[5] = {0.25, -0.5};
    write_offset_table_files(one, mixed);
    std::ofstream(mixed + "/d3d4x.glsl") << offset_table_glsl(two);
    Feed mixed_feed = refuse("eval-table of a set whose .glsl is of another write", {"eval-table", "--cases", "100", mixed + "/d3d4x.json"}, "d3d4x.glsl");
    d.clear();
    r.add(judge(mixed_feed, options.rsaa_binary, d), mixed_feed.label, d);

    // A writer killed between its renames (here: at the second), nothing written since: a reader
    // gets the set its journal commits, whole.
    const std::string killed = f("killed");
    fs::create_directories(killed);
    write_offset_table_files(one, killed);
    const pid_t child = ::fork();
    if (child == 0) {
      int calls = 0;
      write_files_atomically({{killed + "/d3d4x.json", offset_table_json(two)}, {killed + "/d3d4x.glsl", offset_table_glsl(two)},
                              {killed + "/d3d4x.hlsl", offset_table_hlsl(two)}},
                             [&](const std::string& from, const std::string& to, std::string&) {
                               if (++calls == 2) ::_exit(9);
                               return std::rename(from.c_str(), to.c_str()) == 0;
                             });
      ::_exit(0);
    }
    ::waitpid(child, nullptr, 0);
    Feed killed_feed{"render --table of a set whose writer died between its renames",
                     {"render", "--scene", "builtin:edges", "--technique", "rsaa", "--samples", "4", "--table", killed + "/d3d4x.json",
                      "--width", "32", "--height", "24", "--out", f("killed.png")},
                     "", f("killed.png"), {}};
    d.clear();
    r.add(judge(killed_feed, options.rsaa_binary, d), killed_feed.label, d);

    // A full disk (ulimit -f 8 KiB): OIIO's PNG writer reported success for a truncated file and
    // SIGXFSZ ended rsaa mid-write, its temporary left behind.
    for (const Feed& full : {full_disk("render a 640x480 PNG with 8 KiB of disk", {"render", "--scene", "builtin:default", "--out", f("full/r.png")},
                                       "File too large", f("full/r.png"), f("full")),
                             full_disk("train d3d8x with 8 KiB of disk", {"train", "--pattern", "d3d8x", "--cases", "2000", "--quiet", "--out-dir", f("full/t")},
                                       "File too large", f("full/t/d3d8x.json"), f("full/t"))}) {
      d.clear();
      r.add(judge(full, options.rsaa_binary, d), full.label, d);
    }
    // An output that is a symbolic link (to a file outside) is not replaced.
    std::ofstream(f("outside.txt")) << "outside";
    fs::create_symlink(f("outside.txt"), f("link.png"));
    Feed link = refuse("render --out a symbolic link", {"render", "--scene", "builtin:edges", "--width", "32", "--height", "24", "--out", f("link.png")}, "link.png");
    link.check = [&](const std::string&) -> std::string {
      return fs::is_symlink(f("link.png")) && read_whole_file(f("outside.txt")) == "outside" ? "" : "the link or its target was replaced";
    };
    d.clear();
    r.add(judge(link, options.rsaa_binary, d), link.label, d);
    suites.push_back(r);
  }

  suites.push_back(run_class(
      "hostile 5, injection and escape: pattern names and table names",
      {
          refuse("pattern name with a newline", {"train", "--pattern", "custom-a\n#error injected", "--positions", "0.25,0.25", "--out-dir", f("inject")}, "letters, digits"),
          refuse("pattern name with ../", {"train", "--pattern", "custom-../../escaped", "--positions", "0.25,0.25", "--out-dir", f("inject")}, "letters, digits", f("escaped.json")),
          refuse("pattern name with /", {"train", "--pattern", "custom-a/b", "--positions", "0.25,0.25", "--out-dir", f("inject")}, "letters, digits"),
          refuse("table whose pattern is custom-../../x", {"eval-table", "--cases", "100", f("escape.json")}, "escape.json"),
      },
      options));

  const auto psnr_inf = [](const std::string& output) -> std::string {
    return output.find("\"identical\": true") != std::string::npos ? "" : "not equal to its composite: " + output;
  };
  suites.push_back(run_class(
      "hostile 6, silently wrong: NaN/Inf images, alpha, shifted data windows, mixed patterns, repeated keys, degenerate positions, extreme scales and cameras, unplottable spans, repeated columns",
      {
          refuse("all-NaN EXR against black", {"compare", f("nan.exr"), f("black.exr")}, "NaN or infinite"),
          refuse("black against all-Inf EXR", {"compare", f("black.exr"), f("inf.exr")}, "inf.exr"),
          Feed{"grey+alpha PNG against its composite over black", {"compare", f("ga.png"), f("ga-expected.png"), "--json"}, "", "", psnr_inf},
          refuse("eval-table of one pattern name, other positions", {"eval-table", "--cases", "100", f("a/custom-p.json"), f("b/custom-p.json")}, "samples[0]"),
          refuse("custom positions with a subnormal coordinate", {"train", "--pattern", "custom-s", "--positions", "1e-310,0.25 0.25,-0.25", "--out-dir", f("sub")}, "sample 0", f("sub/custom-s.json")),
          refuse("custom positions that coincide", {"train", "--pattern", "custom-c", "--positions", "0.25,0.25 0.25,0.25", "--out-dir", f("sub")}, "coincident", f("sub/custom-c.json")),
          refuse("model at 1e30 scale", {"render", "--scene", f("scale-1e30.obj"), "--out", f("out-10.png")}, "scale-1e30.obj", f("out-10.png")),
          refuse("model at 1e-30 scale", {"render", "--scene", f("scale-1e-30.obj"), "--out", f("out-11.png")}, "scale-1e-30.obj", f("out-11.png")),
          refuse("unit model 1e6 from the origin", {"render", "--scene", f("far-offset.obj"), "--out", f("out-12.png")}, "far-offset.obj", f("out-12.png")),
          refuse("render --scene-scale 1e30 (only the background)", {"render", "--scene", "builtin:default", "--scene-scale", "1e30", "--out", f("out-12s.png")}, "scaled by 1e+30", f("out-12s.png")),
          refuse("render --camera at 3e38 (only the background)", {"render", "--scene", "builtin:default", "--camera", "3e38,0,0,0,0,0", "--out", f("out-12c.png")}, "--camera", f("out-12c.png")),
          refuse("plot of values from 1e308 to -1e308 (nothing drawn)", {"plot", f("span.csv"), "--x", "x", "--y", "y", "--out", f("out-12p.png")}, "span.csv", f("out-12p.png")),
          refuse("plot of x values 1e-320 apart (drawn at one x)", {"plot", f("narrow.csv"), "--x", "x", "--y", "y", "--out", f("out-12n.png")}, "narrow.csv", f("out-12n.png")),
          refuse("plot of a column the header names twice", {"plot", f("twice.csv"), "--x", "x", "--y", "y", "--out", f("out-12t.png")}, "twice.csv", f("out-12t.png")),
          refuse("table naming its pattern twice (the last won)", {"eval-table", "--cases", "100", f("twice.json")}, "twice.json"),
          refuse("EXR whose data window is off its display window (compared unshifted)", {"compare", f("shifted.exr"), f("black.exr")}, "shifted.exr"),
      },
      options));

  suites.push_back(run_class(
      "hostile 7, the command line: typed numbers, unknown commands, CSV, --out-dir, --quick over given options",
      {
          refuse("train --seed -1", {"train", "--pattern", "d3d4x", "--seed", "-1", "--out-dir", f("nowhere-13")}, "--seed", f("nowhere-13")),
          refuse("eval-table --seed -1", {"eval-table", table, "--seed", "-1"}, "--seed"),
          refuse("train --cases -1", {"train", "--pattern", "d3d4x", "--cases", "-1", "--out-dir", f("nowhere-14")}, "--cases", f("nowhere-14")),
          refuse("train --seed 18446744073709551616", {"train", "--pattern", "d3d4x", "--seed", "18446744073709551616", "--out-dir", f("nowhere-15")}, "--seed", f("nowhere-15")),
          refuse("train --threads 100000", {"train", "--pattern", "d3d4x", "--threads", "100000", "--out-dir", f("nowhere-16")}, "--threads", f("nowhere-16")),
          refuse("train --two-line-weight nan", {"train", "--pattern", "d3d4x", "--two-line-weight", "nan", "--out-dir", f("nowhere-17")}, "--two-line-weight", f("nowhere-17")),
          refuse("render --threshold -1", {"render", "--technique", "rsaa", "--threshold", "-1", "--out", f("out-18.png")}, "--threshold", f("out-18.png")),
          refuse("compare --luma-threshold nan", {"compare", f("black.png"), f("black.png"), "--luma-threshold", "nan"}, "--luma-threshold"),
          refuse("bench --quick --width 99999 (--quick replaced it)", {"bench", "--quick", "--width", "99999", "--out-dir", f("nowhere-19")}, "99999"),
          refuse("bench --scenes '' (meant the default scenes)", {"bench", "--scenes", "", "--out-dir", f("nowhere-20")}, "--scenes"),
          refuse("mistyped subcommand evaltable", {"evaltable", table}, "did you mean 'eval-table'"),
          refuse("mistyped subcommand rendr", {"rendr"}, "did you mean 'render'"),
          Feed{"plot a CSV with quoted fields (the bench's)", {"plot", f("bench.csv"), "--x", "frame_ms", "--y", "psnr_db", "--out", f("plot.png")}, "", f("plot.png"), {}},
          Feed{"train --out-dir that does not exist yet", {"train", "--pattern", "d3d4x", "--cases", "2000", "--quiet", "--out-dir", f("new/nested")}, "", f("new/nested/d3d4x.json"), {}},
      },
      options));
  return suites;
}

}  // namespace rsaa::reliability
