#include "language/scene_error.hpp"

#include <algorithm>
#include <sstream>

namespace hexant::language {

namespace {

std::string header(const ErrorPlace& place) {
    if (place.line == 0) return place.file;  // a place outside any file (the command line)
    return place.file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column);
}

// The source line with a caret under the column (tabs kept so it lines up).
// A long line (a generated scene's can be megabytes) is shown as the
// kShownWidth bytes around the column, cut ends marked "...".
void caret(std::ostringstream& out, const ErrorPlace& place) {
    if (place.line == 0) return;  // no place in a file (e.g. an unreadable scene)
    constexpr std::size_t kShownWidth = 160;
    const std::string& line = place.source_line;
    const std::size_t column = std::max<std::size_t>(place.column, 1);
    std::size_t first = 0;  // the first byte shown
    if (line.size() > kShownWidth && column > kShownWidth / 2)
        first = std::min(column - 1 - kShownWidth / 2, line.size() - kShownWidth);
    const std::string shown = line.substr(first, kShownWidth);
    const char* const before = first > 0 ? "..." : "";
    out << "    " << before << shown << (first + shown.size() < line.size() ? "..." : "") << "\n    "
        << before;
    for (std::size_t i = first + 1; i < column && i <= first + shown.size(); ++i)
        out << (line[i - 1] == '\t' ? '\t' : ' ');
    out << "^\n";
}

}  // namespace

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
