// The state of one reading of a scene: the value stack the actions work on,
// the blocks being built, the symbol tables, and the directives that steer
// the reading (#if, #while, #for, #switch, #macro, #include, macro calls).
//
// Directives run as the text is read, as in POV-Ray. A loop rewinds the input
// to its condition; a macro call reads the macro's stored source range with
// its original positions; so every error points at the right line.
#pragma once

#include <cmath>
#include <cstring>
#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include <tao/pegtl.hpp>

#include "language/builtins.hpp"
#include "language/image_map_file.hpp"
#include "language/errors.hpp"
#include "language/grammar.hpp"
#include "language/interpreter.hpp"
#include "language/mesh_reading.hpp"
#include "language/value.hpp"
#include "language/time_branch.hpp"
#include "language/value_ops.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/time/switching_instants.hpp"

namespace hexant::language {

namespace p = tao::pegtl;
using Input = p::memory_input<p::tracking_mode::eager, p::eol::lf_crlf, std::string>;

struct SplineBuilder {
    runtime::SplineKind kind = runtime::SplineKind::Linear;
    std::vector<runtime::Spline::Key> keys;
    int dimensions = 1;
};

struct MaterialBuilder {
    std::optional<runtime::Texture> texture;
    std::optional<runtime::Interior> interior;
};

// image_map { } being read: the map, the file as read (decoded when the
// block closes, after its gamma), and what was said of it.
struct ImageMapBuilder {
    runtime::pattern::ImageMap map;
    // The files as read, over their pieces of time (one piece for a file
    // named once), and each distinct file once.
    std::vector<std::pair<runtime::Interval, std::shared_ptr<const image::StoredImage>>> stored;
    ImageGamma gamma;
    bool gamma_srgb_next = false;  // `gamma srgb` just read
    bool all_next = false;         // `filter all` / `transmit all` being read
};

// A block under construction: `sphere { ... }`, `texture { ... }` ...
using Block = std::variant<runtime::ObjectRecord, runtime::LightRecord, runtime::CameraRecord,
                           runtime::Texture, runtime::Pigment, runtime::Normal, runtime::ColourMap, runtime::SkySphere,
                           runtime::Fog, runtime::Finish,
                           runtime::Interior,
                           runtime::Transform, SplineBuilder, MaterialBuilder, ImageMapBuilder>;

// What a std::bad_alloc while reading becomes, at its place.
inline constexpr const char* kOutOfMemory =
    "out of memory here: the scene asks for more memory than the machine gives (std::bad_alloc)";

// A parse error that is the use of something hexant lacks (see UnsupportedError).
struct unsupported_use : p::parse_error {
    using p::parse_error::parse_error;
};

// The block-structure directives that end or divide a directive's body.
enum class Divider { None, Else, Elseif, End, Case, Range, Break };

// A pattern hexant lacks in a pigment (its pigment map's too) or a normal:
// a ValueError naming where it was written (interpreter.cpp).
void check_pigment(const runtime::Pigment& pigment);
void check_normal(const std::optional<runtime::Normal>& normal);
void check_texture(const runtime::Texture& texture);

class Interpreter {
public:
    Interpreter(const ParseOptions& options, runtime::SceneDescription& scene,
                std::filesystem::path scene_folder);

    // ---- sources and errors
    // Keeps the text for the whole reading (macros point into it).
    const std::string& add_source(const std::string& name, std::string text);
    ErrorPlace place(const p::position& position, std::string note = {}) const;
    // A record's place (the line found by its number).
    ErrorPlace place(const runtime::SourcePlace& where, std::string note = {}) const;
    SceneError to_scene_error(const p::parse_error& e) const;
    [[noreturn]] static void fail(const p::position& position, const std::string& message) {
        throw p::parse_error(message, position);
    }
    void warn(const p::position& position, const std::string& message);
    std::ostream& messages() const;

    // ---- the value stack
    void push(Value v) { stack_.push_back(std::move(v)); }
    Value pop();
    Value& top();
    std::size_t depth() const { return stack_.size(); }
    void open_frame() { frames_.push_back(stack_.size()); }
    std::vector<Value> close_frame();
    void push_name(std::string name) { names_.push_back(std::move(name)); }
    std::string pop_name();

    // ---- blocks under construction
    std::vector<Block> blocks;
    template <typename T>
    T& block(const p::position& where, const char* what);
    // The object block a CSG member or light joins: block() without
    // counting an edit (members added under a time split live on its
    // pieces; other edits there are refused, split_time).
    runtime::ObjectRecord& member_block(const p::position& where) {
        const std::size_t watched = watched_block_;
        watched_block_ = 0;
        runtime::ObjectRecord& record = block<runtime::ObjectRecord>(where, "an object");
        watched_block_ = watched;
        return record;
    }
    void apply_transform(runtime::TransformStep step, const p::position& where);
    void apply_deformation(runtime::TransformStep step, const p::position& where);

    // ---- symbols
    const Value* lookup(const std::string& name) const;
    // When `name` is declared (always, or some pieces of time: see
    // Variable::defined); null when it is not declared at all.
    const runtime::Lifetime* declared_when(const std::string& name) const;
    // Throws ValueError when `name`, declared only part of the time, is used
    // where the domain reaches beyond that time (POV-Ray stops there on an
    // undeclared identifier).
    void check_declared(const std::string& name) const;
    void declare(const std::string& name, Value value, bool local);
    void assign_element(const std::string& name, const std::vector<Value>& indices, Value value,
                        const p::position& where);
    bool undefine(const std::string& name);

    // A finished top-level object joins the scene; its lights join the
    // scene's lights, and a pattern hexant lacks is an error here, where used.
    void add_object(const runtime::ObjectPtr& object, const p::position& where);
    // Adds a light to the scene, and its looks_like object (placed at the
    // light, through its transforms, casting no shadow).
    void add_light(runtime::LightRecord light, const p::position& where);
    // Throws SceneError at the object's place (or its part's) when a
    // parameter is NaN, infinite or degenerate at some instant of the
    // animation (runtime/objects/parameter_check.hpp); `where` is the item that
    // added it to the scene.
    void check_parameters(const runtime::ObjectRecord& object, const p::position& where) const;

