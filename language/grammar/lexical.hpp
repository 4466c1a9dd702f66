// Lexical rules: blanks and comments, words and keywords, names, and the custom rules the
// interpreter reads. Part of the grammar (language/grammar.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>
#include <vector>

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

#include "runtime/objects/kinds.hpp"
#include "runtime/texture/pattern/kinds.hpp"

namespace hexant::language::grammar {

namespace p = tao::pegtl;

// ---------------------------------------------------------------- lexical

struct line_comment : p::seq<p::two<'/'>, p::until<p::eolf>> {};
// Block comments nest. One without its end is an error reported at the
// innermost '/*' still open, as the recursive rule this replaces did. Read
// with a count of depth, not recursion: the reader skips blanks with
// PEGTL's plain control in places (after a directive's keyword), where no
// nesting guard runs, and 100,000 nested comments there overflowed the
// stack (found by the fuzzer).
struct unterminated_comment : p::success {};
struct block_comment_body {
    using rule_t = block_comment_body;
    using subs_t = p::empty_list;
    template <p::apply_mode, p::rewind_mode, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&&... st) {
        const char* const b = in.current();
        const char* const e = in.end();
        if (e - b < 2 || b[0] != '/' || b[1] != '*') return false;
        std::vector<const char*> open{b};  // the openers not yet closed
        const char* q = b + 2;
        while (q + 1 < e) {
            if (q[0] == '/' && q[1] == '*') {
                open.push_back(q);
                q += 2;
            } else if (q[0] == '*' && q[1] == '/') {
                q += 2;
                open.pop_back();
                if (open.empty()) {
                    in.bump(static_cast<std::size_t>(q - b));
                    return true;
                }
            } else {
                ++q;
            }
        }
        if (open.size() == 1) return false;  // block_comment reports it at its '/*'
        in.bump(static_cast<std::size_t>(open.back() - b));
        Control<unterminated_comment>::raise(static_cast<const ParseInput&>(in), st...);
        return false;
    }
};
struct block_comment : p::sor<block_comment_body,
                              p::seq<p::at<p::string<'/', '*'>>, p::raise<unterminated_comment>>> {
};
struct separator : p::sor<p::space, line_comment, block_comment> {};
struct ws : p::star<separator> {};

template <char... C>
struct punct : p::seq<p::string<C...>, ws> {};
struct lbrace : punct<'{'> {};
struct rbrace : punct<'}'> {};
struct lparen : punct<'('> {};
struct rparen : punct<')'> {};
struct lbracket : punct<'['> {};
struct rbracket : punct<']'> {};
struct comma : punct<','> {};
struct semicolon : punct<';'> {};
struct colon : punct<':'> {};
struct equals : punct<'='> {};
struct langle : punct<'<'> {};
struct rangle : punct<'>'> {};

#define HEXANT_KEYWORD(rule, text) \
    struct rule : p::seq<TAO_PEGTL_KEYWORD(text), ws> {}

// The end of the run of letters, digits and '_' that starts at b (b itself
// if there is none): a word, as names and keywords are read.
inline const char* word_end(const char* b, const char* e) {
    while (b != e && (std::isalnum(static_cast<unsigned char>(*b)) || *b == '_')) ++b;
    return b;
}

// One whole word of Words::list (sorted; a word is letters, digits and
// '_'), read once and found by binary search. A p::sor of N keywords
// compares the input with each in turn, and every primary of an expression
// tries the built-in functions' and constants' names before it is a
// number or a name: a scene of 10^5 objects spent a quarter of its parse
// in those comparisons. The words are reserved (keywords.cpp).
template <class Words>
struct one_word_of {
    using rule_t = one_word_of;
    using subs_t = p::empty_list;
    static_assert(std::is_sorted(Words::list.begin(), Words::list.end()));
    template <p::apply_mode, p::rewind_mode, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&...) {
        const char* b = in.current();
        const char* e = in.end();
        const std::string_view word(b, static_cast<std::size_t>(word_end(b, e) - b));
        if (word.empty() || !std::binary_search(Words::list.begin(), Words::list.end(), word))
            return false;
        in.bump_in_this_line(word.size());
        return true;
    }
};

// A name that is not one of hexant's keywords. Matched by a custom rule
// because the set of keywords is a table (keywords.cpp), not a grammar.
bool is_reserved_word(std::string_view word);
struct name {
    using rule_t = name;
    using subs_t = p::empty_list;
    template <p::apply_mode, p::rewind_mode, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&...) {
        const char* b = in.current();
        const char* e = in.end();
        if (b == e || !(std::isalpha(static_cast<unsigned char>(*b)) || *b == '_')) return false;
        const char* q = word_end(b, e);
        if (is_reserved_word(std::string_view(b, static_cast<std::size_t>(q - b)))) return false;
        in.bump_in_this_line(static_cast<std::size_t>(q - b));
        return true;
    }
};
// A declared name, its trailing blanks consumed.
struct identifier : p::seq<name, ws> {};

// Custom rules whose reading the interpreter does (interpreter_state.hpp):
// each hands the input to one member of the parse state. Without a state
// (grammar analysis, grammar tests) they match nothing.
#define HEXANT_CUSTOM_RULE(rule, member)                                                         \
    template <typename Item>                                                                     \
    struct rule {                                                                                \
        using rule_t = rule;                                                                     \
        using subs_t = p::empty_list;                                                            \
        template <p::apply_mode, p::rewind_mode, template <typename...> class Action,            \
                  template <typename...> class Control, typename ParseInput, typename... States> \
        static bool match(ParseInput& in, States&... st) {                                       \
            if constexpr (sizeof...(States) == 0) {                                              \
                return false;                                                                    \
            } else {                                                                             \
                return (st.template member<Item, Action, Control>(in), ...);                     \
            }                                                                                    \
        }                                                                                        \
    }

HEXANT_CUSTOM_RULE(macro_call, call_macro);
HEXANT_CUSTOM_RULE(if_directive, run_if);
HEXANT_CUSTOM_RULE(ifdef_directive, run_ifdef);
HEXANT_CUSTOM_RULE(while_directive, run_while);
HEXANT_CUSTOM_RULE(for_directive, run_for);
HEXANT_CUSTOM_RULE(switch_directive, run_switch);
HEXANT_CUSTOM_RULE(include_directive, run_include);
// The rest of a directive whose taken branch closed the block around it.
HEXANT_CUSTOM_RULE(escaped_branch_end, skip_escaped_rest);
// #macro NAME(PARAMS) ... #end (the Item is unused).
struct macro_definition_item {};
HEXANT_CUSTOM_RULE(macro_definition_rule, define_macro);
struct macro_definition : macro_definition_rule<macro_definition_item> {};

}  // namespace hexant::language::grammar
