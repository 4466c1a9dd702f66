// User functions: function(PARAMS) { EXPRESSION }, function { internal(N) }.
// Part of the grammar (language/grammar.hpp).
//
// A body is an expression of the language's own grammar, read with the
// parameters in scope (x, y, z when none are named, as POV-Ray's default),
// so declared floats, declared functions, POV-Ray's float built-ins and
// clock mean in a body what they mean elsewhere. The forms POV-Ray reads
// after `function {` and hexant does not evaluate yet (pigment, pattern,
// spline, transform) stay unsupported_block: an error where used.
#pragma once

#include "language/grammar/expressions.hpp"

namespace hexant::language::grammar {

HEXANT_KEYWORD(kw_function, "function");
struct function_parameter : p::seq<p::identifier, ws> {};
struct function_parameters
    : p::seq<lparen, p::opt<function_parameter, p::star<comma, p::must<function_parameter>>>,
             p::must<rparen>> {};
// What POV-Ray reads after `function {` that is not an expression.
struct function_special_words {
    static constexpr std::array<std::string_view, 4> list = {"pattern", "pigment", "spline",
                                                             "transform"};
};
struct function_special : one_word_of<function_special_words> {};
struct function_head : p::seq<kw_function, p::opt<function_parameters>, lbrace> {};
// After the head: the parameters are in scope from here to the body's end.
struct function_open : p::success {};
struct function_internal_number : p::seq<number> {};
struct function_internal : p::seq<TAO_PEGTL_KEYWORD("internal"), ws, p::must<lparen>,
                                  p::must<function_internal_number>, p::must<rparen>> {};
struct function_body : p::seq<expression> {};
struct function_content : p::sor<function_internal, function_body> {};
struct function_close : rbrace {};
struct function_value : p::seq<p::at<function_head, p::not_at<function_special>>, function_head,
                               function_open, p::must<function_content>, p::must<function_close>> {
};

}  // namespace hexant::language::grammar
