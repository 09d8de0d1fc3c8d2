// A listing's version line found in its text, for telling listings from other files (case
// discovery) and Direct3D 10's shader models from ours (the parse stage's "unsupported").
#pragma once

#include <optional>
#include <string_view>

namespace tierlift::corpus {

// The major version digit ('1'..'9') of the first version line of `text`: at the start of a
// line, after blanks, vs or ps, '.' or '_', a digit, '.' or '_', then a digit, x, s or w
// ("ps_2_0", "vs.1.1", "ps_2_x", "PS_3_SW", "ps_4_0"), in any case. Scanned by hand: std::regex
// took most of the time of finding 2,000 listings in a folder.
std::optional<char> version_line_major(std::string_view text);

} // namespace tierlift::corpus
