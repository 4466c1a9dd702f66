// Renders frames of an animation: for each pixel, spp samples stratified
// jointly over the pixel, the frame's shutter interval (runtime::Animation::
// frame_window), the lens and the area lights (tracer/sample_pattern.hpp),
// each traced as a 4D ray at its own time. Tiles run in
// parallel with oneTBB; each thread keeps its own mailbox and counters,
// merged when the frame is done.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <tbb/global_control.h>

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "tracer/counters.hpp"
#include "tracer/frame_estimate.hpp"
#include "tracer/image.hpp"
#include "tracer/ray_query.hpp"
#include "tracer/shader.hpp"

namespace hexant::tracer {

struct RenderSettings {
    Mode mode = Mode::Spacetime;
    int samples_per_pixel = 1;
    bool jitter = true;
    // 0: the samples every render of this frame uses; another number gives
    // independent scrambles (an independent estimate of the same image).
    std::uint32_t sample_seed = 0;
    // With 2 or more jittered samples per pixel, each frame comes with an
    // estimate of its error from its samples' own blocks
    // (tracer/block_estimate.hpp, tracer/frame_estimate.hpp), at no cost
    // to the image.
    //
    // > 0: adaptive sampling (needs the estimate) to this RMSE per frame
    // (linear light, over its pixels and channels), samples_per_pixel
    // being the ceiling: every pixel starts with kFirstRoundSamples, then
    // rounds give each pixel the count that meets the target in the least
    // work, from the estimates and each pixel's counted work
    // (tracer/frame_sampling.hpp). The rounds depend on the samples only,
    // so images do not depend on the thread count.
    double target_error = 0.0;
    static constexpr int kFirstRoundSamples = 4;
    // The speed of light in scene units per clock unit (light_travel.hpp):
    // infinite, the default, is instant light. Positive; the constructor
    // throws std::invalid_argument otherwise.
    double light_speed = std::numeric_limits<double>::infinity();
    // Radiosity by one gathering ray per sample and bounce (--gi path)
    // instead of the frame's irradiance cache.
    bool gi_path = false;
    BuildOptions build;
    // 0: as many as the machine has; else the most threads any part of the
    // renderer uses, from its construction (the sweeps, an eager build) to
    // its end.
    int threads = 0;
    // Told, from a worker thread and one call at a time, each time a tile
    // of a frame is done: the frame, the fraction of its tiles done, and
    // the samples (primary rays) the frame has taken so far.
    std::function<void(int frame, double fraction, std::uint64_t samples)> progress;
    // The frames that will be rendered, first and last (0: the animation's
    // own). The spacetime hierarchy spans their time only: rendering one
    // frame of a long animation builds for that frame's time, not for the
    // whole animation. render_frame() refuses frames outside.
    int first_frame = 0, last_frame = 0;
};

class Renderer {
  public:
    // Builds the objects (the scene's records into intelligent objects) and,
    // in spacetime mode, the one hierarchy over the whole animation.
    Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings);
    // The same, letting go of each object record (scene.objects ends empty)
    // as soon as its intelligent objects are made, so that the records and
    // the objects are never all held at once: a parsed sphere's record is
    // about 2 KB, its intelligent object about as much.
    struct ReleaseRecords {};
    Renderer(runtime::SceneDescription& scene, const RenderSettings& settings, ReleaseRecords);
    ~Renderer();

    // Frame numbers as the animation counts them (initial_frame ..), within
    // the settings' first and last frame; std::out_of_range otherwise.
    Image render_frame(int frame);
    // With 2 or more jittered samples: the last frame's estimate of its
    // error, and per pixel its estimated squared error averaged over the
    // channels (linear light, rows top to bottom); none otherwise.
    const std::optional<FrameEstimate>& last_estimate() const { return last_estimate_; }
    const std::vector<double>& last_squared_error() const { return last_squared_; }
    // The samples each pixel of the last frame took (rows top to bottom)
    // and their sum.
    const std::vector<int>& last_samples() const { return last_samples_; }
    std::uint64_t last_sample_count() const { return last_sample_count_; }
    // With a target error: the last frame's tiles that reached the ceiling
    // (samples_per_pixel) still above the target, and all its tiles.
    int last_tiles_over_target() const { return last_tiles_over_target_; }
    int last_tile_count() const { return last_tile_count_; }

    const Counters& counters() const { return counters_; }
    // Statistics: the cells a full build of the hierarchy in use makes
    // (counters().cells_full; RayQuery::count_full_hierarchy).
    void count_full_hierarchy() { query_->count_full_hierarchy(counters_); }
    // Records the memory the hierarchy and sweeps take now (Counters).
    void measure_memory() { query_->measure_memory(counters_); }
    const runtime::Box4& root() const { return root_; }

  private:
    using Records = std::vector<std::shared_ptr<const runtime::ObjectRecord>>;
    Renderer(const runtime::SceneDescription& scene, const RenderSettings& settings,
             Records* release);

    // settings.threads (when set) bounds every parallel part, the sweeps
    // and an eager build in the constructor as well as the frames: held
    // from the first member made to the renderer's end.
    std::unique_ptr<tbb::global_control> thread_limit_;
    const runtime::SceneDescription& scene_;
    RenderSettings settings_;
    std::vector<runtime::IntelligentObjectPtr> objects_;
    // The objects that matter to a camera ray that starts inside them
    // (Shader::matters_to_camera); each frame hands the shader those its
    // eye may lie in.
    std::vector<const runtime::IntelligentObject*> camera_mattering_;
    runtime::Box4 root_;
    // Light of finite speed: how far back a frame's light reaches and the
    // earliest instant any does (the root's).
    double lookback_ = 0.0, floor_ = 0.0;
    LightTravel travel_;
    int first_frame_, last_frame_;
    Counters counters_;
    std::optional<FrameEstimate> last_estimate_;
    std::vector<double> last_squared_;
    std::vector<int> last_samples_;
    std::uint64_t last_sample_count_ = 0;
    int last_tiles_over_target_ = 0, last_tile_count_ = 0;
    std::unique_ptr<RayQuery> query_;
    std::unique_ptr<Shader> shader_;
    // The camera's normal { }, when it has one (runtime/scene/camera.hpp).
    std::optional<runtime::TextureEvaluator> camera_normal_;
};

}  // namespace hexant::tracer