    // ---- time (language/time_branch.hpp)
    // The time the text being read runs for: always, or the pieces where
    // the clock-dependent branches around it hold. Objects and lights made
    // now exist only then.
    runtime::Lifetime domain;
    // The animation's time, from the first frame's shutter opening to the
    // last one's closing.
    runtime::Interval animation_time() const {
        // (A clock that runs backwards, --clock 1:0, spans the same time.)
        const double a = scene.animation.time_begin();
        double b = scene.animation.time_end();
        // The last shutter's closing instant is not in the animation: a
        // sample's time is below 1 of the shutter (2^-32 short at most), so
        // no sample reaches it, and POV-Ray's last frame is at its opening.
        // Without it, what the scene makes only there (a file named for
        // the frame after the last) is not needed. A shutter of 0 (and a
        // still) has its instants only.
        if (scene.animation.exposure() > 0.0 && b != a) b = b > a ? runtime::interval_detail::next_down(b) : runtime::interval_detail::next_up(b);
        return {std::min(a, b), std::max(a, b)};
    }
    // How many times the camera and the background were set: a side of a
    // time split that sets one makes it piecewise.
    std::size_t camera_sets = 0, background_sets = 0;
    // Refuses, at `where`, something that cannot yet change with a
    // clock-dependent branch (`what`: "the camera", ...) when read under one.
    void require_whole_time(const p::position& where, const char* what) const;

    // ---- what the scene fills in
    runtime::SceneDescription& scene;
    const ParseOptions& options;
    RandomStreams random;
    double version = 3.7;
    // The values of the mesh2 section being read (language/mesh_reading.hpp).
    std::vector<MeshValue> mesh2_values;
    // global_settings { charset }: "ascii" (POV-Ray's default) or "utf8".
    std::string charset = "ascii";
    // The option words read before a shape's values (prism's linear_sweep),
    // one list per shape being read.
    std::vector<std::vector<std::string>> shape_options;
    // Patterns read so far (a global noise_generator after them is warned).
    std::size_t patterns_written = 0;
    runtime::SourcePlace shape_place;  // where the shape being read was written

