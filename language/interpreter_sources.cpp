// The Interpreter's sources and errors: the texts it reads, and where a message points.
// Part of the Interpreter (language/interpreter_state.hpp).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "language/checked_integer.hpp"
#include "language/interpreter.hpp"
#include "language/interpreter_state.hpp"
#include "language/keyword_rules.hpp"
#include "runtime/objects/parameter_check.hpp"
#include "runtime/scene/coincident_faces.hpp"

namespace hexant::language {

// ------------------------------------------------------------------ sources and errors

namespace {

// The newest source of that name (an include read twice is kept twice if
// its text changed in between).
const std::string* newest_source(const std::deque<std::pair<std::string, std::string>>& sources,
                                 const std::string& name) {
    for (auto it = sources.rbegin(); it != sources.rend(); ++it)
        if (it->first == name) return &it->second;
    return nullptr;
}

}  // namespace

const std::string& Interpreter::add_source(const std::string& name, std::string text) {
    // A file included again with the same text shares the kept copy (an
    // #include inside a loop kept one copy a turn). Macros declared in it
    // point into the copy, which is never changed.
    if (const std::string* kept = newest_source(sources_, name); kept != nullptr && *kept == text)
        return *kept;
    sources_.emplace_back(name, std::move(text));
    return sources_.back().second;
}

namespace {

// The line of `text` that starts at `begin`, without its end of line: up
// to a '\n', less a '\r' before it. A bare '\r' ends no line, as the
// reader counts lines (PEGTL's lf_crlf).
std::string_view line_from(const std::string& text, std::size_t begin) {
    std::size_t end = begin;
    while (end < text.size() && text[end] != '\n') ++end;
    if (end > begin && text[end - 1] == '\r') --end;
    return std::string_view(text).substr(begin, end - begin);
}

}  // namespace

ErrorPlace Interpreter::place(const p::position& position, std::string note) const {
    ErrorPlace place{position.source, position.line, position.column, {}, std::move(note)};
    if (const std::string* text = newest_source(sources_, position.source)) {
        std::size_t begin = std::min(position.byte, text->size());
        while (begin > 0 && (*text)[begin - 1] != '\n') --begin;
        place.set_source_line(line_from(*text, begin));
    }
    return place;
}

ErrorPlace Interpreter::place(const runtime::SourcePlace& where, std::string note) const {
    ErrorPlace place{where.file, where.line, where.column, {}, std::move(note)};
    if (const std::string* text = newest_source(sources_, where.file)) {
        // Found by its number: a record keeps its line, not its byte.
        std::size_t begin = 0;
        for (std::size_t line = 1; line < where.line && begin != std::string::npos; ++line) {
            begin = text->find('\n', begin);
            if (begin != std::string::npos) ++begin;
        }
        if (begin != std::string::npos) place.set_source_line(line_from(*text, begin));
    }
    return place;
}

SceneError Interpreter::to_scene_error(const p::parse_error& e) const {
    const auto& positions = e.positions();
    SceneError error(std::string(e.message()),
                     positions.empty() ? ErrorPlace{} : place(positions.front()));
    for (std::size_t i = 1; i < positions.size(); ++i)
        error.add_context(place(positions[i], "from here"));
    return error;
}

std::ostream& Interpreter::messages() const {
    return options.messages ? *options.messages : std::cerr;
}

void Interpreter::warn(const p::position& position, const std::string& message) {
    if (options.strict) fail(position, message + " (an error under --strict)");
    std::string text = position.source + ":" + std::to_string(position.line) + ":" +
                       std::to_string(position.column) + ": warning: " + message;
    say_warning(std::move(text));
}

void Interpreter::say_warning(std::string text) {
    if (options.warnings_said == nullptr || options.warnings_said->insert(text).second)
        messages() << text << "\n";
    scene.warnings.push_back(std::move(text));
}

runtime::Unrendered Interpreter::unrendered(const p::position& where, std::string_view word) const {
    const KeywordRuleEntry* entry = find_keyword_rule(word);
    if (entry == nullptr || entry->rule != KeywordRule::Warned)
        throw std::logic_error("unrendered: '" + std::string(word) +
                               "' is not a word whose rule is to warn");
    return {{where.source, where.line, where.column},
            "'" + std::string(word) +
                "' is read but not rendered as POV-Ray renders it: " + std::string(entry->note)};
}

void Interpreter::not_rendered(const p::position& where, std::string_view word) {
    warn(where, unrendered(where, word).message);
}

void Interpreter::finish_reading([[maybe_unused]] const std::string& name) {
    // POV-Ray 3.7 (parse.cpp, after parsing; its EffectiveLanguageVersion
    // is 3.62 until a #version is read): a scene whose version ends below
    // 3.7 and that sets no assumed_gamma is rendered with no gamma
    // correction at all, and its image files are read undecoded.
    const double effective = version_set ? version : 3.62;
    scene.global.language_version = effective;
    scene.global.legacy_sky = effective < 3.7;
    scene.global.legacy_opacity = effective < 3.7;
    // hexant renders it so (GlobalSettings::gamma_correction); image maps
    // read before the end were decoded as 3.7 decodes them, which POV-Ray
    // does not do for such a scene: warned at each.
    if (effective < 3.7 && !assumed_gamma_set) {
        scene.global.gamma_correction = false;
        for (const p::position& place : image_maps_read)
            warn(place,
                 "this image is decoded to linear light as POV-Ray 3.7 decodes it, but the scene " +
                     std::string(version_set ? "ends with a #version below 3.7"
                                             : "has no #version") +
                     " and sets no assumed_gamma, so POV-Ray reads it undecoded (its legacy "
                     "rule); add `#version 3.7;` and global_settings { assumed_gamma 1 } to "
                     "make them agree");
    }
    report_coincident_faces();
}

void Interpreter::report_coincident_faces() {
    const auto report = runtime::find_coincident_faces(scene.objects, scene.default_texture);
    // "the box at P (part of the union at Q)", or less where they coincide.
    auto named = [](const runtime::CoincidentFaces::Side& side, bool place) {
        std::string text = std::string(side.kind) + (place ? " at " + side.place.to_string() : "");
        if (side.top.to_string() != side.place.to_string())
            text +=
                " (part of the " + std::string(side.top_kind) + " at " + side.top.to_string() + ")";
        return text;
    };
    for (const auto& pair : report.pairs) {
        const bool copies = pair.first.place.to_string() == pair.second.place.to_string();
        std::string message =
            (copies ? "two copies of this " + named(pair.first, false) +
                          (pair.second.top.to_string() != pair.first.top.to_string()
                               ? " and of the " + named(pair.second, false)
                               : std::string())
                    : "this " + named(pair.first, false) + " and the " + named(pair.second, true)) +
            " have flat faces in one plane that overlap: where a ray meets both at once, "
            "rounding decides which it sees, in POV-Ray as in hexant, so the images may differ "
            "there (coincident surfaces); move one apart by a little";
        if (options.strict) {
            SceneError error(message + " (an error under --strict)", place(pair.first.place));
            if (!copies) error.add_context(place(pair.second.place, "the other object"));
            throw error;
        }
        say_warning(pair.first.place.to_string() + ": warning: " + message);
    }
    if (report.more > 0)
        say_warning("warning: " + std::to_string(report.more) +
                    " more pairs of objects have coincident flat faces (the first " +
                    std::to_string(report.pairs.size()) + " are named above)");
}

}  // namespace hexant::language
