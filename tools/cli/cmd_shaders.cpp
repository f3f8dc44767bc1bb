// rsaa shaders: the engine-facing shaders for one configuration, each one self-contained text
// (defines set, includes expanded, the offset table inlined), for engines that include files
// without an include mechanism (SMAA-style: generate once, copy into the engine).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <sstream>

#include "core/util/atomic_file.h"
#include "core/util/printable.h"
#include "core/util/shell_quote.h"
#include "core/rsaa/conventions.h"
#include "core/rsaa/offset_table.h"
#include "core/rsaa/sample_pattern.h"
#include "runtime/rsaa_pass.h"
#include "runtime/shader_library.h"
#include "tools/cli/commands.h"
#include "tools/cli/options.h"
#include "tools/cli/out_dir.h"

namespace rsaa::cli {
namespace {

// The record passes of the pre-passes that write surface records, written with --prepass msaa and
// --prepass records only.
constexpr const char* kRecordPassFiles[] = {"rsaa_prepass_list.comp", "rsaa_prepass_codes.comp",
                                            "rsaa_post_list_size.comp"};

struct ShadersArgs {
  std::string out_dir, pattern = "d3d8x", table, material_edges = "off";
  double split_cap = RsaaSettings{}.split_cap;  // parsed as a double: checked before it becomes a float
  RsaaSettings settings;
};

// The shortest text that reads back as the same float ("1.5", "0.1", "0.123456789"), so that the
// header's command line makes the same files: %g's six digits would round a longer option away.
std::string number_text(float value) {
  char text[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(value));
    if (std::strtof(text, nullptr) == value) break;
  }
  return text;
}

// The command line that made a file, for its header: every option, defaults included, so that
// running it makes the same files whatever the defaults become.
std::string command_line(const ShadersArgs& a) {
  const RsaaSettings& s = a.settings;
  return "rsaa shaders " + (a.table.empty() ? "--pattern " + a.pattern : "--table " + shell_quoted(a.table)) +
         " --similarity " + s.similarity + " --auth " + std::to_string(s.auth) + " --code-bits " +
         std::to_string(s.code_bits) + " --split-cap " + number_text(s.split_cap) + " --multi-surface " +
         s.multi_surface + (s.multi_surface == "borrow" ? " --borrow-weight " + number_text(s.borrow_weight) : "") +
         " --split-check " + s.split_check + " --fetch-check " + s.fetch_check +
         " --material-edges " + (s.material_edges ? "on" : "off") + " --depth " + s.depth + " --prepass " +
         s.prepass + " --first-unit " + std::to_string(s.prepass_first_unit) + " --uniform-binding " +
         std::to_string(s.uniform_binding);
}

// What the host does with the files when no RsaaPass drives them (RsaaPass::run_prepass,
// write_frame_uniforms and resolve do the same), with this pattern's numbers, so that an engine
// needs nothing but the files.
std::string host_recipe(const ShadersArgs& a, const SamplePattern& pattern) {
  const RsaaSettings& s = a.settings;
  const int n = pattern.size();
  const char* code_format = s.code_bits == 8 ? "GL_RGBA8UI" : s.code_bits == 16 ? "GL_RGBA16UI" : "GL_RGBA32UI";
  std::ostringstream out;
  out << "// THE HOST'S PART (what the rsaa::pass library's RsaaPass does; every name below is in this text).\n"
      << "// The frame: colour in linear light (GL_RGBA16F, another float format, or sRGB, which reads decoded),\n"
      << "// centre normal GL_RG16UI = rsaa_encode_normal(geometric normal,\n"
      << "// view space), centre primitive GL_R32UI = primitive id + 1 (" << (s.material_edges ? "GL_RG32UI with the draw's material in .y" : "0: background") << "), centre depth; all of the frame's size.\n"
      << "// The RsaaUniforms block (std140, binding " << s.uniform_binding << "): rsaa_inverse_projection of the\n"
      << "// unjittered camera, rsaa_viewport = (width, height), rsaa_threshold = " << (s.similarity == "depth" ? "0.4 (percent of depth)" : "0.4")
      << "\n// (the library's default), rsaa_sample_shift = (0, 0), and per subsample i the values below.\n";
  if (s.prepass == "jittered")
    out << "// Pre-pass: ceil(" << n << " / 4) " << code_format << " code textures cleared to 0; for each subsample i, a\n"
        << "// framebuffer with code texture i / 4 at colour 0 and a 32-bit depth buffer cleared to "
        << (s.depth == "reverse-z" ? "0 (GL_GREATER)" : "1 (GL_LESS)") << ", depth\n"
        << "// writes on, no blending, glColorMaski(0, ...) writing channel i % 4 only, the centre normal, primitive\n"
        << "// and depth at units " << s.prepass_first_unit << " to " << s.prepass_first_unit + 2
        << " (nearest), rsaa_subsample = i, rsaa_jitter_ndc as below; draw the\n"
        << "// frame's geometry with a program of this text (vertex: rsaa_jitter(); fragment: rsaa_prepass_code()).\n";
  else if (s.prepass == "records")
    out << "// Pre-pass: a GL_RG32UI 2D array texture of " << n << " layers (the records) cleared to 0 and a 32-bit depth\n"
        << "// 2D array of " << n << " layers cleared to " << (s.depth == "reverse-z" ? "0 (GL_GREATER)" : "1 (GL_LESS)")
        << "; for each subsample i, a framebuffer with layer i of each, depth writes\n"
        << "// on, no blending, the centre normal, primitive and depth at units " << s.prepass_first_unit << " to "
        << s.prepass_first_unit + 2 << " (nearest), rsaa_subsample = i,\n"
        << "// rsaa_jitter_ndc as below; draw the frame's geometry with a program of this text; then the record\n"
        << "// passes (their files say how) write the " << code_format << " code textures.\n";
  else
    out << "// Pre-pass: one draw of the frame's geometry with a program of this text into a framebuffer with\n"
        << "// a " << n << "-sample GL_RG32UI colour cleared to 0 and a " << n << "-sample 32-bit depth cleared to "
        << (s.depth == "reverse-z" ? "0 (GL_GREATER)" : "1 (GL_LESS)") << ",\n"
        << "// sample shading off, rsaa_subsample = 0, rsaa_jitter_ndc = (0, 0); then the record passes (their\n"
        << "// files say how) write the " << code_format << " code textures.\n";
  out << "// Post-process (rsaa_post.frag): a full-screen draw into a separate colour target of any format (it reads\n"
      << "// the frame's colour; an sRGB target with GL_FRAMEBUFFER_SRGB on, so that the linear result is encoded),\n"
      << "// any vertex stage covering the viewport; units 0 colour (bilinear, clamp to edge),\n"
      << "// 1 centre normal, 2 centre depth, 4.. the code textures, " << (s.material_edges ? "8 centre primitive, " : "")
      << (s.multi_surface == "borrow" && s.prepass != "jittered" ? "10 the sources (the record passes' files), " : "")
      << "all nearest; rsaa_subsample = -1.\n"
      << "// Per subsample: position (pixel space, +y down), rsaa_jitter_ndc, rsaa_neighbours[i]:\n";
  for (int i = 0; i < n; ++i) {
    const Vec2 p = pattern.positions[i];
    const PixelStep step = outside_pixel_towards(p);
    const Vec2 window = pixel_to_gl({double(step.i), double(step.j)});
    char line[200];
    std::snprintf(line, sizeof line, "//   %2d: (%+.6g, %+.6g)  jitter (%+.6g / width, %+.6g / height)  neighbours ivec4(%d, %d, 0, 0)\n",
                  i, p.x, p.y, -2.0 * p.x, 2.0 * p.y, int(window.x), int(window.y));
    out << line;
  }
  return out.str();
}

// Borrowed colours' sources texture by rsaa_sources_channels().
constexpr const char* kSourcesFormats[] = {"GL_R32UI", "GL_RG32UI", "", "GL_RGBA32UI"};

int run_shaders(ShadersArgs a) {
  a.settings.material_edges = a.material_edges == "on";
  // As RsaaPass and `rsaa render` take it: 0 or at least 1 (1e-320 would round to the paper's 0,
  // 0.9999999999 to 1, silently).
  if (!(a.split_cap == 0.0 || (a.split_cap >= 1.0 && std::isfinite(a.split_cap))))
    throw std::invalid_argument("--split-cap must be 0 (the paper's split) or a finite number >= 1");
  a.settings.split_cap = float(a.split_cap);
  if (a.settings.borrow_weight != RsaaSettings{}.borrow_weight && a.settings.multi_surface != "borrow")
    throw std::invalid_argument("--borrow-weight needs --multi-surface borrow");
  const OffsetTable table = a.table.empty() ? gl::builtin_offset_table(a.pattern) : read_offset_table(a.table);
  const int n = table.pattern.size();
  const bool multisample = a.settings.prepass == "msaa";
  const bool writes_records = multisample || a.settings.prepass == "records";
  // (printable: a newline in the table's path would end the comment and start a line of code)
  const std::string header = "// Generated by: " + printable(command_line(a)) + "\n// Pattern " + table.pattern.name + ", " +
                             std::to_string(n) + " subsamples. Do not edit: generate again.\n";
  const std::string defines = rsaa_shader_defines(a.settings, n, multisample);

  std::vector<std::pair<std::string, std::string>> files;
  files.push_back({a.out_dir + "/rsaa_prepass.glsl",
                   header +
                       "// The pre-pass functions (shaders/rsaa_prepass.glsl documents them). Put this text after\n"
                       "// #version 450 in both stages of the engine's pre-pass program, in the vertex stage after\n"
                       "// `#define RSAA_INCLUDE_FS 0`.\n" + host_recipe(a, table.pattern) +
                       rsaa_prepass_text(defines)});
  files.push_back({a.out_dir + "/rsaa_post.frag",
                   "#version 450 core\n" + header +
                       "// The post-process as a complete fragment shader (shaders/rsaa_post.glsl documents its\n"
                       "// resources), the offset table inlined: no table texture. Draw it over the frame.\n" +
                       host_recipe(a, table.pattern) +
                       defines + "#define RSAA_TABLE_ARRAY\n" + offset_table_glsl(table) +
                       rsaa_shader_file("rsaa_post.frag")});
  if (writes_records) {
    // The record passes that turn the draws' records into the codes the post-process reads: the
    // records' units beside the pre-pass's three (as RsaaPass places them), code images from 0,
    // the pixel list at storage binding 0.
    const int record_unit = rsaa_record_first_unit(a.settings.prepass_first_unit);
    const int code_textures = (n + 3) / 4;
    const bool borrow = a.settings.multi_surface == "borrow";
    const std::string record_defines = rsaa_record_pass_defines(table.pattern, record_unit, 0, 0, code_textures);
    const std::string usage =
        "// The record passes of the pre-pass (shaders/rsaa_prepass_records.glsl documents them).\n"
        "// After the pre-pass " + std::string(multisample ? "draw" : "draws") +
        ": bind the centre textures (units --first-unit to +2), the " +
        (multisample ? "draw's\n// records (RG32UI" : "draws'\n// records (the RG32UI array") + ", unit " + std::to_string(record_unit) +
        "; with material edges the material packed in) and depths (" + (multisample ? "" : "the array, ") + "unit " +
        std::to_string(record_unit + 1) + "),\n"
        "// the code textures as images (units 0.., write-only), a buffer of 16 + 4 x width x\n"
        "// height bytes at storage binding 0 whose first 16 bytes are {0, 1, 1, 0}; set rsaa_rows\n"
        "// (location 0) to (0, height); dispatch rsaa_prepass_list.comp over the image in its work\n"
        "// groups, then rsaa_post_list_size.comp (1 group), then rsaa_prepass_codes.comp indirectly\n"
        "// from the buffer's first 12 bytes, with memory barriers between (RsaaPass::codes_from_records).\n" +
        (borrow ? "// Borrowed colours: a " + std::string(kSourcesFormats[rsaa_sources_channels(n) - 1]) +
                      " texture of the frame's size (the sources), cleared to 0\n// once, as image unit " +
                      std::to_string(code_textures) +
                      " (write-only) of rsaa_prepass_codes.comp; the post-process reads it at unit 10.\n"
                : std::string());
    for (const char* name : kRecordPassFiles)
      files.push_back({a.out_dir + "/" + name, "#version 450 core\n" + header + usage + defines + record_defines +
                                                   rsaa_shader_file(name)});
  }
  {
    // Post-pass authentication is the post-process's; pre-pass authentication is the pre-pass's.
    std::string hlsl_defines = "#define RSAA_SAMPLE_COUNT " + std::to_string(n) + "\n#define RSAA_AUTH " +
                               std::to_string(a.settings.auth == 1 ? 1 : 0) + "\n#define RSAA_CODE_BITS " +
                               std::to_string(a.settings.code_bits) + "\n";
    if (a.settings.similarity == "depth") hlsl_defines += "#define RSAA_SIMILARITY_DEPTH\n";
    if (a.settings.similarity == "sadp-plane") hlsl_defines += "#define RSAA_SIMILARITY_SADP_PLANE\n";
    // The options beyond the paper, as rsaa_shader_defines() writes them.
    for (const char* name :
         {"#define RSAA_SPLIT_CAP ", "#define RSAA_MULTI_SURFACE_NEIGHBOURS", "#define RSAA_SPLIT_CHECK_NEIGHBOURS",
          "#define RSAA_FETCH_CHECK_NEIGHBOURS", "#define RSAA_MATERIAL_EDGES"}) {
      const std::size_t at = defines.find(name);
      if (at != std::string::npos) hlsl_defines += defines.substr(at, defines.find('\n', at) + 1 - at);
    }
    files.push_back({a.out_dir + "/rsaa_post.hlsl",
                     header +
                         "// The post-process in HLSL (Direct3D conventions; shaders/rsaa_post.hlsl documents its\n"
                         "// resources), the offset table inlined. Entry points RsaaPostPS, RsaaResolve.\n" +
                         hlsl_defines + offset_table_hlsl(table) + rsaa_shader_file("rsaa_post.hlsl")});
  }
  const auto lock = claim_out_dir(a.out_dir, "rsaa shaders");
  write_files_atomically(files);
  for (const auto& [path, text] : files) std::printf("wrote %s\n", path.c_str());
  // The directory holds one configuration's files: the record passes an earlier --prepass msaa
  // or records run wrote there would be taken as this one's.
  if (!writes_records)
    for (const char* name : kRecordPassFiles) {
      std::error_code error;
      const std::string stale = a.out_dir + "/" + name;
      if (std::filesystem::is_regular_file(stale, error) && std::filesystem::remove(stale, error))
        std::printf("removed %s (an earlier configuration's record pass)\n", stale.c_str());
    }
  return 0;
}

}  // namespace

