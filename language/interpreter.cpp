// The reader's entry points, which run the grammar and its actions over a
// scene file; the Interpreter's other parts are interpreter_*.cpp.
#include "language/interpreter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "language/actions.hpp"
#include "language/checked_integer.hpp"
#include "language/interpreter_state.hpp"
#include "language/source_files.hpp"
#include "runtime/objects/parameter_check.hpp"

namespace hexant::language {

Interpreter::Interpreter(const ParseOptions& options_in, runtime::SceneDescription& scene_in,
                         std::filesystem::path scene_folder)
    : symbols(std::make_shared<MemoryBudget>(options_in.limits.array_memory)),
      scene(scene_in),
      options(options_in),
      scene_folder_(std::move(scene_folder)) {
    // POV-Ray 3.7 (Scene::StartParser): the version in hundredths, from
    // 1.0 to 100.0, and set as a #version sets it.
    if (options.language_version) {
        version =
            std::clamp(std::floor(*options.language_version * 100.0 + 0.5), 100.0, 10000.0) / 100.0;
        version_set = true;
    }
}

void Interpreter::check_string_length(std::size_t length, const std::string& what) const {
    if (length > options.limits.string_length)
        throw ValueError(what + " would be " + std::to_string(length) +
                         " characters long, more than the limit of " +
                         std::to_string(options.limits.string_length) +
                         " (--max-string-length N raises it)");
}

void Interpreter::count_debug_output(std::size_t bytes, const p::position& where) {
    debug_output_ += bytes;
    if (debug_output_ > options.limits.debug_output)
        fail(where, "#debug has printed more than " + std::to_string(options.limits.debug_output) +
                        " bytes (--max-debug-output N raises it)");
}

void Interpreter::check_object_count(std::uint64_t objects, const p::position& where) const {
    if (objects > options.limits.objects)
        fail(where, "this object would make " +
                        (objects >= runtime::kManyObjects ? std::string("more than 2^62")
                                                          : std::to_string(objects)) +
                        " objects (each member of a CSG, and each copy, is one), more than the "
                        "limit of " +
                        std::to_string(options.limits.objects) +
                        " (a union doubled in a loop? --max-objects N raises the limit)");
}

void Interpreter::tell_progress_now() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_progress_ ||
        now - began_ < std::chrono::duration<double>(options.progress_delay))
        return;
    next_progress_ = now + std::chrono::seconds(1);
    options.progress(
        {std::chrono::duration<double>(now - began_).count(), steps_, objects_, triangles_});
}

void Interpreter::count_triangles(std::size_t triangles, const p::position& where) {
    tell_progress();
    triangles_ += triangles;
    if (triangles_ > options.limits.triangles)
        fail(where, "the scene's meshes hold more than " +
                        std::to_string(options.limits.triangles) +
                        " triangles (--max-triangles N raises the limit)");
}

// ------------------------------------------------------------------ entry points

namespace {

// A Declare= value is a value, never scene text (a ';' or '#' would splice
// directives into the scene): a number, a vector of numbers or a string
// without quotes inside. POV-Ray 3.7 itself takes a float only.
void check_declare(const std::string& key, const std::string& value) {
    static const std::regex name("[A-Za-z_][A-Za-z0-9_]*");
    static const std::string number = R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)";
    static const std::regex accepted("\\s*(" + number + "|<\\s*" + number + "(\\s*,\\s*" + number +
                                     ")*\\s*>|\"[^\"\\\\\\n]*\")\\s*");
    if (!std::regex_match(key, name))
        throw SceneError("the name must be an identifier",
                         ErrorPlace{"--declare " + key, 0, 0, "", ""});
    if (!std::regex_match(value, accepted))
        throw SceneError("the value '" + value +
                             "' must be a number, a vector of numbers <a, b, c> or a \"string\" "
                             "(it is never read as scene text)",
                         ErrorPlace{"--declare " + key, 0, 0, "", ""});
    // A number past the doubles (1e999) reads as an infinity.
    if (value.find('"') == std::string::npos) {
        static const std::regex each(number);
        for (auto it = std::sregex_iterator(value.begin(), value.end(), each);
             it != std::sregex_iterator(); ++it)
            if (!std::isfinite(std::strtod(it->str().c_str(), nullptr)))
                throw SceneError("the number " + it->str() + " is beyond the doubles (infinite)",
                                 ErrorPlace{"--declare " + key, 0, 0, "", ""});
    }
}

runtime::SceneDescription parse(const std::string& text, const std::string& name,
                                const std::filesystem::path& folder, const ParseOptions& options) {
    const NestingGuard nesting;  // the reader's stack is measured from here
    runtime::SceneDescription scene;
    scene.animation = options.animation;
    Interpreter interpreter(options, scene, folder);
    // Declare= / --declare: each value is read as an expression.
    for (const auto& [key, value] : options.declares) {
        check_declare(key, value);
        const std::string source = "#declare " + key + " = " + value + ";";
        interpreter.read_file<grammar::scene_item, action, action_control>("--declare " + key,
                                                                           source);
    }
    try {
        interpreter.read_file<grammar::scene_item, action, action_control>(name, text);
    } catch (SceneError& e) {
        if (interpreter.split_refused) e.set_may_read_frame_by_frame();
        throw;
    }
    interpreter.finish_reading(name);
    return scene;
}

}  // namespace

runtime::SceneDescription parse_scene_file(const std::filesystem::path& path,
                                           const ParseOptions& options) {
    std::string text;
    try {
        text = read_source_text(path, options.limits.text_read);
    } catch (const ValueError& e) {
        throw SceneError(std::string("cannot read the scene file: ") + e.what(),
                         ErrorPlace{path.string(), 0, 0, {}, {}});
    }
    const auto folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    runtime::SceneDescription scene = parse(text, path.string(), folder, options);
    std::error_code error;
    const auto real = std::filesystem::canonical(path, error);
    if (!error) scene.inputs.insert(scene.inputs.begin(), real);
    return scene;
}

runtime::SceneDescription parse_scene_text(const std::string& text, const std::string& name,
                                           const ParseOptions& options) {
    return parse(text, name, std::filesystem::current_path(), options);
}

}  // namespace hexant::language
