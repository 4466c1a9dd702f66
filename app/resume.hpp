// `render --resume`: which frames already on disk a render keeps and which
// it renders again (README, "Resuming"). Checked (the default), a frame is
// kept only when its record (app/frame_record.hpp) says this very render
// made it: the same scene and files, the same settings, the very bytes
// written. --resume=keep is POV-Ray's +C: any readable frame of the
// frame's size is kept, with a note for those made otherwise.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/frame_record.hpp"
#include "app/render_command.hpp"
#include "runtime/scene/animation.hpp"

namespace hexant::app {

// At most this many frames rendered again are named one by one on stderr;
// the rest are counted on one line.
inline constexpr std::size_t kResumeLinesShown = 10;

struct ResumeCheck {
    std::vector<int> missing;  // the frames to render, in increasing order
};

// Removes what a killed run left half-written (the temporaries of the
// selected frames, of their records and of --video), then sorts the
// selected frames of `pattern` into those kept and those to render: each
// frame rendered again is said on `err` with why ("frame 3 (out/a3.png)
// rendered again: it was made at 64x48, this render is 32x24"), the first
// differences only. A frame kept whose --error-image or --samples-image
// file is not on disk is rendered again too (those come only from a
// render). `inputs`: the files this render's scene read (null
// when the scene is read frame by frame).
ResumeCheck resume_check(const RenderArguments& args, const std::string& pattern,
                         const std::vector<int>& selected, const runtime::Animation& animation,
                         FrameRecords& records, const FrameRecords::ReadFiles* inputs,
                         std::ostream& err);

}  // namespace hexant::app
