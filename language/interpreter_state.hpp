// The state of one reading of a scene: the value stack the actions work on,
// the blocks being built, the symbol tables, and the directives that steer
// the reading (#if, #while, #for, #switch, #macro, #include, macro calls).
//
// Directives run as the text is read, as in POV-Ray. A loop rewinds the input
// to its condition; a macro call reads the macro's stored source range with
// its original positions; so every error points at the right line.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
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
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include <tao/pegtl.hpp>

#include "language/block_stack.hpp"
#include "language/builtins.hpp"
#include "language/errors.hpp"
#include "language/file_io.hpp"
#include "language/grammar.hpp"
#include "language/image_map_file.hpp"
#include "language/interpreter.hpp"
#include "language/mesh_reading.hpp"
#include "language/scene_queries.hpp"
#include "language/symbol_table.hpp"
#include "language/time_branch.hpp"
#include "language/value.hpp"
#include "language/value_ops.hpp"
#include "language/value_stack.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/texture/finish_pool.hpp"
#include "runtime/time/switching_instants.hpp"

namespace hexant::language {

namespace p = tao::pegtl;
using Input = p::memory_input<p::tracking_mode::eager, p::eol::lf_crlf, std::string>;

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
    // A value operation's error at `position` (after `prefix`); one of what
    // cannot yet be piecewise in time marks the reading (split_refused).
    [[noreturn]] void fail(const p::position& position, const ValueError& e,
                           const std::string& prefix = {}) const {
        if (dynamic_cast<const PiecewiseError*>(&e) != nullptr) split_refused = true;
        fail(position, prefix + e.what());
    }
    // What cannot yet be piecewise in time, refused at `position`.
    [[noreturn]] void fail_piecewise(const p::position& position,
                                     const std::string& message) const {
        split_refused = true;
        fail(position, message);
    }
    // A warning at `position` (an error under ParseOptions::strict).
    void warn(const p::position& position, const std::string& message);
    // A warning's whole text, said (once over a scene read frame by frame,
    // ParseOptions::warnings_said) and kept in the scene's warnings.
    void say_warning(std::string text);
    // `word`, one of POV-Ray's words whose KeywordRule is Warned
    // (language/keyword_rules.hpp), read at `where`: what hexant does
    // instead, to keep with what it belongs to and warn where that is used
    // (report_unrendered). std::logic_error for any other word.
    runtime::Unrendered unrendered(const p::position& where, std::string_view word) const;
    // The same, warned now (a global setting, a camera's, a light's).
    void not_rendered(const p::position& where, std::string_view word);
    // Warns (once each in the reading) what `object` and what it holds
    // (its textures, their layers and maps, its interior, its members) ask
    // for that hexant lacks; `where` is the item that added it to the scene.
    void report_unrendered(const runtime::ObjectRecord& object, const p::position& where);
    std::ostream& messages() const;

    // ---- the value stack (language/value_stack.hpp)
    ValueStack values;

    // ---- blocks under construction (language/block_stack.hpp)
    BlockStack blocks;
    void apply_transform(runtime::TransformStep step, const p::position& where);
    void apply_deformation(runtime::TransformStep step, const p::position& where);

    // ---- symbols (language/symbol_table.hpp)
    SymbolTable symbols;
    // Throws ValueError when `name`, declared only part of the time, is used
    // where the domain reaches beyond that time (POV-Ray stops there on an
    // undeclared identifier).
    void check_declared(const std::string& name) const;
    // An array element set: `name[indices] = value`; errors at `where`.
    void assign_element(const std::string& name, const std::vector<Value>& indices, Value value,
                        const p::position& where);

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
    // last one's closing; read for one frame alone
    // (ParseOptions::frame_alone), that frame's exposure or its clock.
    runtime::Interval animation_time() const {
        // (A clock that runs backwards, --clock 1:0, spans the same time.)
        const runtime::Animation& animation = scene.animation;
        const auto& alone = options.frame_alone;
        if (alone && alone->at_clock) {
            const double c = animation.clock_of_frame(alone->frame);
            return {c, c};
        }
        const runtime::Animation::Window last =
            animation.frame_window(alone ? alone->frame : animation.final_frame);
        const double a = alone ? last.open : animation.time_begin();
        double b = last.close();
        // The last shutter's closing instant is not in the animation: a
        // sample's time is below 1 of the shutter (2^-32 short at most), so
        // no sample reaches it, and POV-Ray's last frame is at its opening.
        // Without it, what the scene makes only there (a file named for
        // the frame after the last) is not needed. A shutter of 0 (and a
        // still, and a last frame cut to the instant Final_Clock) has its
        // instants only.
        if (last.length != 0.0 && b != a)
            b = b > a ? runtime::interval_detail::next_down(b)
                      : runtime::interval_detail::next_up(b);
        return {std::min(a, b), std::max(a, b)};
    }
    // How many times the camera and the background were set: a side of a
    // time split that sets one makes it piecewise.
    std::size_t camera_sets = 0, background_sets = 0;
    // Whether the reading stopped at what hexant cannot make piecewise in
    // time (fail_piecewise, a PiecewiseError): reading frame by frame may
    // pass it (SceneError::may_read_frame_by_frame).
    mutable bool split_refused = false;
    // Refuses, at `where`, something that cannot yet change with a
    // clock-dependent branch (`what`: "the camera", ...) when read under one.
    void require_whole_time(const p::position& where, const char* what) const;

