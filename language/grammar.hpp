// The grammar of hexant's scene language, a subset of POV-Ray 3.7's SDL.
//
// Rules only: what each rule does lives in actions.hpp, its error message in
// errors.hpp. Directives that steer the reading itself (#if, #while, #for,
// #switch, #macro, #include and macro calls) are custom rules whose match()
// hands the input to the interpreter (interpreter_state.hpp), which runs them
// as POV-Ray does: while the text is read, replaying a loop's or a macro's
// stored source range so that positions stay exact.
//
// Every rule consumes the blanks and comments after it, so rules start at a
// token.
//
// The rules live in language/grammar/, one file a part, each including the
// one before it: lexical, expressions, skipping, directives, modifiers, textures, media, objects,
// scene.
#pragma once

#include "language/grammar/scene.hpp"

// For analyze<>(): each custom rule consumes input when it succeeds.
namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, hexant::language::grammar::name> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, hexant::language::grammar::block_comment_body> : analyze_any_traits<> {
};
template <typename Name, typename Words>
struct analyze_traits<Name, hexant::language::grammar::one_word_of<Words>> : analyze_any_traits<> {
};
#define HEXANT_CUSTOM_ANALYZE(rule)         \
    template <typename Name, typename Item> \
    struct analyze_traits<Name, hexant::language::grammar::rule<Item>> : analyze_any_traits<> {}
HEXANT_CUSTOM_ANALYZE(macro_call);
HEXANT_CUSTOM_ANALYZE(if_directive);
HEXANT_CUSTOM_ANALYZE(ifdef_directive);
HEXANT_CUSTOM_ANALYZE(while_directive);
HEXANT_CUSTOM_ANALYZE(for_directive);
HEXANT_CUSTOM_ANALYZE(switch_directive);
HEXANT_CUSTOM_ANALYZE(include_directive);
HEXANT_CUSTOM_ANALYZE(escaped_branch_end);
HEXANT_CUSTOM_ANALYZE(object_macro_base);
HEXANT_CUSTOM_ANALYZE(object_macro_first);
HEXANT_CUSTOM_ANALYZE(macro_definition_rule);
HEXANT_CUSTOM_ANALYZE(declared_value_rule);
#undef HEXANT_CUSTOM_ANALYZE
// macro_ahead, items_macro_ahead, argument_directive_ahead and
// declared_object_ahead only look.
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::macro_ahead_rule<Item>>
    : analyze_opt_traits<> {};
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::items_macro_ahead<Item>>
    : analyze_opt_traits<> {};
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::argument_directive_ahead_rule<Item>>
    : analyze_opt_traits<> {};
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::declared_object_ahead_rule<Item>>
    : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, hexant::language::grammar::arithmetic_left> : analyze_opt_traits<> {};
}  // namespace tao::pegtl
