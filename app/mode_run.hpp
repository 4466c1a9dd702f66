// One render of frames in one mode (spacetime, frames or brute), and the
// paper's table rows it prints (--stats, --compare) and writes as JSON.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/render_command.hpp"
#include "runtime/scene/scene.hpp"
#include "tracer/counters.hpp"
#include "tracer/frame_estimate.hpp"
#include "tracer/image.hpp"
#include "tracer/ray_query.hpp"

namespace hexant::app {

// What --stats-json records of each frame (keys none of the rows use, so
// a tool that greps one row's name finds the row).
struct FrameRecord {
    int frame = 0;
    double seconds = 0.0;       // rendering it, its file written
    double mean_samples = 0.0;  // samples per pixel, over the frame
    std::optional<tracer::FrameEstimate> estimate;
    int tiles_over_target = 0;  // (adaptive sampling: at the ceiling, above the target)
};

struct ModeRun {
    tracer::Counters counters;
    std::vector<FrameRecord> frames;
};

// The paper's table rows of each column (its name and its counters), with
// a ratio column when there are two.
void print_stats(std::ostream& out,
                 const std::vector<std::pair<std::string, tracer::Counters>>& columns);
// The same rows as JSON, with each frame's time, samples and estimate.
void write_stats_json(const std::string& path,
                      const std::vector<std::pair<std::string, ModeRun>>& columns);

// Where a render's frames stand among all a run renders (for the progress
// line): `done` rendered before them, `total` in all (0: these alone).
struct FramesOf {
    std::size_t done = 0, total = 0;
};

// What is done with each frame as it finishes (its number, its image), in
// order, after its file is written: --video adds it.
using FrameSink = std::function<void(int, const tracer::Image&)>;

// One full render of `frames` of `scene` in one mode; with `write`, each
// frame goes to its file (`pattern`) as it finishes, then to `sink` if set;
// with `keep` it is kept too. With last_use, each of the scene's object records is freed as soon as
// the renderer has made its intelligent objects of it (about 2 KB a parsed
// object, as much as the object: records and objects are never all held at
// once). Estimates go to `err`.
ModeRun render_mode(runtime::SceneDescription& scene, const RenderArguments& args,
                    const Sampling& sampling, tracer::Mode mode, const std::string& pattern,
                    const std::vector<int>& frames, bool write, std::vector<tracer::Image>* keep,
                    bool last_use, std::ostream& err, FramesOf of = {}, const FrameSink& sink = {});

}  // namespace hexant::app
