#include "language/scene_error.hpp"

#include <sstream>

namespace hexant::language {

namespace {

std::string header(const ErrorPlace& place) {
    if (place.line == 0) return place.file;  // a place outside any file (the command line)
    return place.file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column);
}

// The source line with a caret under the column (tabs kept so it lines up).
void caret(std::ostringstream& out, const ErrorPlace& place) {
    if (place.line == 0) return;  // no place in a file (e.g. an unreadable scene)
    out << "    " << place.source_line << "\n    ";
    for (std::size_t i = 1; i < place.column && i <= place.source_line.size(); ++i)
        out << (place.source_line[i - 1] == '\t' ? '\t' : ' ');
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