    // ---- directives, called by the custom rules in grammar.hpp
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_if(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_ifdef(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_while(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_for(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_switch(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_include(ParseInput& in);
    // #include of a name that depends on clock (language/timed_string.hpp).
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    void include_by_clock(ParseInput& in, const p::position& opened, const TimedString& name);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control>
    void include_file(const p::position& opened, const std::string& file);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool define_macro(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool call_macro(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool declare_value(ParseInput& in);
    // Whether a call of a declared macro comes next; consumes nothing.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool macro_ahead(ParseInput& in) {
        const char* b = in.current();
        const char* q = b;
        while (q != in.end() && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
        if (q == b) return false;
        const Value* v = lookup(std::string(b, q));
        return v != nullptr && v->is<std::shared_ptr<const Macro>>();
    }

    // Whether a conditional directive whose branch starts with a value comes
    // next (grammar.hpp, argument_directive_ahead); consumes nothing. A value
    // starts with '<', a digit, a sign, '.', '(' or '"', a reserved word
    // that names a value or calls a function (x, pi, clock, vrotate(...)),
    // or a declared name that is not a macro; anything else (translate,
    // pigment, a macro call) starts the modifiers.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool argument_directive_ahead(ParseInput& in) {
        using opener = p::seq<p::one<'#'>, grammar::skip::blanks,
                              p::sor<TAO_PEGTL_KEYWORD("ifdef"), TAO_PEGTL_KEYWORD("ifndef"),
                                     TAO_PEGTL_KEYWORD("if")>,
                              grammar::skip::separators, grammar::skip::parenthesized,
                              grammar::skip::separators>;
        p::memory_input<> look(in.current(), in.end(), "");
        try {
            // Through the nesting guard (control): thousands of parentheses
            // in a condition would otherwise overflow the stack here.
            if (!p::parse<opener, p::nothing, control>(look)) return false;
        } catch (const p::parse_error&) {
            return false;  // an unclosed condition: the directive reports it
        }
        const char* q = look.current();
        if (q == in.end()) return false;
        if (std::strchr("<.-+(\"", *q) != nullptr || std::isdigit(static_cast<unsigned char>(*q)))
            return true;
        const char* b = q;
        while (q != in.end() && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
        if (q == b) return false;
        const std::string word(b, q);
        if (grammar::is_reserved_word(word)) {
            static const char* const kValueWords[] = {
                "x", "y", "z", "t", "u", "v", "pi", "tau", "clock", "clock_delta", "clock_on",
                "frame_number", "initial_clock", "final_clock", "initial_frame", "final_frame",
                "image_width", "image_height", "true", "false", "yes", "no", "on", "off",
                "version", "rgb", "rgbf", "rgbt", "rgbft", "color", "colour", "red", "green",
                "blue"};
            for (const char* w : kValueWords)
                if (word == w) return true;
            while (q != in.end() && (*q == ' ' || *q == '\t')) ++q;
            return q != in.end() && *q == '(';  // a function: sin(...), vrotate(...)
        }
        const Value* v = lookup(word);
        return v == nullptr || !v->is<std::shared_ptr<const Macro>>();
    }

    // Reads a whole file's items with the given rule (the main scene, an include).
    template <typename Items, template <typename...> class Action,
              template <typename...> class Control>
    void read_file(const std::string& name, const std::string& text);

    // (`what` names the file in messages: "include file", "image file".)
    // `also` are searched after the usual folders (and may be read).
    std::filesystem::path resolve_include(const std::string& name, const p::position& where,
                                          const std::string& what = "include file",
                                          const std::vector<std::filesystem::path>& also = {}) const;
    // The text of the include file at `path` (resolve_include's), counted
    // against Limits::text_read before it is read (read_source_text).
    std::string read_include(const std::filesystem::path& path, const p::position& where);

    // The arrays' memory (Limits::array_memory): every array of this
    // reading is charged to it.
    const std::shared_ptr<MemoryBudget>& array_memory() const { return array_memory_; }
    // A string about to be made of `length` characters, against
    // Limits::string_length; throws ValueError naming `what`.
    void check_string_length(std::size_t length, const std::string& what) const;

    // One loop iteration or macro call, against Limits::total_iterations:
    // the budget of the whole reading, across nested loops and macros.
    void count_step(const p::position& where) {
        if (++steps_ > options.limits.total_iterations)
            fail(where, "the scene ran more than " +
                            std::to_string(options.limits.total_iterations) +
                            " loop iterations and macro calls in all; stopping here "
                            "(--max-iterations N raises the limit)");
    }

    // Text about to be read, or just read again (a file, a loop's turn, a
    // macro's body), against Limits::text_read; throws at `where` past it.
    void count_text(std::size_t bytes, const p::position& where) {
        text_read_ += bytes;
        if (text_read_ > options.limits.text_read)
            fail(where, "the scene's reading went over more than " +
                            std::to_string(options.limits.text_read) +
                            " bytes of text (each loop turn and macro call reads its body "
                            "again); stopping here (--max-text-read N raises the limit)");
    }

private:
    template <typename Rule, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    void read(ParseInput& in) {
        (void)p::match<p::must<Rule>, p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(
            in, *this);
    }
    template <template <typename...> class Control, typename ParseInput>
    void skip_text(ParseInput& in) {
        (void)p::match<grammar::skip::text, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing,
                 Control>(in, *this);
    }
    template <typename ParseInput>
    Divider next_divider(ParseInput& in);
    template <typename ParseInput>
    bool keyword(ParseInput& in, std::string_view word);
    template <typename ParseInput>
    std::string identifier(ParseInput& in, const char* what);
    template <template <typename...> class Action, template <typename...> class Control,
              typename ParseInput>
    double condition(ParseInput& in, const char* directive);
    // A condition that may depend on clock.
    template <template <typename...> class Action, template <typename...> class Control,
              typename ParseInput>
    TimeFunction timed_condition(ParseInput& in, const char* directive);
    // An #if's (or #elseif's) bodies after its condition `c`, read at `at`.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    void if_chain(ParseInput& in, const p::position& opened, const p::position& at,
                  const TimeFunction& c);
    // A #while's turns from `count` on, its condition at `start`.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename Iterator>
    void while_from(ParseInput& in, const p::position& opened, const Iterator& start,
                    std::size_t count);
    // A #for's turns from `v` on (`count` done), its body at `start`.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename Iterator>
    void for_from(ParseInput& in, const p::position& opened, const Iterator& start,
                  const std::string& variable, double v, double step, const TimeFunction& to,
                  std::size_t count);
    // A #switch on `value` from the divider `d` on.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    void switch_from(ParseInput& in, const p::position& opened, const TimeFunction& value,
                     Divider d, bool matched, bool executing);
    // The same for a condition known to be `taken` over the whole domain.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    void if_rest(ParseInput& in, const p::position& opened, bool taken);
    // Splits the domain by the truth of `c` and calls read(taken) for each
    // side that has time, from the input's present place, with the domain
    // restricted to that side; then merges the variables the sides set
    // (time_branch.hpp). Errors name `at`.
    template <typename ParseInput, typename Read>
    void split_time(ParseInput& in, const p::position& at, const TimeFunction& c,
                    const runtime::TruthPieces& pieces, Read read);
    // The domain split by the truth of `c` (recorded for `hexant check`);
    // errors name `at`.
    runtime::TruthPieces split_domain(const TimeFunction& c, const p::position& at);
    // The truth of `c` when it is the same over the whole domain (no split
    // needed: nothing nests), else none.
    static std::optional<bool> whole_truth(const runtime::TruthPieces& pieces) {
        if (pieces.when_false.is_never()) return true;
        if (pieces.when_true.is_never()) return false;
        return std::nullopt;
    }
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    Divider run_body(ParseInput& in) {
        (void)p::match<p::star<Item>, p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(
            in, *this);
        return next_divider(in);
    }
    template <template <typename...> class Control, typename ParseInput>
    Divider skip_body(ParseInput& in) {
        skip_text<Control>(in);
        return next_divider(in);
    }
    template <typename ParseInput>
    [[noreturn]] void unclosed(const p::position& opened, const char* directive, Divider found,
                               const ParseInput& in);

    std::deque<std::pair<std::string, std::string>> sources_;
    // A variable: its value, and what its string's characters are charged
    // to the memory budget (array_memory_; an array charges itself).
    struct Variable {
        Value value;
        MemoryCharge charge;
        // When it is declared: always, or (set or #undef-ed on one side of
        // a branch on clock only) the pieces of time where it is.
        runtime::Lifetime defined;
    };
    using Scope = std::unordered_map<std::string, Variable>;
    // Sets the scope's variable `name` to `value`, charging a string's
    // characters; throws ValueError past the budget, changing nothing.
    void set_variable(Scope& scope, const std::string& name, Value value);
    std::vector<Scope> scopes_;
    // While one side of a time split is read: the variables of the scopes
    // older than the split that it changed, with what they held before
    // (none: undefined), so that the next side starts from the same state.
    using VariableKey = std::pair<std::size_t, std::string>;  // scope, name
    struct Held {  // a variable's value and when it is declared
        Value value;
        runtime::Lifetime defined;
    };
    struct BranchLog {
        std::size_t scopes = 0;  // scopes_.size() when the side began
        std::map<VariableKey, std::optional<Held>> before;
    };
    std::vector<BranchLog> branch_logs_;
    bool restoring_ = false;  // writing back a log: not itself logged
    // The depth of the object block a side of a time split reads inside
    // (0: none), and how many times block() handed it out for an edit.
    std::size_t watched_block_ = 0, watched_edits_ = 0;
    void log_change(const Scope& scope, const std::string& name);
    std::optional<Held> variable_at(const VariableKey& key) const;
    void set_variable_at(const VariableKey& key, const std::optional<Held>& held);
    // One side of a time split, read: its pieces, the variables it changed
    // (as they were when it ended), the values it left on the stack and the
    // object block around it as it left it.
    struct TimeSide {
        runtime::Lifetime when;
        std::map<VariableKey, std::optional<Held>> after;
        std::vector<Value> pushed;
        std::optional<runtime::ObjectRecord> top;
        bool top_edited = false;  // beyond adding members
        std::optional<runtime::CameraRecord> camera;        // when it set one
        std::optional<runtime::ColourFunction> background;  // when it set one
    };
    // After both sides of a split on `c` (read at `at`): their variables,
    // values and the block's CSG members made piecewise (time_branch.hpp).
    void merge_time_sides(const p::position& at, const TimeFunction& c,
                          std::optional<TimeSide> (&sides)[2],
                          const std::optional<runtime::ObjectRecord>& top_before,
                          const runtime::CameraRecord& camera_before,
                          const runtime::ColourFunction& background_before);
    std::vector<Value> stack_;
    std::vector<std::size_t> frames_;
    std::vector<std::string> names_;
    std::filesystem::path scene_folder_;
    int macro_depth_ = 0;
    int include_depth_ = 0;
    std::size_t steps_ = 0;
    std::size_t text_read_ = 0;
    std::shared_ptr<MemoryBudget> array_memory_;
};

// ------------------------------------------------------------------ templates

template <typename T>
T& Interpreter::block(const p::position& where, const char* what) {
    if (blocks.empty() || !std::holds_alternative<T>(blocks.back()))
        fail(where, std::string(what) + " does not belong here");
    // (A side of a time split editing the object around it: split_time.)
    if (blocks.size() == watched_block_) ++watched_edits_;
    return std::get<T>(blocks.back());
}

// Where a directive starts: at its '#', just before the input's position.
template <typename ParseInput>
p::position directive_position(const ParseInput& in) {
    p::position position = in.position();
    if (position.byte > 0 && position.column > 1 && in.current()[-1] == '#') {
        --position.byte;
        --position.column;
    }
    return position;
}

template <typename ParseInput>
void Interpreter::unclosed(const p::position& opened, const char* directive, Divider found,
                           const ParseInput& in) {
    static const char* names[] = {"", "#else", "#elseif", "#end", "#case", "#range", "#break"};
    if (found == Divider::None) {
        if (in.empty())
            fail(opened, std::string(directive) + " has no matching #end");
        fail(in.position(), std::string("this does not belong inside ") + directive +
                                " here: expected an item of the enclosing block, a directive "
                                "or #end" + found_text(in));
    }
    fail(in.position(), std::string(names[static_cast<int>(found)]) + " does not belong here, in the " +
                            directive + " opened at line " + std::to_string(opened.line));
}

template <typename ParseInput>
bool Interpreter::keyword(ParseInput& in, std::string_view word) {
    const char* b = in.current();
    const std::size_t n = word.size();
    if (static_cast<std::size_t>(in.end() - b) < n || std::string_view(b, n) != word) return false;
    if (b + n != in.end() && (std::isalnum(static_cast<unsigned char>(b[n])) || b[n] == '_'))
        return false;
    in.bump_in_this_line(n);
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing, p::normal>(
        in);
    return true;
}

template <typename ParseInput>
std::string Interpreter::identifier(ParseInput& in, const char* what) {
    const char* b = in.current();
    const auto position = in.position();
    if (!p::match<grammar::name, p::apply_mode::nothing, p::rewind_mode::required, p::nothing,
                  p::normal>(in))
        fail(position, std::string("expected ") + what + found_text(in));
    std::string result(b, in.current());
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing, p::normal>(
        in);
    return result;
}

template <typename ParseInput>
Divider Interpreter::next_divider(ParseInput& in) {
    const char* b = in.current();
    const char* e = in.end();
    if (b == e || *b != '#') return Divider::None;
    const char* q = b + 1;
    while (q != e && (*q == ' ' || *q == '\t')) ++q;
    const char* w = q;
    while (q != e && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
    const std::string_view word(w, static_cast<std::size_t>(q - w));
    Divider d = Divider::None;
    if (word == "else") d = Divider::Else;
    else if (word == "elseif") d = Divider::Elseif;
    else if (word == "end") d = Divider::End;
    else if (word == "case") d = Divider::Case;
    else if (word == "range") d = Divider::Range;
    else if (word == "break") d = Divider::Break;
    if (d == Divider::None) return d;
    in.bump_in_this_line(static_cast<std::size_t>(q - b));
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing, p::normal>(
        in);
    return d;
}

template <template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
double Interpreter::condition(ParseInput& in, const char* directive) {
    const auto position = in.position();
    read<grammar::condition, Action, Control>(in);
    try {
        return to_constant(pop(), std::string("the condition of ") + directive);
    } catch (const ValueError& e) {
        fail(position, e.what());
    }
}

template <template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
TimeFunction Interpreter::timed_condition(ParseInput& in, const char* directive) {
    const auto position = in.position();
    read<grammar::condition, Action, Control>(in);
    try {
        return to_float(pop(), std::string("the condition of ") + directive);
    } catch (const ValueError& e) {
        fail(position, e.what());
    }
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_if(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "if")) return false;
    const auto at = in.position();
    if_chain<Item, Action, Control>(in, opened, at, timed_condition<Action, Control>(in, "#if"));
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
void Interpreter::if_chain(ParseInput& in, const p::position& opened, const p::position& at,
                           const TimeFunction& c) {
    if (c.is_constant()) return if_rest<Item, Action, Control>(in, opened, runtime::pov_true(c.constant()));
    const runtime::TruthPieces pieces = split_domain(c, at);
    if (const auto whole = whole_truth(pieces)) return if_rest<Item, Action, Control>(in, opened, *whole);
    split_time(in, at, c, pieces, [&](bool taken) { if_rest<Item, Action, Control>(in, opened, taken); });
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
void Interpreter::if_rest(ParseInput& in, const p::position& opened, bool taken) {
    bool seen_else = false;
    for (;;) {
        const Divider d = taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
        if (d == Divider::End) return;
        if (taken) {
            // The rest, up to #end, is skipped whatever it holds.
            if (d != Divider::Else && d != Divider::Elseif) unclosed(opened, "#if", d, in);
            if (d == Divider::Else && seen_else) unclosed(opened, "#if", d, in);
            Divider rest;
            do {
                rest = skip_body<Control>(in);
            } while (rest == Divider::Else || rest == Divider::Elseif);
            if (rest != Divider::End) unclosed(opened, "#if", rest, in);
            return;
        }
        if (d == Divider::Else) {
            if (seen_else) unclosed(opened, "#if", d, in);
            seen_else = true;
            taken = true;
            // After #else only #end may follow.
            const Divider last = run_body<Item, Action, Control>(in);
            if (last != Divider::End) unclosed(opened, "#if", last, in);
            return;
        }
        if (d == Divider::Elseif) {
            const auto at = in.position();
            const TimeFunction c = timed_condition<Action, Control>(in, "#elseif");
            // The rest of the chain splits the time this side holds.
            if (!c.is_constant()) return if_chain<Item, Action, Control>(in, opened, at, c);
            taken = runtime::pov_true(c.constant());
            continue;
        }
        unclosed(opened, "#if", d, in);
    }
}

template <typename ParseInput, typename Read>
void Interpreter::split_time(ParseInput& in, const p::position& at, const TimeFunction& c,
                             const runtime::TruthPieces& pieces, Read read) {
    // Each split re-reads its text once a side and nests the next inside
    // it: bounded like macro calls (a chain of #elseif each on clock).
    if (branch_logs_.size() >= static_cast<std::size_t>(options.limits.macro_depth))
        fail(at, "clock-dependent branches nested more than " +
                     std::to_string(options.limits.macro_depth) +
                     " deep (--max-macro-depth N raises the limit)");
    const auto start = in.iterator();
    const runtime::Lifetime outer = domain;
    // What a side may change besides variables: values it leaves on the
    // stack (an #if inside a macro that returns a value), and the object
    // being built around it (CSG members it adds).
    const std::size_t stack_base = stack_.size();
    const runtime::CameraRecord camera_before = scene.camera;
    const runtime::ColourFunction background_before = scene.background;
    const std::size_t camera_count = camera_sets, background_count = background_sets;
    const std::size_t block_count = blocks.size();
    std::optional<runtime::ObjectRecord> top_before;
    if (!blocks.empty()) {
        if (!std::holds_alternative<runtime::ObjectRecord>(blocks.back()))
            fail(at, "a branch whose condition depends on clock inside this block; hexant makes "
                     "objects, their CSG members, floats and vectors piecewise in time, not yet "
                     "what this block holds");
        top_before = std::get<runtime::ObjectRecord>(blocks.back());
    }
    std::optional<TimeSide> sides[2];  // [0]: where c holds
    auto end = start;
    const auto restore = [&] {
        BranchLog log = std::move(branch_logs_.back());
        branch_logs_.pop_back();
        TimeSide side;
        restoring_ = true;
        for (auto& [key, before] : log.before) {
            side.after[key] = variable_at(key);
            set_variable_at(key, before);
        }
        restoring_ = false;
        if (camera_sets != camera_count) side.camera = std::exchange(scene.camera, camera_before);
        if (background_sets != background_count)
            side.background = std::exchange(scene.background, background_before);
        camera_sets = camera_count;
        background_sets = background_count;
        if (stack_.size() >= stack_base) {
            side.pushed.assign(std::make_move_iterator(stack_.begin() + static_cast<std::ptrdiff_t>(stack_base)),
                               std::make_move_iterator(stack_.end()));
        }
        const bool balanced = stack_.size() >= stack_base && blocks.size() == block_count;
        stack_.resize(std::min(stack_.size(), stack_base));
        if (blocks.size() == block_count && top_before) {
            side.top = std::move(std::get<runtime::ObjectRecord>(blocks.back()));
            blocks.back() = *top_before;
        }
        return std::pair{std::move(side), balanced};
    };
    for (int side = 0; side < 2; ++side) {
        const runtime::Lifetime& when = side == 0 ? pieces.when_true : pieces.when_false;
        if (when.is_never()) continue;
        in.iterator() = start;
        // (A condition true, or false, over all of the domain: no split.)
        const bool whole = (side == 0 ? pieces.when_false : pieces.when_true).is_never();
        domain = whole ? outer : when;
        branch_logs_.push_back({scopes_.size(), {}});
        const std::size_t watched = watched_block_, edits = watched_edits_;
        watched_block_ = top_before ? block_count : 0;
        watched_edits_ = 0;
        try {
            read(side == 0);
        } catch (const p::parse_error& e) {
            // Where in time the error is: from this side's first instant
            // (POV-Ray stops at that clock's frame).
            std::ostringstream note;
            note << std::setprecision(17) << e.message() << " (at clock " << when.pieces().front().lo
                 << ", on a side of the branch on clock at line " << at.line << ")";
            domain = outer;
            watched_block_ = watched;
            watched_edits_ = edits;
            (void)restore();
            if (e.message().find(" (at clock ") != std::string_view::npos) throw;  // said once, innermost
            p::parse_error amended(note.str(), e.positions().front());
            for (std::size_t i = 1; i < e.positions().size(); ++i)
                amended.add_position(p::position(e.positions()[i]));
            throw amended;
        } catch (...) {
            domain = outer;
            watched_block_ = watched;
            watched_edits_ = edits;
            (void)restore();
            throw;
        }
        const bool edited = watched_edits_ > 0;
        watched_block_ = watched;
        watched_edits_ = edits + (edited ? 1 : 0);
        auto [done, balanced] = restore();
        done.top_edited = edited;
        if (!balanced) {
            domain = outer;
            fail(at, "a branch whose condition depends on clock that uses values from before it "
                     "or leaves a block open; hexant cannot yet make that piecewise in time");
        }
        done.when = when;
        sides[side] = std::move(done);
        end = in.iterator();
    }
    domain = outer;
    in.iterator() = end;
    merge_time_sides(at, c, sides, top_before, camera_before, background_before);
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_ifdef(ParseInput& in) {
    const auto opened = directive_position(in);
    bool negate = false;
    if (keyword(in, "ifndef")) negate = true;
    else if (!keyword(in, "ifdef")) return false;
    const char* name = negate ? "#ifndef" : "#ifdef";
    read<grammar::lparen, Action, Control>(in);
    const std::string id = identifier(in, "a name in #ifdef ( )");
    read<grammar::condition_close, Action, Control>(in);
    const auto rest = [&](bool taken) {
        Divider d = taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
        if (d == Divider::Else) d = taken ? skip_body<Control>(in) : run_body<Item, Action, Control>(in);
        if (d != Divider::End) unclosed(opened, name, d, in);
    };
    const runtime::Lifetime* when = declared_when(id);
    if (when == nullptr || when->is_always()) {
        rest((when != nullptr) != negate);
        return true;
    }
    // Declared part of the time: a branch on the time it is declared.
    TimeFunction c = indicator(*when);
    if (negate) c = TimeFunction::apply(runtime::TimeOp::Not, c);
    // (The split is the directive's, as an #if's is.)
    const runtime::TruthPieces pieces = split_domain(c, opened);
    if (const auto whole = whole_truth(pieces)) rest(*whole);
    else split_time(in, opened, c, pieces, rest);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_while(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "while")) return false;
    const auto start = in.iterator();  // (a copy: the input moves on)
    while_from<Item, Action, Control>(in, opened, start, 0);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput, typename Iterator>
void Interpreter::while_from(ParseInput& in, const p::position& opened, const Iterator& start,
                             std::size_t count) {
    for (;; ++count) {
        in.iterator() = start;
        const auto at = in.position();
        const TimeFunction c = timed_condition<Action, Control>(in, "#while");
        // A condition on clock: the loop goes on only on the pieces where
        // it holds, turn by turn (objects that appear one by one).
        const auto turn = [&](bool go) {
            if (go && count >= options.limits.loop_iterations)
                fail(opened, "#while loop ran more than " +
                                 std::to_string(options.limits.loop_iterations) +
                                 " times; stopping (is its condition ever false? "
                                 "--max-loop-iterations N raises the limit)");
            if (go) count_step(opened);
            const Divider d = go ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
            if (d != Divider::End) unclosed(opened, "#while", d, in);
            if (go) count_text(static_cast<std::size_t>(in.current() - start.data), opened);
            return go;
        };
        bool go;
        if (c.is_constant()) {
            go = runtime::pov_true(c.constant());
        } else {
            const runtime::TruthPieces pieces = split_domain(c, at);
            if (const auto whole = whole_truth(pieces)) {
                go = *whole;  // the same all the domain's time: a plain turn
            } else {
                split_time(in, at, c, pieces, [&](bool on) {
                    if (turn(on)) while_from<Item, Action, Control>(in, opened, start, count + 1);
                });
                return;
            }
        }
        if (!turn(go)) return;
    }
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_for(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "for")) return false;
    open_frame();
    read<grammar::for_header, Action, Control>(in);
    std::vector<Value> bounds = close_frame();
    const std::string variable = pop_name();
    double from, step = 1.0;
    TimeFunction to;
    try {
        from = to_constant(bounds[0], "the start of #for");
        to = to_float(bounds[1], "the end of #for");
        if (bounds.size() > 2) step = to_constant(bounds[2], "the step of #for");
    } catch (const ValueError& e) {
        fail(opened, e.what());
    }
    if (step == 0.0) fail(opened, "#for with a step of 0 would never end");
    const auto start = in.iterator();
    for_from<Item, Action, Control>(in, opened, start, variable, from, step, to, 0);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput, typename Iterator>
void Interpreter::for_from(ParseInput& in, const p::position& opened, const Iterator& start,
                           const std::string& variable, double v, double step, const TimeFunction& to,
                           std::size_t count) {
    for (;; v += step) {
        // Goes on while v <= to (or >= for a negative step), within
        // POV-Ray's epsilon; an end on clock splits time turn by turn, as
        // a #while on clock does.
        const TimeFunction go =
            step > 0 ? TimeFunction::apply(runtime::TimeOp::LessEqual, v, to + runtime::kPovEpsilon)
                     : TimeFunction::apply(runtime::TimeOp::GreaterEqual, v, to - runtime::kPovEpsilon);
        const auto turn = [&](bool on) {
            // As in POV-Ray, the variable is left one step past the end.
            declare(variable, Value{TimeFunction(v)}, true);
            if (!on) {
                if (count == 0) {
                    const Divider d = skip_body<Control>(in);
                    if (d != Divider::End) unclosed(opened, "#for", d, in);
                }
                return false;
            }
            if (count + 1 > options.limits.loop_iterations)
                fail(opened, "#for loop ran more than " +
                                 std::to_string(options.limits.loop_iterations) +
                                 " times; stopping (--max-loop-iterations N raises the limit)");
            count_step(opened);
            in.iterator() = start;
            const Divider d = run_body<Item, Action, Control>(in);
            if (d != Divider::End) unclosed(opened, "#for", d, in);
            count_text(static_cast<std::size_t>(in.current() - start.data), opened);
            return true;
        };
        bool on;
        if (go.is_constant()) {
            on = runtime::pov_true(go.constant());
        } else {
            const runtime::TruthPieces pieces = split_domain(go, opened);
            if (const auto whole = whole_truth(pieces)) {
                on = *whole;
            } else {
                split_time(in, opened, go, pieces, [&](bool more) {
                    if (turn(more))
                        for_from<Item, Action, Control>(in, opened, start, variable, v + step, step, to,
                                                        count + 1);
                });
                return;
            }
        }
        if (!turn(on)) return;
        ++count;
    }
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_switch(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "switch")) return false;
    const TimeFunction value = timed_condition<Action, Control>(in, "#switch");
    switch_from<Item, Action, Control>(in, opened, value, skip_body<Control>(in), false, false);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
void Interpreter::switch_from(ParseInput& in, const p::position& opened, const TimeFunction& value,
                              Divider d, bool matched, bool executing) {
    for (;;) {
        const auto at = in.position();
        switch (d) {
            case Divider::Case:
            case Divider::Range: {
                TimeFunction hit;
                if (d == Divider::Case) {
                    // POV-Ray's: |value - case| < epsilon.
                    hit = TimeFunction::apply(runtime::TimeOp::Equal, value,
                                              timed_condition<Action, Control>(in, "#case"));
                } else {
                    open_frame();
                    read<grammar::range_header, Action, Control>(in);
                    auto r = close_frame();
                    try {
                        const TimeFunction lo = to_float(r[0], "the low end of #range");
                        const TimeFunction hi = to_float(r[1], "the high end of #range");
                        hit = TimeFunction::apply(runtime::TimeOp::And,
                                                  TimeFunction::apply(runtime::TimeOp::GreaterEqual, value, lo),
                                                  TimeFunction::apply(runtime::TimeOp::LessEqual, value, hi));
                    } catch (const ValueError& e) {
                        fail(at, e.what());
                    }
                }
                // A clause that matches part of the time (once none before
                // it runs): the rest of the #switch once for each side.
                std::optional<bool> decided;
                runtime::TruthPieces pieces;
                if (hit.is_constant()) decided = runtime::pov_true(hit.constant());
                else if (!executing) decided = whole_truth(pieces = split_domain(hit, at));
                if (!executing && !decided) {
                    split_time(in, at, hit, pieces, [&](bool taken) {
                        const Divider next =
                            taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                        switch_from<Item, Action, Control>(in, opened, value, next, matched || taken, taken);
                    });
                    return;
                }
                executing = executing || decided.value_or(false);
                if (executing) matched = true;
                d = executing ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                break;
            }
            case Divider::Else:
                executing = !matched;
                d = executing ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                break;
            case Divider::Break:
                if (executing) {
                    // Skip the remaining clauses up to #end.
                    do {
                        d = skip_body<Control>(in);
                    } while (d != Divider::End && d != Divider::None);
                    if (d != Divider::End) unclosed(opened, "#switch", d, in);
                    return;
                }
                d = skip_body<Control>(in);
                break;
            case Divider::End: return;
            default: unclosed(opened, "#switch", d, in);
        }
    }
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::define_macro(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "macro")) return false;
    std::string name = identifier(in, "the macro's name after #macro");
    std::vector<std::string> parameters;
    read<grammar::lparen, Action, Control>(in);
    while (in.current() != in.end() && *in.current() != ')') {
        if (!parameters.empty()) {
            // POV-Ray lets one leave out the ',' and allows a trailing one.
            (void)p::match<grammar::comma, p::apply_mode::nothing, p::rewind_mode::required,
                           p::nothing, p::normal>(in);
            if (in.current() != in.end() && *in.current() == ')') break;
        }
        parameters.push_back(identifier(in, "a parameter name in #macro ( )"));
    }
    read<grammar::rparen, Action, Control>(in);
    const char* body_begin = in.current();
    const auto body_position = in.position();
    skip_text<Control>(in);
    const char* body_end = in.current();
    const Divider d = next_divider(in);
    if (d != Divider::End) unclosed(opened, "#macro", d, in);
    auto macro = std::make_shared<Macro>(Macro{std::move(name), std::move(parameters), body_begin,
                                               body_end, body_position, opened});
    declare(macro->name, Value{std::shared_ptr<const Macro>(macro)}, false);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::call_macro(ParseInput& in) {
    const char* b = in.current();
    const char* e = in.end();
    const char* q = b;
    while (q != e && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
    if (q == b || std::isdigit(static_cast<unsigned char>(*b))) return false;
    const std::string name(b, q);
    const Value* v = lookup(name);
    if (v == nullptr || !v->is<std::shared_ptr<const Macro>>()) return false;
    const auto macro = v->as<std::shared_ptr<const Macro>>();
    const auto call_place = in.position();
    in.bump_in_this_line(static_cast<std::size_t>(q - b));
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing, p::normal>(
        in);
    read<grammar::call_open, Action, Control>(in);
    open_frame();
    // An argument that is just a declared name is passed by reference, as in
    // POV-Ray: what the macro #declares to its parameter goes back to it.
    std::vector<std::string> references;
    if (in.current() != in.end() && *in.current() != ')') {
        do {
            const char* start = in.current();
            read<grammar::call_argument, Action, Control>(in);
            std::string text(start, in.current());
            while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
            const bool is_name = !text.empty() && !std::isdigit(static_cast<unsigned char>(text[0])) &&
                                 std::all_of(text.begin(), text.end(), [](char c) {
                                     return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                                 });
            references.push_back(is_name && lookup(text) ? text : std::string());
        } while (p::match<grammar::comma, p::apply_mode::nothing, p::rewind_mode::required,
                          p::nothing, p::normal>(in));
    }
    read<grammar::call_close, Action, Control>(in);
    std::vector<Value> args = close_frame();
    if (args.size() != macro->parameters.size())
        fail(call_place, "macro '" + name + "' takes " + std::to_string(macro->parameters.size()) +
                             " argument" + (macro->parameters.size() == 1 ? "" : "s") + ", not " +
                             std::to_string(args.size()));
    if (macro_depth_ >= options.limits.macro_depth)
        fail(call_place, "macro calls nested more than " +
                             std::to_string(options.limits.macro_depth) +
                             " deep; stopping (runaway recursion? --max-macro-depth N raises the "
                             "limit)");
    count_step(call_place);
    count_text(static_cast<std::size_t>(macro->body_end - macro->body_begin), call_place);
    scopes_.emplace_back();
    try {
        for (std::size_t i = 0; i < args.size(); ++i)
            set_variable(scopes_.back(), macro->parameters[i], std::move(args[i]));
    } catch (const ValueError& e) {
        scopes_.pop_back();
        fail(call_place, e.what());
    }
    ++macro_depth_;
    const std::size_t before = depth();
    const auto& at = macro->body_position;
    Input body(macro->body_begin, macro->body_end, at.source, at.byte, at.line, at.column);
    try {
        (void)p::match<p::seq<grammar::ws, p::star<Item>, p::must<grammar::macro_body_end>>,
                 p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(body, *this);
    } catch (const unsupported_use&) {
        // A #declare around the call may keep it as source and read on.
        --macro_depth_;
        scopes_.pop_back();
        throw;
    } catch (const p::parse_error& error) {
        SceneError scene_error = to_scene_error(error);
        scene_error.add_context(place(call_place, "in macro '" + name + "' called here"));
        throw scene_error;
    } catch (SceneError& scene_error) {
        scene_error.add_context(place(call_place, "in macro '" + name + "' called here"));
        throw;
    }
    --macro_depth_;
    for (std::size_t i = 0; i < references.size(); ++i) {
        if (references[i].empty()) continue;
        auto found = scopes_.back().find(macro->parameters[i]);
        if (found == scopes_.back().end()) continue;
        for (std::size_t level = scopes_.size() - 1; level-- > 0;) {
            auto target = scopes_[level].find(references[i]);
            if (target != scopes_[level].end()) {
                try {
                    set_variable(scopes_[level], references[i], found->second.value);
                } catch (const ValueError& e) {
                    scopes_.pop_back();
                    fail(call_place, e.what());
                }
                break;
            }
        }
    }
    scopes_.pop_back();
    if constexpr (std::is_same_v<Item, grammar::value_item>) {
        if (depth() != before + 1)
            fail(call_place, "macro '" + name + "' is used as a value but gives " +
                                 std::to_string(depth() - before) + " values");
    }
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::declare_value(ParseInput& in) {
    const auto start = in.iterator();
    const std::size_t values = stack_.size(), block_count = blocks.size(),
                      frame_count = frames_.size(), name_count = names_.size();
    try {
        return p::match<grammar::value, p::apply_mode::action, p::rewind_mode::required, Action,
                        Control>(in, *this);
    } catch (const unsupported_use& e) {
        // Keep the declaration as source: an error only where it is used.
        in.iterator() = start;
        stack_.erase(stack_.begin() + static_cast<std::ptrdiff_t>(values), stack_.end());
        blocks.erase(blocks.begin() + static_cast<std::ptrdiff_t>(block_count), blocks.end());
        frames_.resize(frame_count);
        names_.resize(name_count);
        const auto where = in.position();
        (void)p::match<grammar::skip::declaration, p::apply_mode::nothing, p::rewind_mode::dontcare,
                       p::nothing, Control>(in, *this);
        push(Value{Unevaluated{"declaration that hexant cannot evaluate (" + std::string(e.message()) + ")",
                               where}});
        return true;
    }
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
bool Interpreter::run_include(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "include")) return false;
    read<grammar::include_name, Action, Control>(in);
    const Value name = pop();
    if (name.is<TimedString>()) {
        include_by_clock<Item, Action, Control>(in, opened, name.as<TimedString>());
        return true;
    }
    std::string file;
    try {
        file = to_string_value(name, "the name after #include");
    } catch (const ValueError& e) {
        fail(opened, e.what());
    }
    include_file<Item, Action, Control>(opened, file);
    return true;
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput>
void Interpreter::include_by_clock(ParseInput& in, const p::position& opened, const TimedString& name) {
    // Each file read for the time its name holds, as the sides of a branch
    // on clock: the first name against the rest, then the rest in turn.
    std::vector<double> instants;  // for `hexant check`, as split_domain records them
    for (std::size_t i = 1; i < name.pieces.size(); ++i)
        if (domain.contains(name.pieces[i].time.lo)) instants.push_back(name.pieces[i].time.lo);
    if (!instants.empty()) scene.time_splits.push_back({{opened.source, opened.line, opened.column}, instants});
    std::vector<std::pair<std::string, runtime::Lifetime>> files;
    for (auto& [file, when] : name.by_text()) {
        runtime::Lifetime here = runtime::Lifetime::of(when.within(animation_time())).intersect(domain);
        if (!here.is_never()) files.push_back({file, std::move(here)});
    }
    const auto from = [&](const auto& self, std::size_t k) -> void {
        if (k + 1 >= files.size()) {
            if (k < files.size()) include_file<Item, Action, Control>(opened, files[k].first);
            return;
        }
        runtime::TruthPieces pieces;
        pieces.when_true = files[k].second;
        std::vector<runtime::Interval> rest;
        for (std::size_t j = k + 1; j < files.size(); ++j)
            rest.insert(rest.end(), files[j].second.pieces().begin(), files[j].second.pieces().end());
        pieces.when_false = runtime::Lifetime::of(std::move(rest));
        split_time(in, opened, indicator(pieces.when_true), pieces, [&](bool first) {
            if (first) include_file<Item, Action, Control>(opened, files[k].first);
            else self(self, k + 1);
        });
    };
    from(from, 0);
}

template <typename Item, template <typename...> class Action,
          template <typename...> class Control>
void Interpreter::include_file(const p::position& opened, const std::string& file) {
    if (include_depth_ >= options.limits.include_depth)
        fail(opened, "#include nested more than " + std::to_string(options.limits.include_depth) +
                         " deep; stopping (does a file include itself? --max-include-depth N "
                         "raises the limit)");
    const std::filesystem::path path = resolve_include(file, opened);
    const std::string text = read_include(path, opened);
    ++include_depth_;
    scopes_.emplace_back();
    try {
        read_file<Item, Action, Control>(path.string(), text);
    } catch (SceneError& scene_error) {
        scene_error.add_context(place(opened, "included from here"));
        throw;
    }
    scopes_.pop_back();
    --include_depth_;
}

template <typename Items, template <typename...> class Action,
          template <typename...> class Control>
void Interpreter::read_file(const std::string& name, const std::string& text) {
    const std::string& stored = add_source(name, text);
    Input in(stored.data(), stored.data() + stored.size(), name, 0, 1, 1);
    try {
        if constexpr (std::is_same_v<Items, grammar::scene_item>)
            (void)p::match<grammar::scene_file, p::apply_mode::action, p::rewind_mode::dontcare, Action,
                     Control>(in, *this);
        else
            (void)p::match<p::seq<grammar::ws, p::star<Items>, p::must<grammar::include_end>>,
                     p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(in, *this);
    } catch (const p::parse_error& error) {
        throw to_scene_error(error);
    } catch (const std::bad_alloc&) {
        // An allocation outside any action (a directive's own work): the
        // place is where the reading of this file had got to.
        throw to_scene_error(p::parse_error(kOutOfMemory, in.position()));
    }
}

}  // namespace hexant::language
