// GLSL sources embedded in the binary at build time (shaders/*, and the runtime's tables from
// tables/*.glsl), so that the runtime needs no files next to it.
#pragma once

#include <map>
#include <string>

#include "core/offset_table.h"

namespace rsaa::gl {

// Name -> text: "rsaa_common.glsl", "scene.vert", ..., "tables/d3d8x.glsl".
const std::map<std::string, std::string>& embedded_shader_sources();

// A shader's text with every `#include "NAME"` line replaced by NAME's text (once per name).
// Throws std::runtime_error for an unknown name.
std::string shader_source(const std::string& name);

// The baked offset table of a pattern (tables/P.glsl); throws naming the pattern if absent.
std::string table_glsl(const std::string& pattern);
// The same table as data (tables/P.json), parsed and validated.
OffsetTable builtin_offset_table(const std::string& pattern);

}  // namespace rsaa::gl
