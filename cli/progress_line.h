// Progress of a long `--frames` run: one line on standard error, updated in place, only when
// standard error is a terminal (a log or a pipe gets nothing) and the command prints text
// (not -q, not --json).
#pragma once

#include <string>

#include "tierlift/effects/graph/run_graph.h"

namespace tierlift::cli {

// Whether the running command shows progress at all (glow: neither -q nor --json).
void set_frame_progress(bool enabled);

// "[glow] DEVICE: frame 12/300", rewritten at most ten times a second and erased after the
// last frame; empty (no progress) unless enabled and standard error is a terminal.
effects::FrameProgress frame_progress_line(const std::string& device);

} // namespace tierlift::cli
