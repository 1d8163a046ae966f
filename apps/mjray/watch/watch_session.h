#pragma once
/// mjray --watch: serve the live page, render the scene progressively, and render it again
/// whenever the script or a file it read changes, until Ctrl-C.

#include "mjray/job/run_options.h"

namespace mjray {

/// Runs the watch loop for `options` (report.watch set) and returns the exit code:
/// 0 when Ctrl-C ends it between renders, 130 when it interrupts a render (the partial image
/// and its state are written, as without --watch); while the script runs or a frame is
/// prepared, Ctrl-C ends the process at once with 130. Throws OutputError when the page cannot
/// be served.
int run_watch_session(const RunOptions& options);

}  // namespace mjray
