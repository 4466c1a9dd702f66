#include "app/scene_reading.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "language/interpreter.hpp"
#include "language/scene_error.hpp"

namespace hexant::app {

namespace {

// On a terminal, a line on stderr while a long reading runs, wiped when
// the reading ends (ParseOptions::progress).
class ReadingLine {
  public:
    explicit ReadingLine(language::ParseOptions& options, const std::filesystem::path& file) {
        if (!isatty(STDERR_FILENO)) return;
        options.progress = [width = width_, name = file.filename().string()](
                               const language::ParseOptions::Progress& p) {
            char line[200];
            std::snprintf(line, sizeof line,
                          "\rreading %.60s: %.0f s, %llu loop turns and macro calls, %llu "
                          "objects, %llu triangles ",
                          name.c_str(), p.seconds, static_cast<unsigned long long>(p.steps),
                          static_cast<unsigned long long>(p.objects),
                          static_cast<unsigned long long>(p.triangles));
            std::cerr << line << std::flush;
            *width = std::max(*width, std::strlen(line));
        };
    }
    ReadingLine(const ReadingLine&) = delete;
    ReadingLine& operator=(const ReadingLine&) = delete;
    ~ReadingLine() {
        if (*width_) std::cerr << "\r" << std::string(*width_, ' ') << "\r" << std::flush;
    }

  private:
    std::shared_ptr<std::size_t> width_ = std::make_shared<std::size_t>(0);
};

}  // namespace

SceneReading::SceneReading(const ResolvedScene& resolved, std::ostream& err)
    : options_(resolved.options), file_(resolved.scene), err_(err) {
    // What the whole reading says (#debug, warnings) is said when it
    // stands; read frame by frame, each frame's reading says it.
    std::ostringstream said;
    language::ParseOptions whole = options_;
    whole.messages = &said;
    std::ostream& messages = options_.messages ? *options_.messages : std::cerr;
    options_.warnings_said = &warnings_said_;
    try {
        const ReadingLine line(whole, file_);
        scene_ = language::parse_scene_file(file_, whole);
        messages << said.str();
        return;
    } catch (const language::SceneError& e) {
        if (!e.may_read_frame_by_frame()) {
            messages << said.str();
            throw;
        }
        const language::ErrorPlace& at = e.places().front();
        why_ = at.file + ":" + std::to_string(at.line) + ": " + e.message();
        // The first frame, for what every frame shares (read_frame says
        // what it says, when it is read for its render).
        std::ostringstream unsaid;
        const int first = options_.animation.initial_frame;
        std::optional<runtime::SceneDescription> scene = try_frame(first, false, &unsaid);
        if (!scene) scene = try_frame(first, true, &unsaid);  // (throws when it cannot)
        scene_ = std::move(*scene);
        err_ << "note: " << file_.string()
             << " is read frame by frame, as POV-Ray reads it (each frame its own hierarchy, "
                "blurred within its shutter): read over the whole animation it stopped at "
             << *why_ << "\n";
    }
}

std::optional<runtime::SceneDescription> SceneReading::try_frame(int frame, bool at_clock,
                                                                 std::ostream* messages) {
    language::ParseOptions options = options_;
    options.frame_alone = language::ParseOptions::FrameAlone{frame, at_clock};
    if (messages) {
        options.messages = messages;
        options.warnings_said = nullptr;
    }
    try {
        const ReadingLine line(options, file_);
        return language::parse_scene_file(file_, options);
    } catch (const language::SceneError& e) {
        if (!e.may_read_frame_by_frame() || at_clock) throw;
        return std::nullopt;
    }
}

runtime::SceneDescription SceneReading::read_frame(int frame) {
    try {
        if (auto scene = try_frame(frame, false)) return std::move(*scene);
        auto scene = try_frame(frame, true);
        err_ << "warning: frame " << frame
             << ": its shutter holds what hexant cannot make piecewise in time; the frame is "
                "read at its clock alone, as POV-Ray reads it (clock a constant: "
                "nothing in this frame is blurred by motion)\n";
        return std::move(*scene);
    } catch (language::SceneError& e) {
        e.add_context(language::ErrorPlace{
            file_.string(), 0, 0, {}, "reading frame " + std::to_string(frame) + " alone"});
        throw;
    }
}

}  // namespace hexant::app
