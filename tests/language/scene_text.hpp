// Reading scene text in the language tests: the error a text gives, or
// that it reads. Its #debug and #warning output is kept out of the test's.
#pragma once

#include <optional>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"

namespace hexant::test {

// Frames 1 to 8 over clock 0 to 1 (the shutter of the last one ends at 8/7:
// placed as it opens, not cut to Final_Clock, so that the language's rules
// are seen past the last frame's clock too).
inline language::ParseOptions animation() {
    language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 8;
    options.animation.shutter_beyond_range = true;
    return options;
}

// The error reading `text` (as the file `name`) gives, or nothing.
inline std::optional<language::SceneError> read_error(const std::string& text,
                                                      language::ParseOptions options = {},
                                                      const std::string& name = "test.pov") {
    std::ostringstream messages;
    options.messages = &messages;
    try {
        language::parse_scene_text(text, name, options);
    } catch (const language::SceneError& e) {
        return e;
    }
    return std::nullopt;
}

// The error of `text`; a failed test when it reads.
inline language::SceneError error_of(const std::string& text, language::ParseOptions options = {},
                                     const std::string& name = "test.pov") {
    auto e = read_error(text, std::move(options), name);
    if (!e) FAIL("expected an error");
    return *e;
}

// The scene `text` reads into (its messages kept out of the test's).
inline runtime::SceneDescription scene_of(const std::string& text,
                                          language::ParseOptions options = {}) {
    std::ostringstream messages;
    options.messages = &messages;
    return language::parse_scene_text(text, "test.pov", options);
}

// That `text` is refused at `line` with a message holding `words`.
inline void check_error_at(const std::string& text, const char* words, std::size_t line) {
    const auto e = error_of(text);
    INFO(e.formatted());
    CHECK(e.places().front().line == line);
    CHECK(e.formatted().find(words) != std::string::npos);
}

// A failed test, with the error, unless `text` reads.
inline void reads(const std::string& text, language::ParseOptions options = {}) {
    const auto e = read_error(text, std::move(options));
    if (e) FAIL(e->formatted());
}

}  // namespace hexant::test
