// Literals and expressions: numbers, strings, vectors, colours, calls, operators.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/lexical.hpp"

namespace hexant::language::grammar {

// ---------------------------------------------------------------- literals

struct exponent : p::seq<p::one<'e', 'E'>, p::opt<p::one<'+', '-'>>, p::plus<p::digit>> {};
struct number_text
    : p::seq<p::sor<p::seq<p::plus<p::digit>, p::opt<p::one<'.'>, p::star<p::digit>>>,
                    p::seq<p::one<'.'>, p::plus<p::digit>>>,
             p::opt<exponent>> {};
struct number_end : p::not_at<p::identifier_other> {};
struct number : p::seq<number_text, p::must<number_end>, ws> {};

struct string_escape : p::seq<p::one<'\\'>, p::any> {};
struct string_content : p::star<p::sor<string_escape, p::not_one<'"', '\n', '\r'>>> {};
struct string_close : p::one<'"'> {};
struct string_literal : p::seq<p::one<'"'>, string_content, p::must<string_close>, ws> {};

// ---------------------------------------------------------------- expressions

struct expression;
struct sum;
struct unary;
struct value;

// Marks where a variable-length list of values begins on the value stack.
struct frame_open : p::success {};

struct paren_close : rparen {};
struct paren_content : p::seq<expression> {};
struct paren_expression : p::seq<lparen, p::must<paren_content>, p::must<paren_close>> {};

struct vector_open : langle {};
struct vector_close : rangle {};
struct vector_component : p::seq<sum> {};
// As POV-Ray reads vectors: the commas between components may be left out
// (woods.inc writes `< -1 0 0 >`; `<1 -1>` is then 1 - 1, in POV-Ray too)
// and a comma may end the list (`rgb <0.2, 0.1, 0.5,>`).
struct vector_literal
    : p::seq<vector_open, frame_open, p::must<vector_component>,
             p::star<p::sor<p::seq<comma, p::not_at<vector_close>, p::must<vector_component>>,
                            vector_component>>,
             p::opt<comma>, p::must<vector_close>> {};

// Built-in functions; the name picks the implementation (builtins.cpp).
struct function_words {
    static constexpr std::array<std::string_view, 58> list = {"abs",
                                                              "acos",
                                                              "acosh",
                                                              "asc",
                                                              "asin",
                                                              "asinh",
                                                              "atan",
                                                              "atan2",
                                                              "atanh",
                                                              "bitwise_and",
                                                              "bitwise_or",
                                                              "bitwise_xor",
                                                              "ceil",
                                                              "chr",
                                                              "concat",
                                                              "cos",
                                                              "cosh",
                                                              "degrees",
                                                              "dimension_size",
                                                              "dimensions",
                                                              "div",
                                                              "exp",
                                                              "file_exists",
                                                              "floor",
                                                              "inside",
                                                              "int",
                                                              "ln",
                                                              "log",
                                                              "max",
                                                              "max_extent",
                                                              "min",
                                                              "min_extent",
                                                              "mod",
                                                              "pow",
                                                              "radians",
                                                              "rand",
                                                              "seed",
                                                              "select",
                                                              "sin",
                                                              "sinh",
                                                              "sqrt",
                                                              "str",
                                                              "strcmp",
                                                              "strlen",
                                                              "strlwr",
                                                              "strupr",
                                                              "substr",
                                                              "tan",
                                                              "tanh",
                                                              "val",
                                                              "vaxis_rotate",
                                                              "vcross",
                                                              "vdot",
                                                              "vlength",
                                                              "vnormalize",
                                                              "vrotate",
                                                              "vstr",
                                                              "vturbulence"};
};
struct function_name : one_word_of<function_words> {};
struct call_open : lparen {};
struct call_close : rparen {};
struct call_argument : p::seq<value> {};
struct call_arguments : p::opt<call_argument, p::star<comma, p::must<call_argument>>> {};
struct function_call : p::seq<function_name, ws, p::must<call_open>, frame_open, call_arguments,
                              p::must<call_close>> {};
// trace(OBJECT, A, B [, N]): N names a declared vector that receives the
// normal (POV-Ray's Parse_Trace).
struct trace_normal_name : identifier {};
struct trace_call
    : p::seq<TAO_PEGTL_KEYWORD("trace"), ws, p::must<call_open>, frame_open, p::must<call_argument>,
             p::must<comma>, p::must<call_argument>, p::must<comma>, p::must<call_argument>,
             p::opt<comma, p::must<trace_normal_name>>, p::must<call_close>> {};

// defined(IDENT): whether a name is declared.
HEXANT_KEYWORD(kw_defined, "defined");
struct defined_name : identifier {};
struct defined_call
    : p::seq<kw_defined, p::must<lparen>, p::must<defined_name>, p::must<paren_close>> {};

struct builtin_constant_words {
    static constexpr std::array<std::string_view, 25> list = {"clock",
                                                              "clock_delta",
                                                              "clock_on",
                                                              "false",
                                                              "final_clock",
                                                              "final_frame",
                                                              "frame_number",
                                                              "image_height",
                                                              "image_width",
                                                              "initial_clock",
                                                              "initial_frame",
                                                              "no",
                                                              "off",
                                                              "on",
                                                              "pi",
                                                              "t",
                                                              "tau",
                                                              "true",
                                                              "u",
                                                              "v",
                                                              "version",
                                                              "x",
                                                              "y",
                                                              "yes",
                                                              "z"};
};
struct builtin_constant_name : one_word_of<builtin_constant_words> {};
struct builtin_constant : p::seq<builtin_constant_name, ws> {};

// Colours: rgb <..>, rgbf, rgbt, rgbft, srgb..., and `color red 1 green .5`.
struct colour_model_words {
    static constexpr std::array<std::string_view, 8> list = {"rgb",  "rgbf",  "rgbft",  "rgbt",
                                                             "srgb", "srgbf", "srgbft", "srgbt"};
};
struct colour_model : one_word_of<colour_model_words> {};
// POV-Ray's rgb takes a whole sum: rgb <.1,.2,.3> + .5 leaves filter at 0.
struct colour_model_argument : p::seq<sum> {};
struct colour_model_literal : p::seq<colour_model, ws, p::must<colour_model_argument>> {};
struct colour_component_words {
    static constexpr std::array<std::string_view, 5> list = {"blue", "filter", "green", "red",
                                                             "transmit"};
};
struct colour_component_name : one_word_of<colour_component_words> {};
// (A whole sum, as POV-Ray's Parse_Float: `transmit 1 - level`.)
struct colour_component_value : p::seq<sum> {};
struct colour_component_setting
    : p::seq<colour_component_name, ws, p::must<colour_component_value>> {};
struct colour_keyword
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("color"), TAO_PEGTL_KEYWORD("colour")>, ws> {};
struct colour_base : p::seq<p::not_at<colour_component_name>, unary> {};
struct colour_expression
    : p::seq<colour_keyword, p::opt<colour_base>, p::star<colour_component_setting>> {};

// A call of a declared macro; the body is spliced in where the call stands.
struct value_item;

// A declared name used as a value.
struct reference : identifier {};

struct primary : p::sor<number, string_literal, vector_literal, paren_expression, function_call,
                        trace_call, colour_model_literal, colour_expression, defined_call,
                        builtin_constant, macro_call<value_item>, reference> {};

struct component_name
    : p::sor<TAO_PEGTL_KEYWORD("x"), TAO_PEGTL_KEYWORD("y"), TAO_PEGTL_KEYWORD("z"),
             TAO_PEGTL_KEYWORD("t"), TAO_PEGTL_KEYWORD("u"), TAO_PEGTL_KEYWORD("v"),
             TAO_PEGTL_KEYWORD("red"), TAO_PEGTL_KEYWORD("green"), TAO_PEGTL_KEYWORD("blue"),
             TAO_PEGTL_KEYWORD("filter"), TAO_PEGTL_KEYWORD("transmit"), TAO_PEGTL_KEYWORD("gray"),
             TAO_PEGTL_KEYWORD("grey")> {};
struct component_access : p::seq<p::one<'.'>, component_name, ws> {};
struct index_close : rbracket {};
struct index_value : p::seq<expression> {};
struct index_suffix : p::seq<lbracket, p::must<index_value>, p::must<index_close>> {};
// S(t): evaluating a spline.
struct spline_call : p::seq<call_open, frame_open, call_arguments, p::must<call_close>> {};
struct postfix : p::seq<primary, p::star<p::sor<component_access, index_suffix, spline_call>>> {};

struct unary_operand : p::seq<unary> {};
struct negation : p::seq<p::one<'-'>, ws, p::must<unary_operand>> {};
struct unary_plus : p::seq<p::one<'+'>, ws, p::must<unary_operand>> {};
struct logical_not : p::seq<p::one<'!'>, p::not_at<p::one<'='>>, ws, p::must<unary_operand>> {};
struct unary : p::sor<negation, unary_plus, logical_not, postfix> {};

struct multiplication : p::seq<p::one<'*'>, ws, p::must<unary_operand>> {};
struct division : p::seq<p::one<'/'>, ws, p::must<unary_operand>> {};
struct product : p::seq<unary, p::star<p::sor<multiplication, division>>> {};

struct product_operand : product {};
struct addition : p::seq<p::one<'+'>, ws, p::must<product_operand>> {};
struct subtraction : p::seq<p::one<'-'>, ws, p::must<product_operand>> {};
// An operand that takes + and -: the value before is a number, a vector or
// a string, not an object (whose value ends there, as in POV-Ray:
// `Align_Object(Center_Object(O, x) -y, 0)` passes -y as the next argument).
// Consumes nothing; without a parse state (grammar analysis and tests) it
// holds.
struct arithmetic_left {
    using rule_t = arithmetic_left;
    using subs_t = p::empty_list;
    template <p::apply_mode, p::rewind_mode, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match([[maybe_unused]] ParseInput& in, [[maybe_unused]] States&... st) {
        if constexpr (sizeof...(States) == 0)
            return true;
        else
            return (st.arithmetic_left(), ...);
    }
};
struct sum : p::seq<product, p::star<arithmetic_left, p::sor<addition, subtraction>>> {};

struct sum_operand : p::seq<sum> {};
struct less_equal : p::seq<p::string<'<', '='>, ws, p::must<sum_operand>> {};
struct greater_equal : p::seq<p::string<'>', '='>, ws, p::must<sum_operand>> {};
struct not_equal : p::seq<p::string<'!', '='>, ws, p::must<sum_operand>> {};
struct less : p::seq<p::one<'<'>, ws, p::must<sum_operand>> {};
struct greater : p::seq<p::one<'>'>, ws, p::must<sum_operand>> {};
struct equal : p::seq<p::one<'='>, ws, p::must<sum_operand>> {};
struct comparison
    : p::seq<sum, p::star<p::sor<less_equal, greater_equal, not_equal, less, greater, equal>>> {};

// POV-Ray gives & and | one precedence, read left to right.
struct comparison_operand : comparison {};
struct logical_and : p::seq<p::one<'&'>, ws, p::must<comparison_operand>> {};
struct logical_or : p::seq<p::one<'|'>, ws, p::must<comparison_operand>> {};
struct disjunction : p::seq<comparison, p::star<p::sor<logical_and, logical_or>>> {};

struct conditional_branch : p::seq<expression> {};
struct conditional_tail : p::seq<p::one<'?'>, ws, p::must<conditional_branch>, p::must<colon>,
                                 p::must<conditional_branch>> {};
struct expression : p::seq<disjunction, p::opt<conditional_tail>> {};

}  // namespace hexant::language::grammar
