// Internal: glslang's info log ("ERROR: file:12: 'token' : message") turned into tierlift's
// diagnostics (file:line:col, the source line, a caret).
#pragma once

#include <string>
#include <string_view>

namespace tierlift::glsl {

// Every ERROR and WARNING line of `log` positioned in `source`; lines glslang adds without
// a position ("compilation terminated", "N compilation errors") are dropped when a
// positioned one exists, else kept as "file: error: …". Never empty.
std::string render_glslang_log(std::string_view log, const std::string& source,
                               const std::string& file_name);

// One error at the first declaration of `name` (a line holding "uniform" and the name), or at
// line 1 when none is found.
std::string render_at_name(const std::string& name, const std::string& message,
                           const std::string& source, const std::string& file_name);

} // namespace tierlift::glsl
