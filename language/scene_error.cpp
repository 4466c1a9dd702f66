#include "language/scene_error.hpp"

#include <algorithm>
#include <sstream>

namespace hexant::language {

namespace {

std::string header(const ErrorPlace& place) {
    if (place.line == 0) return place.file;  // a place outside any file (the command line)
    return place.file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column);
}

// The first byte of a line of `size` bytes to show so that `column` (1 is
// the first byte) lies in the kShownWidth shown: the line's start, or a
// window with the column near its middle.
std::size_t shown_first(std::size_t size, std::size_t column) {
    constexpr std::size_t w = ErrorPlace::kShownWidth;
    if (size <= w || column <= w / 2) return 0;
    return std::min(column - 1 - w / 2, size - w);
}

// The source line with a caret under the column (tabs kept so it lines up),
// cut ends marked "...".
void caret(std::ostringstream& out, const ErrorPlace& place) {
    if (place.line == 0) return;  // no place in a file (e.g. an unreadable scene)
    const std::string& line = place.source_line;
    // The column within source_line (1 its first byte).
    const std::size_t column =
        place.column > place.source_first ? place.column - place.source_first : 1;
    const std::size_t first = shown_first(line.size(), column);
    const std::string shown = line.substr(first, ErrorPlace::kShownWidth);
    const char* const before = place.source_first + first > 0 ? "..." : "";
    const bool cut = place.source_cut || first + shown.size() < line.size();
    out << "    " << before << shown << (cut ? "..." : "") << "\n    " << before;
    for (std::size_t i = first + 1; i < column && i <= first + shown.size(); ++i)
        out << (line[i - 1] == '\t' ? '\t' : ' ');
    out << "^\n";
}

}  // namespace

void ErrorPlace::set_source_line(std::string_view whole_line) {
    const std::size_t first = shown_first(whole_line.size(), std::max<std::size_t>(column, 1));
    source_line = std::string(whole_line.substr(first, kShownWidth));
    source_first = first;
    source_cut = first + source_line.size() < whole_line.size();
}

SceneError::SceneError(std::string message, ErrorPlace place)
    : std::runtime_error(header(place) + ": " + message), message_(std::move(message)) {
    places_.push_back(std::move(place));
}

std::string SceneError::formatted() const {
    std::ostringstream out;
    out << header(places_.front()) << ": error: " << message_ << "\n";
    caret(out, places_.front());
    // A runaway recursion reaches its error through thousands of calls: the
    // first and last few say where it went; the middle repeats them.
    constexpr std::size_t kShown = 10;
    for (std::size_t i = 1; i < places_.size(); ++i) {
        if (places_.size() > 2 * kShown + 1 && i == kShown + 1) {
            const std::size_t skipped = places_.size() - 1 - 2 * kShown;
            out << "... " << skipped << " more places like these ...\n";
            i += skipped - 1;
            continue;
        }
        out << header(places_[i]) << ": note: " << places_[i].note << "\n";
        caret(out, places_[i]);
    }
    return out.str();
}

}  // namespace hexant::language
