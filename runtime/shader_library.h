// GLSL sources and the built-in tables (shaders/*, tables/*.json) embedded in the binary at build
// time, so that the runtime needs no files next to it.

#pragma once

#include <map>
#include <string>

#include "core/rsaa/offset_table.h"

namespace rsaa::gl {

// Name -> text: "rsaa_common.glsl", "scene.vert", ..., "tables/d3d8x.json".
const std::map<std::string, std::string>& embedded_shader_sources();

// A shader's text with every `#include "NAME"` line replaced by NAME's text (once per name).
// Throws std::runtime_error for an unknown name.
std::string shader_source(const std::string& name);

// The built-in offset table of a pattern (tables/P.json, embedded), parsed and validated.
OffsetTable builtin_offset_table(const std::string& pattern);

}  // namespace rsaa::gl
