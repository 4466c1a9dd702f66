// A scene read for rendering. Most scenes are read once for the whole
// animation, one spacetime hierarchy over every frame (the paper's method).
// A scene whose reading of the whole stops at what hexant cannot make
// piecewise in time, under a branch on clock (POV-Ray's way of carrying
// state from frame to frame: arrays advanced in a #while up to
// frame_number), is read again once per frame, as POV-Ray reads it:
// frame_number is then a constant and clock still runs through the frame's
// shutter, so what moves is blurred; where even one frame's shutter holds
// what cannot be made piecewise, that frame is read at its clock
// alone, clock a constant, as POV-Ray reads it (a warning names the frame).
#pragma once

#include <iosfwd>
#include <optional>
#include <set>
#include <string>

#include "app/command_line.hpp"
#include "runtime/scene/scene.hpp"

namespace hexant::app {

class SceneReading {
  public:
    // Reads the scene (warnings and notes to `err`); language::SceneError
    // for an error the frame-by-frame reading cannot pass, reported at its
    // place, as parse_scene_file.
    SceneReading(const ResolvedScene& resolved, std::ostream& err);
    SceneReading(const SceneReading&) = delete;
    SceneReading& operator=(const SceneReading&) = delete;

    // The scene read whole, or read for the first frame (what every frame
    // shares: the animation, the image's size, the global settings; its
    // messages unsaid: read_frame says them).
    runtime::SceneDescription& scene() { return scene_; }
    bool frame_by_frame() const { return why_.has_value(); }
    // Frame `frame` read alone (frame by frame); language::SceneError with
    // a note naming the frame when it cannot be read.
    runtime::SceneDescription read_frame(int frame);

  private:
    // Frame `frame` read alone; none when it stopped at a branch on clock
    // (never at_clock: then it throws). Its messages go to `messages`
    // when given.
    std::optional<runtime::SceneDescription> try_frame(int frame, bool at_clock,
                                                       std::ostream* messages = nullptr);

    language::ParseOptions options_;
    std::filesystem::path file_;
    std::ostream& err_;
    std::set<std::string> warnings_said_;
    std::optional<std::string> why_;  // the whole reading's error, where it stopped
    runtime::SceneDescription scene_;
};

}  // namespace hexant::app
