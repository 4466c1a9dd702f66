// The one kind of error the language reports: a message at a place in a
// scene file, with the chain of places that led there (macro calls,
// #include), formatted as `file:line:column: message`, the source line and a
// caret.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexant::language {

struct ErrorPlace {
    std::string file;
    std::size_t line = 0;
    std::size_t column = 0;
    std::string source_line;  // the text of that line, for the caret
    std::string note;         // for the chain: "in macro 'M' called here"
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

private:
    std::string message_;
    std::vector<ErrorPlace> places_;
};

}  // namespace hexant::language
