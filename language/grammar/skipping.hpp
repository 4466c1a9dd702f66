// Text stepped over without being run: false branches, loop and macro bodies.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/expressions.hpp"

namespace hexant::language::grammar {

// ---------------------------------------------------------------- skipping

// Text read without being run: a false #if branch, a loop or macro body
// being stepped over. Strings and comments are skipped whole, nested
// directive blocks as a unit.
namespace skip {
struct string_raw
    : p::seq<p::one<'"'>, p::until<p::one<'"'>, p::sor<p::seq<p::one<'\\'>, p::any>, p::any>>> {};
struct blanks : p::star<p::blank> {};
struct separators : p::star<separator> {};
struct divider_word
    : p::sor<TAO_PEGTL_KEYWORD("else"), TAO_PEGTL_KEYWORD("elseif"), TAO_PEGTL_KEYWORD("end"),
             TAO_PEGTL_KEYWORD("case"), TAO_PEGTL_KEYWORD("range"), TAO_PEGTL_KEYWORD("break")> {};
struct divider : p::seq<p::one<'#'>, blanks, divider_word> {};
struct end : p::seq<p::one<'#'>, blanks, TAO_PEGTL_KEYWORD("end")> {};
struct opener
    : p::seq<
          p::one<'#'>, blanks,
          p::sor<TAO_PEGTL_KEYWORD("if"), TAO_PEGTL_KEYWORD("ifdef"), TAO_PEGTL_KEYWORD("ifndef"),
                 TAO_PEGTL_KEYWORD("while"), TAO_PEGTL_KEYWORD("for"), TAO_PEGTL_KEYWORD("switch"),
                 TAO_PEGTL_KEYWORD("macro")>> {};
// A run of characters that start nothing: read as one token, not one at a
// time through every alternative (a loop stepping over a 50 KB body of
// directives and braces read 28 MB/s that way, 111 MB/s this way).
struct plain : p::plus<p::not_one<'/', '"', '#'>> {};
struct nested;
struct token : p::sor<plain, separator, string_raw, nested, p::seq<p::not_at<divider>, p::any>> {};
// Up to (not including) the next divider at this depth, or the end.
struct text : p::star<token> {};
struct nested_end : end {};
struct nested
    : p::seq<opener, p::star<p::sor<token, p::seq<p::not_at<end>, divider>>>, p::must<nested_end>> {
};
// A { ... } block with everything inside it.
struct braced;
struct braced_plain : p::plus<p::not_one<'/', '"', '{', '}'>> {};
struct braced_token : p::sor<braced_plain, separator, string_raw, braced, p::not_one<'{', '}'>> {};
struct braced_close : p::one<'}'> {};
struct braced : p::seq<p::one<'{'>, p::star<braced_token>, p::must<braced_close>> {};
struct until_rbrace : p::star<braced_token> {};

struct parenthesized;
struct paren_plain : p::plus<p::not_one<'/', '"', '(', ')'>> {};
struct paren_token
    : p::sor<paren_plain, separator, string_raw, parenthesized, p::not_one<'(', ')'>> {};
struct parenthesized_close : p::one<')'> {};
struct parenthesized : p::seq<p::one<'('>, p::star<paren_token>, p::must<parenthesized_close>> {};
// The text of a declaration's value, stepped over: a block (with any further
// texture layers) or anything up to ';'.
struct declaration_block
    : p::seq<p::identifier, separators, p::opt<parenthesized, separators>, braced, separators,
             p::star<TAO_PEGTL_KEYWORD("texture"), separators, braced, separators>> {};
struct declaration_text
    : p::seq<p::star<p::sor<separator, string_raw, braced, parenthesized, p::not_one<';', '#'>>>,
             p::opt<p::one<';'>>> {};
struct declaration : p::seq<p::sor<declaration_block, declaration_text>, separators> {};
}  // namespace skip

// A value read and thrown away (a setting hexant ignores).
struct ignored_value : p::seq<expression> {};
// A { } block stepped over whole.
struct skipped_block : p::seq<skip::braced> {};

}  // namespace hexant::language::grammar
