// The one kind of error the language reports: a message at a place in a
// scene file, with the chain of places that led there (macro calls,
// #include), formatted as `file:line:column: message`, the source line and a
// caret.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hexant::language {

struct ErrorPlace {
    std::string file;
    std::size_t line = 0;
    std::size_t column = 0;
    std::string
        source_line;   // the text of that line (or of its part around the column), for the caret
    std::string note;  // for the chain: "in macro 'M' called here"
    std::size_t source_first = 0;  // the byte of the line where source_line starts
    bool source_cut = false;       // the line goes on past source_line

    // Keeps `whole_line`, or of a long one (a generated scene's can be
    // megabytes, and a runaway recursion makes hundreds of places on it)
    // the kShownWidth bytes around the column.
    void set_source_line(std::string_view whole_line);
    static constexpr std::size_t kShownWidth = 160;
};

class SceneError : public std::runtime_error {
  public:
    SceneError(std::string message, ErrorPlace place);

    const std::string& message() const { return message_; }
    // The place of the error first, then where it was reached from.
    const std::vector<ErrorPlace>& places() const { return places_; }
    void add_context(ErrorPlace place) { places_.push_back(std::move(place)); }

    // The whole report as printed on stderr.
    std::string formatted() const;

    // Whether the reading stopped under (or at the merging of) a branch on
    // clock, at what hexant cannot make piecewise over the whole
    // animation's time: reading each frame alone (ParseOptions::frame_alone)
    // may succeed.
    bool may_read_frame_by_frame() const { return frame_by_frame_; }
    void set_may_read_frame_by_frame() { frame_by_frame_ = true; }

  private:
    bool frame_by_frame_ = false;
    std::string message_;
    std::vector<ErrorPlace> places_;
};

}  // namespace hexant::language