    // ---- what the scene fills in
    runtime::SceneDescription& scene;
    const ParseOptions& options;
    RandomStreams random;
    double version = 3.7;
    // Whether a #version was read (anywhere, as POV-Ray's languageVersionSet)
    // and global_settings { assumed_gamma }: without either POV-Ray 3.7 reads
    // a scene with its legacy gamma rule (finish_reading).
    bool version_set = false, assumed_gamma_set = false;
    // Where image maps were read (warned at the end in a legacy-gamma scene).
    std::vector<p::position> image_maps_read;
    // After the whole scene is read: what holds only then (the legacy
    // gamma rule's warning, coincident faces).
    void finish_reading(const std::string& name);
    // A warning at each pair of objects whose flat faces coincide
    // (runtime/scene/coincident_faces.hpp); errors under --strict.
    void report_coincident_faces();
    // The user functions being read, innermost last: each one's parameter
    // names (grammar/functions.hpp), and the names of the one whose head is
    // being read (given: whether it wrote a list, empty or not).
    std::vector<std::vector<std::string>> functions_open;
    std::vector<std::string> function_parameter_names;
    bool function_parameters_given = false;
    // The index of `name` among the parameters of the function being read.
    std::optional<int> function_parameter(const std::string& name) const {
        if (functions_open.empty()) return std::nullopt;
        const auto& names = functions_open.back();
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return static_cast<int>(i);
        return std::nullopt;
    }
    // User functions' calls made so far (language/actions/literals.hpp,
    // call_user_function): keyed by the function's and the arguments'
    // addresses (a constant argument by its bits, its lowest bit flipped).
    using FunctionCall = std::vector<std::uint64_t>;
    struct CalledFunction {
        std::shared_ptr<const runtime::UserFunction> function;
        std::vector<TimeFunction> arguments;
        TimeFunction result;
    };
    std::map<FunctionCall, CalledFunction> function_calls;
    // The objects trace() and inside() have asked of (language/scene_queries.hpp).
    QueriedObjects queried_objects;
    // The files #fopen opened (language/file_io.hpp), and whether the
    // #read being read has met its file's end.
    UserFiles user_files;
    bool file_read_ended = false;
    // The values of the mesh2 section being read (language/mesh_reading.hpp).
    std::vector<MeshValue> mesh2_values;
    // global_settings { charset }: "ascii" (POV-Ray's default) or "utf8".
    std::string charset = "ascii";
    // The shape blocks being read, the innermost last: each one's kind (its
    // index in runtime::ShapeKinds), the option words read before its values
    // (prism's linear_sweep) and where it was written.
    struct ShapeOpening {
        std::size_t kind;
        std::vector<std::string> options;
        runtime::SourcePlace place;
    };
    std::vector<ShapeOpening> shapes_open;
    // How many #default directives were read.
    std::size_t defaults_set = 0;
    // Inside #default { } (its block depth then), and the pattern-less
    // normal it gave (`normal { bump_size 1.5 }`): POV-Ray's default Tnormal,
    // which every new normal starts from (Parse_Tnormal) and which is an
    // error only where a surface would use it without a pattern.
    std::optional<std::size_t> default_depth;
    std::optional<runtime::Normal> default_normal_start;
    // Patterns read so far (a global noise_generator after them is warned).
    std::size_t patterns_written = 0;
    // Every finish { } written, as one block per distinct finish.
    runtime::FinishPool finishes;

