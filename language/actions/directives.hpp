// Directives: declarations, conditions, loops, messages.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/operators.hpp"

namespace hexant::language {

// ------------------------------------------------------------ directives

template <>
struct action<g::declare_directive> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> frame = st.values.close_frame();  // indices..., value
        Value value = std::move(frame.back());
        frame.pop_back();
        const std::string name = st.values.pop_name();
        const bool local = st.values.pop_name() == "local";
        if (value.is<std::shared_ptr<Array>>())
            value = Value{std::make_shared<Array>(*value.as<std::shared_ptr<Array>>())};
        if (frame.empty()) {
            st.symbols.declare(name, std::move(value), local);
        } else {
            st.assign_element(name, frame, std::move(value), in.position());
        }
    }
};

template <>
struct action<g::undef_name> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.symbols.undefine(word(in));
    }
};

template <>
struct action<g::version_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.version = to_constant(st.values.pop(), "#version");
        st.version_set = true;
    }
};

// A message's text that depends on clock: each piece's text, after the
// time it is said for (POV-Ray says it once a frame, at that frame's clock).
inline std::string message_text(const Value& value, const char* what) {
    if (!value.is<TimedString>()) return to_string_value(value, what);
    std::ostringstream out;
    out << std::setprecision(17);
    for (const auto& piece : value.as<TimedString>().pieces) {
        out << "[clock " << piece.time.lo << " to " << piece.time.hi << "] " << piece.text;
        // (One line a piece, whether or not the text ends its line.)
        if (piece.text.empty() || piece.text.back() != '\n') out << '\n';
    }
    return out.str();
}

template <>
struct action<g::debug_directive> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string text = message_text(st.values.pop(), "#debug's text");
        st.count_debug_output(text.size(), in.position());
        st.messages() << text;
    }
};

template <>
struct action<g::warning_directive> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.warn(in.position(), message_text(st.values.pop(), "#warning's text"));
    }
};

template <>
struct action<g::error_directive> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Interpreter::fail(in.position(),
                          "#error: " + message_text(st.values.pop(), "#error's text"));
    }
};

template <>
struct action<g::unsupported_directive> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Interpreter::fail(in.position(), "#" + word(in) + " is not supported by hexant");
    }
};

template <>
struct action<g::lone_hash> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.warn(in.position(), "a '#' that starts no directive is ignored, as POV-Ray ignores it");
    }
};

template <>
struct action<g::unknown_directive> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter&) {
        const char* b = in.begin();
        const char* e = in.input().end();
        const char* q = b;
        while (q != e && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
        Interpreter::fail(in.position(), "unknown directive '#" + std::string(b, q) + "'");
    }
};

template <>
struct action<g::default_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        st.default_depth = st.blocks.depth();
    }
};
template <>
struct action<g::default_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, Interpreter& st) {
        st.default_depth.reset();
    }
};

template <>
struct action<g::default_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "#default");
        Value v = st.values.pop();
        auto& texture = st.scene.default_texture;
        // (Each part was read into the default's own: pigment_open,
        // finish_open.) POV-Ray's Parse_Default refuses a patterned or a
        // layered default texture.
        if (v.is<runtime::Texture>()) {
            const auto& given = v.as<runtime::Texture>();
            if (given.is_patterned())
                Interpreter::fail(in.position(),
                                  "the #default texture cannot be a texture_map or block pattern "
                                  "(as in POV-Ray)");
            if (!given.below.empty())
                Interpreter::fail(in.position(),
                                  "the #default texture cannot be layered (as in POV-Ray)");
            texture = given;
        } else if (v.is<runtime::Pigment>())
            texture.pigment = v.as<runtime::Pigment>();
        else if (v.is<runtime::Normal>()) {
            const auto& normal = v.as<runtime::Normal>();
            // (A normal without a pattern sets what new normals start from.)
            if (normal.patterned->kind == nullptr && normal.unsupported_name.empty() &&
                !normal.bump_map)
                st.default_normal_start = normal;
            else
                texture.normal = normal;
        } else if (v.is<runtime::Finish>())
            texture.finish = st.finishes.share(std::move(v.as<runtime::Finish>()));
        // Checked here, at the #default: the objects that take it are
        // checked for their own parameters only.
        if (auto problem = runtime::bad_parameter(texture, "the #default", st.scene.animation))
            Interpreter::fail(in.position(), *problem);
        ++st.defaults_set;
    }
};

}  // namespace hexant::language
