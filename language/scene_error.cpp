#include "language/scene_error.hpp"

#include <algorithm>
#include <sstream>

namespace hexant::language {

namespace {

std::string header(const ErrorPlace& place) {
    if (place.line == 0) return place.file;  // a place outside any file (the command line)
    return place.file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column);
}

bool continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// The first byte of `line` to show so that `column` (1 is the first byte)
// lies in the kShownWidth shown: the line's start, or a window with the
// column near its middle; never inside a UTF-8 character.
std::size_t shown_first(std::string_view line, std::size_t column) {
    constexpr std::size_t w = ErrorPlace::kShownWidth;
    if (line.size() <= w || column <= w / 2) return 0;
    std::size_t first = std::min(column - 1 - w / 2, line.size() - w);
    while (first < line.size() && continuation(line[first])) ++first;
    return first;
}

// The end of the window from `first`: at most kShownWidth bytes, never
// inside a UTF-8 character.
std::size_t shown_end(std::string_view line, std::size_t first) {
    std::size_t end = std::min(line.size(), first + ErrorPlace::kShownWidth);
    while (end > first && end < line.size() && continuation(line[end])) --end;
    return end;
}

// The source line with a caret under the column (tabs kept so it lines up,
// one space a character, not a byte), cut ends marked "..." and control
// characters (a bare carriage return, a NUL, an escape) shown as '?', so
// that nothing in a scene can move the terminal's cursor or colour it.
void caret(std::ostringstream& out, const ErrorPlace& place) {
    if (place.line == 0) return;  // no place in a file (e.g. an unreadable scene)
    const std::string_view line = place.source_line;
    // The column within source_line (1 its first byte).
    const std::size_t column =
        place.column > place.source_first ? place.column - place.source_first : 1;
    const std::size_t first = shown_first(line, column);
    const std::size_t end = shown_end(line, first);
    const char* const before = place.source_first + first > 0 ? "..." : "";
    out << "    " << before;
    for (std::size_t i = first; i < end; ++i) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        out << ((c < 0x20 && c != '\t') || c == 0x7F ? '?' : line[i]);
    }
    out << (place.source_cut || end < line.size() ? "..." : "") << "\n    " << before;
    for (std::size_t i = first + 1; i < column && i <= end; ++i) {
        if (continuation(line[i - 1])) continue;
        out << (line[i - 1] == '\t' ? '\t' : ' ');
    }
    out << "^\n";
}

}  // namespace

void ErrorPlace::set_source_line(std::string_view whole_line) {
    const std::size_t first = shown_first(whole_line, std::max<std::size_t>(column, 1));
    const std::size_t end = shown_end(whole_line, first);
    source_line = std::string(whole_line.substr(first, end - first));
    source_first = first;
    source_cut = end < whole_line.size();
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