    // ---- directives, called by the custom rules in grammar.hpp
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool run_if(ParseInput& in);
    // The rest of a directive whose taken branch closed the block around
    // it (read_closing_branch), when the reading reaches it.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool skip_escaped_rest(ParseInput& in);
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
    // object { MACRO(...) modifiers }: a macro whose body gives the object
    // and goes on with modifiers of it (`Obj rotate A*y`), as POV-Ray's
    // tokens read it; object_macro_first reads the object where the body
    // has not given it yet (macros.hpp).
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool call_object_macro(ParseInput& in);
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool object_macro_first(ParseInput& in);
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
        const Value* v = symbols.lookup(std::string(b, q));
        return v != nullptr && v->is<std::shared_ptr<const Macro>>();
    }
    // Whether a call of a declared macro comes next whose body begins with
    // an item of the block (Item) rather than a value: glass.inc's
    // `interior { I_Glass_Exp(2) }` gives `ior 1.5 fade_distance 2 ...`,
    // which POV-Ray's tokens read as the block's items, not as its base.
    // Only the grammar looks (no actions run); consumes nothing.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool items_macro_ahead(ParseInput& in) {
        const char* b = in.current();
        const char* q = b;
        while (q != in.end() && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
        if (q == b) return false;
        const Value* v = symbols.lookup(std::string(b, q));
        if (v == nullptr || !v->is<std::shared_ptr<const Macro>>()) return false;
        const auto& macro = v->as<std::shared_ptr<const Macro>>();
        tao::pegtl::memory_input<> body(macro->body_begin, macro->body_end, "");
        try {
            return tao::pegtl::match<
                tao::pegtl::seq<grammar::ws, Item>, tao::pegtl::apply_mode::nothing,
                tao::pegtl::rewind_mode::required, tao::pegtl::nothing, tao::pegtl::normal>(body);
        } catch (const tao::pegtl::parse_error&) {
            return true;  // an item's keyword matched, its value did not
        }
    }

    // Whether the value just read may take + or - (grammar::arithmetic_left):
    // not an object.
    bool arithmetic_left() { return values.depth() == 0 || !values.top().is<runtime::ObjectPtr>(); }
    // Whether a declared object's name comes next (grammar.hpp,
    // keyword_around_object); consumes nothing.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool declared_object_ahead(ParseInput& in) {
        const char* b = in.current();
        const char* q = grammar::word_end(b, in.end());
        if (q == b || grammar::is_reserved_word(std::string(b, q))) return false;
        const Value* v = symbols.lookup(std::string(b, q));
        return v != nullptr && v->is<runtime::ObjectPtr>();
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
            static const char* const kValueWords[] = {"x",
                                                      "y",
                                                      "z",
                                                      "t",
                                                      "u",
                                                      "v",
                                                      "pi",
                                                      "tau",
                                                      "clock",
                                                      "clock_delta",
                                                      "clock_on",
                                                      "frame_number",
                                                      "initial_clock",
                                                      "final_clock",
                                                      "initial_frame",
                                                      "final_frame",
                                                      "image_width",
                                                      "image_height",
                                                      "true",
                                                      "false",
                                                      "yes",
                                                      "no",
                                                      "on",
                                                      "off",
                                                      "version",
                                                      "rgb",
                                                      "rgbf",
                                                      "rgbt",
                                                      "rgbft",
                                                      "color",
                                                      "colour",
                                                      "red",
                                                      "green",
                                                      "blue"};
            for (const char* w : kValueWords)
                if (word == w) return true;
            while (q != in.end() && (*q == ' ' || *q == '\t')) ++q;
            return q != in.end() && *q == '(';  // a function: sin(...), vrotate(...)
        }
        const Value* v = symbols.lookup(word);
        return v == nullptr || !v->is<std::shared_ptr<const Macro>>();
    }

    // Reads a whole file's items with the given rule (the main scene, an include).
    template <typename Items, template <typename...> class Action,
              template <typename...> class Control>
    void read_file(const std::string& name, const std::string& text);

    // (`what` names the file in messages: "include file", "image file".)
    // `also` are searched after the usual folders (and may be read).
    std::filesystem::path resolve_include(
        const std::string& name, const p::position& where, const std::string& what = "include file",
        const std::vector<std::filesystem::path>& also = {}) const;
    // The file resolve_include finds and confines, without failing: its
    // real path, or why it may not be read (`error`, never the contents).
    struct FoundFile {
        std::filesystem::path path;
        std::string error;
    };
    FoundFile find_readable(const std::string& name, const std::string& what,
                            const std::vector<std::filesystem::path>& also = {}) const;
    // The pixels an image the scene reads (image_map, bump_map,
    // height_field) may declare: Limits::image_pixels, as a rendered
    // frame's.
    std::size_t max_image_pixels() const {
        return static_cast<std::size_t>(std::max(1LL, options.limits.image_pixels));
    }
    // The text of the include file at `path` (resolve_include's), counted
    // against Limits::text_read before it is read (read_source_text).
    std::string read_include(const std::filesystem::path& path, const p::position& where);

    // The arrays' memory (Limits::array_memory): every array of this
    // reading is charged to it.
    const std::shared_ptr<MemoryBudget>& array_memory() const { return symbols.memory(); }
    // A string about to be made of `length` characters, against
    // Limits::string_length; throws ValueError naming `what`.
    void check_string_length(std::size_t length, const std::string& what) const;
    // #debug text about to be printed, against Limits::debug_output over
    // the whole reading; an error at `where` past it.
    void count_debug_output(std::size_t bytes, const p::position& where);

    // An object about to be made of `objects` objects (ObjectRecord::objects),
    // against Limits::objects; an error at `where` past it.
    void check_object_count(std::uint64_t objects, const p::position& where) const;
    // Triangles about to be added to a mesh, against Limits::triangles over
    // the whole reading; an error at `where` past it.
    void count_triangles(std::size_t triangles, const p::position& where);
    // ParseOptions::progress, when it is due (the clock is read once every
    // 1024 calls: a loop's turn takes microseconds).
    void tell_progress() {
        if (options.progress && (++ticks_ & 1023) == 0) tell_progress_now();
    }
    void tell_progress_now();

    // One loop iteration or macro call, against Limits::total_iterations:
    // the budget of the whole reading, across nested loops and macros.
    void count_step(const p::position& where) {
        tell_progress();
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
        (void)p::match<p::must<Rule>, p::apply_mode::action, p::rewind_mode::dontcare, Action,
                       Control>(in, *this);
    }
    template <template <typename...> class Control, typename ParseInput>
    void skip_text(ParseInput& in) {
        (void)p::match<grammar::skip::text, p::apply_mode::nothing, p::rewind_mode::dontcare,
                       p::nothing, Control>(in, *this);
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
    // A taken branch that opens a block the text after its #end closes:
    // read with that text (conditions.hpp); false when its braces balance.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool read_opening_branch(ParseInput& in, const p::position& opened, const char* directive);
    // A taken branch that closes the block around its directive: its items
    // are read up to that '}' and the rest of the directive is stepped over
    // when the reading reaches it (skip_escaped_rest); false when it does not.
    template <typename Item, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    bool read_closing_branch(ParseInput& in, const p::position& opened, const char* directive,
                             const char* body_end);
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
        (void)p::match<p::star<Item>, p::apply_mode::action, p::rewind_mode::dontcare, Action,
                       Control>(in, *this);
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
    // The copies read_opening_branch reads from (kept: macros declared in
    // them point into them).
    std::deque<std::string> spliced_texts_;
    // Where the branches read_closing_branch read end (the directive's
    // next divider), in their input's text.
    std::vector<const char*> escaped_ends_;
    // The block depths at which object { MACRO(...) } macros are being
    // read, innermost last (call_object_macro).
    std::vector<std::size_t> object_macro_depths_;
    // The depth of the object block around the time split being read (its
    // sides may close it only together), and where the side being read
    // closed it: its branch's end, kept for the last side's.
    std::optional<std::size_t> split_block_depth_;
    const char* side_escape_ = nullptr;
    // One side of a time split, read: its pieces, the variables it changed
    // (as they were when it ended), the values it left on the stack and the
    // object block around it as it left it.
    struct TimeSide {
        runtime::Lifetime when;
        SymbolTable::Changes after;
        std::vector<Value> pushed;
        std::optional<runtime::ObjectRecord> top;
        BlockStack::Edited top_edited = BlockStack::Edited::No;  // beyond adding members
        std::optional<runtime::CameraRecord> camera;             // when it set one
        std::optional<runtime::ColourFunction> background;       // when it set one
    };
    // After both sides of a split on `c` (read at `at`): their variables,
    // values and the block's CSG members made piecewise (time_branch.hpp).
    void merge_time_sides(const p::position& at, const TimeFunction& c,
                          std::optional<TimeSide> (&sides)[2],
                          const std::optional<runtime::ObjectRecord>& top_before,
                          const runtime::CameraRecord& camera_before,
                          const runtime::ColourFunction& background_before);
    std::filesystem::path scene_folder_;
    std::set<std::string> unrendered_reported_;  // place and message, once each
    int macro_depth_ = 0;
    int include_depth_ = 0;
    std::size_t steps_ = 0;
    std::size_t text_read_ = 0;
    std::size_t debug_output_ = 0;
    std::uint64_t objects_ = 0;    // made for the scene's objects (add_object)
    std::uint64_t triangles_ = 0;  // read into meshes
    std::uint64_t ticks_ = 0;      // calls of tell_progress
    std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point next_progress_ = began_;
};

}  // namespace hexant::language

// The member templates, by what they read (language/interpreter/).
#include "language/interpreter/conditions.hpp"
#include "language/interpreter/files.hpp"
#include "language/interpreter/loops.hpp"
#include "language/interpreter/macros.hpp"
#include "language/interpreter/reading.hpp"
#include "language/interpreter/switch.hpp"
