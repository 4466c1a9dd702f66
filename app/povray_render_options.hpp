// POV-Ray's rendering options (language/povray_options.hpp) as `render`'s
// own flags: the frames' names (+O, +F), the frames (+SF, +EF, +STP),
// resuming (+C), the sampling (+A, +AM, +R, +J), the threads (+WT), and
// notes for what hexant does otherwise (+D, +Q). The hexant flags given
// win: each POV-Ray option fills only what they leave unsaid, and is the
// last given of its kind (switches and .ini files apply in the order of
// the command line). Meanings: POV-Ray 3.7's reference, section 3.2.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.hpp"
#include "app/render_command.hpp"
#include "runtime/scene/animation.hpp"

namespace hexant::app {

// `arguments` with the POV-Ray options of `resolved` applied; `notes` gets
// a line for each option that hexant maps rather than takes as it is, or
// that a flag overrides. -A (no antialiasing) also closes the shutter of
// `resolved`'s animation unless --shutter was given: one ray at the
// frame's clock, as POV-Ray's. Throws std::runtime_error naming the switch
// or option and its place for one hexant cannot honour (-F, +FN16, an +EF
// past Final_Frame, +O-).
RenderArguments with_povray_options(const RenderArguments& arguments, ResolvedScene& resolved,
                                    std::vector<std::string>& notes);

// POV-Ray 3.7's names for the frames (frontend/imageprocessing.cpp,
// GetOutputFilename), as a pattern of hexant's (#### the frame number):
// `name` without the type's extension (`extension`, compared in its case)
// or a final '.', then in an animation the frame number in as many digits
// as the last frame has (counted one frame more when cyclic, as POV-Ray
// counts them), then the extension: out/a.png over frames 1 to 4 is
// out/a#.png, a1.png to a4.png. A `name` that is a folder (ending in /),
// or the extension alone, takes the scene's name. A name that already
// holds # is a pattern of hexant's and is kept as it is.
std::string povray_frame_pattern(const std::filesystem::path& name, const std::string& extension,
                                 const runtime::Animation& animation,
                                 const std::filesystem::path& scene);

// The frames POV-Ray 3.7 renders for Subset_Start_Frame, Subset_End_Frame
// and Frame_Step (frontend/animationprocessing.cpp), as --frames takes
// them ("A:B", or a comma list with a step); none when none is set. A
// subset value below 1 (and above 0) is a fraction of the frames (+SF0.5:
// from the middle on), counted one more in a cyclic animation as POV-Ray
// counts them. std::runtime_error naming the option when the subset runs
// past the animation's last frame (POV-Ray runs its clock on past
// Final_Clock there) or Frame_Step is below 1.
std::optional<std::string> povray_frames(const language::PovRaySettings& settings,
                                         const runtime::Animation& animation);

// `check` and `dump` render nothing: one note naming the render options
// given, if any.
void note_render_only(const ResolvedScene& resolved, const std::string& command, std::ostream& err);

}  // namespace hexant::app
