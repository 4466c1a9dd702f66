// `hexant merge-stats`: the statistics of an animation rendered in windows
// (render --window I/N --stats-json, one file per window) as one run's:
// counts and times summed over the windows (times are then CPU-seconds of
// the windows together, not wall time), memory the largest window's, the
// per-ray and per-second rows recomputed from the sums, every window's
// frames in order, and a "per window" list of each window's frames and
// build, sweep, lazy-build and render times: what a window costs (its own
// build) beside what it renders.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace hexant::app {

// Reads the windows' JSON files (in window order) and writes the merged
// JSON to `output` whole. std::runtime_error naming the file that cannot
// be read, is not hexant's statistics, or holds another mode than the rest.
void merge_stats(const std::vector<std::string>& windows, const std::string& output);

// The CLI: `hexant merge-stats WINDOW.json ... -o MERGED.json`.
int run_merge_stats(const std::vector<std::string>& windows, const std::string& output,
                    std::ostream& out, std::ostream& err);

}  // namespace hexant::app