Action add_shaders_command(CLI::App& app) {
  auto args = std::make_shared<ShadersArgs>();
  CLI::App* cmd = app.add_subcommand(
      "shaders", "Write the engine-facing shaders of one configuration, self-contained (defines set, includes "
                 "expanded, table inlined): DIR/rsaa_prepass.glsl, DIR/rsaa_post.frag, DIR/rsaa_post.hlsl");
  cmd->add_option("--out-dir", args->out_dir, "Directory for the files (created if missing)")->required();
  cmd->add_option("--pattern", args->pattern, "Built-in table: d3d8x | d3d4x | gl4x")
      ->capture_default_str()
      ->check(CLI::IsMember({"d3d8x", "d3d4x", "gl4x"}));
  cmd->add_option("--table", args->table, "An offset table file (JSON) instead of a built-in table")
      ->excludes("--pattern");
  RsaaSettings& s = args->settings;
  cmd->add_option("--similarity", s.similarity, "sadp-plane | sadp | depth")
      ->capture_default_str()
      ->check(CLI::IsMember({"sadp-plane", "sadp", "depth"}));
  cmd->add_option("--auth", s.auth, "Authentication: 0 none, 1 post-pass, 2 pre-pass")
      ->capture_default_str()
      ->check(whole_range(0, 2));
  cmd->add_option("--code-bits", s.code_bits, "Bits per stored similarity: 8 | 16 | 32")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16, 32}));
  cmd->add_option("--split-cap", args->split_cap, "Ours: cap of the k-means split in thresholds (>= 1); 0 = the paper's")
      ->capture_default_str()
      ->check(finite_range(0.0, 1e30));
  cmd->add_option("--multi-surface", s.multi_surface,
                  "Ours: fetch (the paper) | neighbours (3+ surface pixels) | borrow (as neighbours, colours taken from "
                  "the pixel within two that shows a subsample's surface: with --prepass msaa or records, the GLSL "
                  "files; as neighbours otherwise and in the HLSL)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fetch", "neighbours", "borrow"}));
  cmd->add_option("--borrow-weight", s.borrow_weight,
                  "Ours, with borrow: the mean's share where only a source beyond the 3x3 calls for it, the rest the "
                  "table's fetch; 1 = the mean alone")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--split-check", s.split_check, "Ours: neighbours (subsamples above the threshold) | off (the paper's)")
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "neighbours"}));
  cmd->add_option("--fetch-check", s.fetch_check,
                  "Ours: neighbours (half the offset where no outside pixel shows what a subsample saw) | off (the paper's)")
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "neighbours"}));
  cmd->add_option("--material-edges", args->material_edges,
                  "Ours: on (the pre-pass takes each draw's material; centre_primitive is RG32UI) | off (the paper's)")
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "on"}));
  cmd->add_option("--depth", s.depth,
                  "The engine's depth convention: gl (glClipControl GL_NEGATIVE_ONE_TO_ONE, OpenGL's default) | "
                  "zero-to-one (GL_ZERO_TO_ONE) | reverse-z (GL_ZERO_TO_ONE, nearer is greater)")
      ->capture_default_str()
      ->check(CLI::IsMember({"gl", "zero-to-one", "reverse-z"}));
  s.prepass = "jittered";  // files for one configuration: the engine picks what its driver can do
  cmd->add_option("--prepass", s.prepass,
                  "jittered (one draw per subsample) | msaa (one multisample draw of the table's samples, then the "
                  "record passes; a union or cell pattern's draws need the rsaa::pass library, RsaaPass) | records (one "
                  "draw per subsample writing surface records into the layers of array textures, then the record "
                  "passes: what RsaaPass's auto runs for a pattern the driver cannot sample, 12 bytes a subsample)")
      ->capture_default_str()
      ->check(CLI::IsMember({"jittered", "msaa", "records"}));
  // Within what every GL 4.5 driver has (16 texture units a stage, 84 uniform buffer bindings):
  // the files are for a driver this command does not see.
  cmd->add_option("--first-unit", s.prepass_first_unit,
                  "First of the pre-pass's three texture units (0-13: every GL 4.5 driver has 16 a stage)")
      ->capture_default_str()
      ->check(whole_range(0, 13));
  cmd->add_option("--uniform-binding", s.uniform_binding,
                  "Uniform-buffer binding of the RsaaUniforms block (0-83: every GL 4.5 driver has 84)")
      ->capture_default_str()
      ->check(whole_range(0, 83));
  return [args] { return run_shaders(*args); };
}

}  // namespace rsaa::cli
