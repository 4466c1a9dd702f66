// What made each frame, recorded beside it, so that `render --resume` keeps
// only frames this very render would write (issue 46: POV-Ray's +C keeps
// any file at a frame's name, and a resumed animation mixed two renders).
//
// A frame's record is a small JSON file of its own, FOLDER/.hexant/NAME.json
// for the frame FOLDER/NAME, written whole (tracer::TemporaryFile) after the
// frame's file: the hexant version, every setting that changes the pixels
// (render_settings), the frame's number and clock, the size and SHA-256 of
// the frame's file and of every file its scene read (the scene, includes,
// images, fonts, #fopen'd data). One file per frame has one writer, the run
// that rendered the frame: windows of a farm writing on different nodes at
// once never write the same record, so none is lost or merged, and no lock
// is needed (README, "Resuming").
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "app/render_command.hpp"
#include "app/sha256.hpp"
#include "language/interpreter.hpp"
#include "runtime/scene/animation.hpp"

namespace hexant::app {

// The record of the frame file `frame_file`: FOLDER/.hexant/NAME.json.
std::filesystem::path frame_record_path(const std::filesystem::path& frame_file);

// One thing that changes a frame's pixels, as the record names it (a key)
// and its value in words ("64x48", "0.25", "box").
struct PixelSetting {
    std::string key, value;
};

// The settings of a render that change its frames' pixels, alike for every
// frame: hexant's version, the image's size, the animation's frames, clock
// and shutter, the sampling (after POV-Ray's +A options and the scene's
// motion_blur are applied: the resolved values, not the flags), the speed
// of light, the Declare= values and the language version. Left out because
// they change no pixel: the threads, the mode and the hierarchy's flags
// (tests/tracer/build_modes_test.cpp: equal bit for bit), --window and
// --frames, the statistics, the limits (they stop a scene, never change
// it), the outputs' names.
std::vector<PixelSetting> render_settings(const Sampling& sampling, const RenderArguments& args,
                                          const runtime::Animation& animation,
                                          const language::ParseOptions& options);

// The records of one render's frames: writes them, and tells why a frame on
// disk is not this render's.
class FrameRecords {
  public:
    // `scene`: the scene file; the paths of files inside its folder are
    // recorded relative to it (a project moved whole keeps its frames).
    FrameRecords(std::vector<PixelSetting> settings, const runtime::Animation& animation,
                 const std::filesystem::path& scene);

    // The files a reading read, each as the record names it and with its
    // hash: taken right after the reading, so that a file edited while the
    // frames render is not recorded as what made them.
    struct ReadFile {
        std::string name;
        FileHash hash;
    };
    using ReadFiles = std::vector<ReadFile>;
    // `inputs`: canonical, the scene first (SceneDescription::inputs).
    // std::runtime_error naming a file that cannot be read.
    ReadFiles hash_inputs(const std::vector<std::filesystem::path>& inputs);

    // Writes frame `frame`'s record, once its file `file` is written whole;
    // `inputs`: what the reading that made it read. std::runtime_error
    // naming the file when it cannot be written.
    void write(int frame, const std::filesystem::path& file, const ReadFiles& inputs);

    // Why the frame file `file` (frame `frame`) is not what this render
    // would write, in words, the most telling first ("it was made at 64x48,
    // this render is 32x24"); empty when its record matches this render and
    // the file is the very one recorded. `inputs`: what this render's scene
    // read, compared both ways; null when unknown (a scene read frame by
    // frame: each frame's files are the record's own, read again now).
    // Never throws for a missing, damaged or foreign record: that is a
    // reason too.
    std::vector<std::string> differences(int frame, const std::filesystem::path& file,
                                         const ReadFiles* inputs);

  private:
    // A file's size and hash, read once per run while its size and time
    // stay the same.
    FileHash hash(const std::filesystem::path& path);
    // How the record names an input: relative to the scene's folder inside
    // it, else absolute.
    std::string input_name(const std::filesystem::path& path) const;
    std::filesystem::path input_path(const std::string& name) const;
    std::vector<PixelSetting> frame_settings(int frame) const;

    std::vector<PixelSetting> settings_;
    runtime::Animation animation_;
    std::filesystem::path folder_;  // the scene's, canonical
    struct Cached {
        std::uintmax_t bytes = 0;
        std::filesystem::file_time_type time;
        FileHash hash;
    };
    std::map<std::filesystem::path, Cached> hashes_;
};

// hexant's version, as the records hold it.
std::string hexant_version();

}  // namespace hexant::app
