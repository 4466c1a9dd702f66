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
struct block_comment
    : p::sor<block_comment_body, p::seq<p::at<p::string<'/', '*'>>, p::raise<unterminated_comment>>> {};
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
#define HEXANT_CUSTOM_RULE(rule, member)                                                        \
    template <typename Item>                                                                   \
    struct rule {                                                                              \
        using rule_t = rule;                                                                   \
        using subs_t = p::empty_list;                                                          \
        template <p::apply_mode, p::rewind_mode, template <typename...> class Action,          \
                  template <typename...> class Control, typename ParseInput, typename... States> \
        static bool match(ParseInput& in, States&... st) {                                     \
            if constexpr (sizeof...(States) == 0) {                                            \
                return false;                                                                  \
            } else {                                                                           \
                return (st.template member<Item, Action, Control>(in), ...);                   \
            }                                                                                  \
        }                                                                                      \
    }

HEXANT_CUSTOM_RULE(macro_call, call_macro);
HEXANT_CUSTOM_RULE(if_directive, run_if);
HEXANT_CUSTOM_RULE(ifdef_directive, run_ifdef);
HEXANT_CUSTOM_RULE(while_directive, run_while);
HEXANT_CUSTOM_RULE(for_directive, run_for);
HEXANT_CUSTOM_RULE(switch_directive, run_switch);
HEXANT_CUSTOM_RULE(include_directive, run_include);
// #macro NAME(PARAMS) ... #end (the Item is unused).
struct macro_definition_item {};
HEXANT_CUSTOM_RULE(macro_definition_rule, define_macro);
struct macro_definition : macro_definition_rule<macro_definition_item> {};

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
    static constexpr std::array<std::string_view, 53> list = {
        "abs", "acos", "asc", "asin", "atan", "atan2", "bitwise_and", "bitwise_or", "bitwise_xor",
        "ceil", "chr", "concat", "cos", "cosh", "degrees", "dimension_size", "dimensions", "div",
        "exp", "file_exists", "floor", "int", "ln", "log", "max", "max_extent", "min", "min_extent", "mod", "pow",
        "radians",
        "rand", "seed", "select", "sin", "sinh", "sqrt", "str", "strcmp", "strlen", "strlwr", "strupr",
        "substr", "tan", "tanh", "val", "vaxis_rotate", "vcross", "vdot", "vlength", "vnormalize",
        "vrotate", "vstr"};
};
struct function_name : one_word_of<function_words> {};
struct call_open : lparen {};
struct call_close : rparen {};
struct call_argument : p::seq<value> {};
struct call_arguments : p::opt<call_argument, p::star<comma, p::must<call_argument>>> {};
struct function_call
    : p::seq<function_name, ws, p::must<call_open>, frame_open, call_arguments,
             p::must<call_close>> {};

// defined(IDENT): whether a name is declared.
HEXANT_KEYWORD(kw_defined, "defined");
struct defined_name : identifier {};
struct defined_call
    : p::seq<kw_defined, p::must<lparen>, p::must<defined_name>, p::must<paren_close>> {};

struct builtin_constant_words {
    static constexpr std::array<std::string_view, 25> list = {
        "clock", "clock_delta", "clock_on", "false", "final_clock", "final_frame", "frame_number",
        "image_height", "image_width", "initial_clock", "initial_frame", "no", "off", "on", "pi",
        "t", "tau", "true", "u", "v", "version", "x", "y", "yes", "z"};
};
struct builtin_constant_name : one_word_of<builtin_constant_words> {};
struct builtin_constant : p::seq<builtin_constant_name, ws> {};

// Colours: rgb <..>, rgbf, rgbt, rgbft, srgb..., and `color red 1 green .5`.
struct colour_model_words {
    static constexpr std::array<std::string_view, 8> list = {
        "rgb", "rgbf", "rgbft", "rgbt", "srgb", "srgbf", "srgbft", "srgbt"};
};
struct colour_model : one_word_of<colour_model_words> {};
// POV-Ray's rgb takes a whole sum: rgb <.1,.2,.3> + .5 leaves filter at 0.
struct colour_model_argument : p::seq<sum> {};
struct colour_model_literal : p::seq<colour_model, ws, p::must<colour_model_argument>> {};
struct colour_component_words {
    static constexpr std::array<std::string_view, 5> list = {
        "blue", "filter", "green", "red", "transmit"};
};
struct colour_component_name : one_word_of<colour_component_words> {};
struct colour_component_value : p::seq<unary> {};
struct colour_component_setting
    : p::seq<colour_component_name, ws, p::must<colour_component_value>> {};
struct colour_keyword : p::seq<p::sor<TAO_PEGTL_KEYWORD("color"), TAO_PEGTL_KEYWORD("colour")>, ws> {};
struct colour_base : p::seq<p::not_at<colour_component_name>, unary> {};
struct colour_expression
    : p::seq<colour_keyword, p::opt<colour_base>, p::star<colour_component_setting>> {};

// A call of a declared macro; the body is spliced in where the call stands.
struct value_item;

// A declared name used as a value.
struct reference : identifier {};

struct primary
    : p::sor<number, string_literal, vector_literal, paren_expression, function_call,
             colour_model_literal, colour_expression, defined_call, builtin_constant,
             macro_call<value_item>, reference> {};

struct component_name
    : p::sor<TAO_PEGTL_KEYWORD("x"), TAO_PEGTL_KEYWORD("y"), TAO_PEGTL_KEYWORD("z"),
             TAO_PEGTL_KEYWORD("t"), TAO_PEGTL_KEYWORD("u"), TAO_PEGTL_KEYWORD("v"),
             TAO_PEGTL_KEYWORD("red"), TAO_PEGTL_KEYWORD("green"), TAO_PEGTL_KEYWORD("blue"),
             TAO_PEGTL_KEYWORD("filter"), TAO_PEGTL_KEYWORD("transmit"),
             TAO_PEGTL_KEYWORD("gray"), TAO_PEGTL_KEYWORD("grey")> {};
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
struct sum : p::seq<product, p::star<p::sor<addition, subtraction>>> {};

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
struct conditional_tail
    : p::seq<p::one<'?'>, ws, p::must<conditional_branch>, p::must<colon>,
             p::must<conditional_branch>> {};
struct expression : p::seq<disjunction, p::opt<conditional_tail>> {};

// ---------------------------------------------------------------- skipping

// Text read without being run: a false #if branch, a loop or macro body
// being stepped over. Strings and comments are skipped whole, nested
// directive blocks as a unit.
namespace skip {
struct string_raw : p::seq<p::one<'"'>, p::until<p::one<'"'>, p::sor<p::seq<p::one<'\\'>, p::any>, p::any>>> {};
struct blanks : p::star<p::blank> {};
struct separators : p::star<separator> {};
struct divider_word
    : p::sor<TAO_PEGTL_KEYWORD("else"), TAO_PEGTL_KEYWORD("elseif"), TAO_PEGTL_KEYWORD("end"),
             TAO_PEGTL_KEYWORD("case"), TAO_PEGTL_KEYWORD("range"), TAO_PEGTL_KEYWORD("break")> {};
struct divider : p::seq<p::one<'#'>, blanks, divider_word> {};
struct end : p::seq<p::one<'#'>, blanks, TAO_PEGTL_KEYWORD("end")> {};
struct opener
    : p::seq<p::one<'#'>, blanks,
             p::sor<TAO_PEGTL_KEYWORD("if"), TAO_PEGTL_KEYWORD("ifdef"), TAO_PEGTL_KEYWORD("ifndef"),
                    TAO_PEGTL_KEYWORD("while"), TAO_PEGTL_KEYWORD("for"),
                    TAO_PEGTL_KEYWORD("switch"), TAO_PEGTL_KEYWORD("macro")>> {};
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
    : p::seq<opener, p::star<p::sor<token, p::seq<p::not_at<end>, divider>>>, p::must<nested_end>> {};
// A { ... } block with everything inside it.
struct braced;
struct braced_plain : p::plus<p::not_one<'/', '"', '{', '}'>> {};
struct braced_token : p::sor<braced_plain, separator, string_raw, braced, p::not_one<'{', '}'>> {};
struct braced_close : p::one<'}'> {};
struct braced : p::seq<p::one<'{'>, p::star<braced_token>, p::must<braced_close>> {};
struct until_rbrace : p::star<braced_token> {};

struct parenthesized;
struct paren_plain : p::plus<p::not_one<'/', '"', '(', ')'>> {};
struct paren_token : p::sor<paren_plain, separator, string_raw, parenthesized, p::not_one<'(', ')'>> {};
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

// ---------------------------------------------------------------- directives

HEXANT_KEYWORD(kw_declare, "declare");
HEXANT_KEYWORD(kw_local, "local");
HEXANT_KEYWORD(kw_undef, "undef");
HEXANT_KEYWORD(kw_version, "version");
HEXANT_KEYWORD(kw_debug, "debug");
HEXANT_KEYWORD(kw_warning, "warning");
HEXANT_KEYWORD(kw_error, "error");
HEXANT_KEYWORD(kw_default, "default");

struct hash : p::seq<p::one<'#'>, skip::blanks> {};

// #declare NAME = value; #declare NAME[i][j] = value; #local likewise.
struct declare_kind : p::sor<kw_declare, kw_local> {};
struct declare_index : p::seq<lbracket, p::must<index_value>, p::must<index_close>> {};
struct declare_name : identifier {};
struct declare_target : p::seq<frame_open, declare_name, p::star<declare_index>> {};
struct declare_equals : equals {};
// The value of a #declare; a custom rule so that a declaration using
// something hexant lacks is kept unevaluated instead of failing.
struct declared_value_item {};
HEXANT_CUSTOM_RULE(declared_value_rule, declare_value);
struct declared_value : declared_value_rule<declared_value_item> {};
// POV-Ray 3.7: #declare deprecated [once] "message" NAME = ...
struct declare_deprecation
    : p::seq<TAO_PEGTL_KEYWORD("deprecated"), ws, p::opt<TAO_PEGTL_KEYWORD("once"), ws>,
             p::must<ignored_value>> {};
struct declare_directive
    : p::seq<declare_kind, p::opt<declare_deprecation>, p::must<declare_target>, p::must<declare_equals>,
             p::must<declared_value>, p::opt<semicolon>> {};

struct undef_name : identifier {};
struct undef_directive : p::seq<kw_undef, p::must<undef_name>> {};
struct version_value : p::seq<expression> {};
struct version_directive : p::seq<kw_version, p::must<version_value>, p::opt<semicolon>> {};
struct message_text : p::seq<expression> {};
struct debug_directive : p::seq<kw_debug, p::must<message_text>> {};
struct warning_directive : p::seq<kw_warning, p::must<message_text>> {};
struct error_directive : p::seq<kw_error, p::must<message_text>> {};

// #if, #ifdef, #ifndef, #while, #for, #switch, #macro, #include and macro
// calls are custom rules (above), with Item the kind of thing their bodies hold.

// The parts the custom rules read with the grammar.
struct condition_close : rparen {};
struct condition_value : p::seq<expression> {};
struct condition : p::seq<lparen, p::must<condition_value>, p::must<condition_close>> {};
struct include_name : p::seq<expression> {};
struct macro_name : identifier {};
struct macro_parameter : identifier {};
struct macro_parameters
    : p::seq<lparen, p::opt<macro_parameter, p::star<comma, p::must<macro_parameter>>>,
             p::must<rparen>> {};
struct for_variable : identifier {};
struct for_bound : p::seq<expression> {};
struct for_header
    : p::seq<lparen, p::must<for_variable>, p::must<comma>, p::must<for_bound>, p::must<comma>,
             p::must<for_bound>, p::opt<comma, p::must<for_bound>>, p::must<condition_close>> {};
struct range_header
    : p::seq<lparen, p::must<condition_value>, p::must<comma>, p::must<condition_value>,
             p::must<condition_close>> {};
struct macro_body_end : p::eof {};
struct include_end : p::eof {};

struct unsupported_directive
    : p::sor<TAO_PEGTL_KEYWORD("fopen"), TAO_PEGTL_KEYWORD("fclose"), TAO_PEGTL_KEYWORD("read"),
             TAO_PEGTL_KEYWORD("write"), TAO_PEGTL_KEYWORD("render"),
             TAO_PEGTL_KEYWORD("statistics")> {};
// Anything after '#' that is not a directive, nor a block's divider.
struct unknown_directive : p::seq<p::not_at<skip::divider_word>, p::identifier_first> {};

struct default_block;
template <typename Item>
struct directive
    : p::seq<hash,
             p::sor<declare_directive, if_directive<Item>, ifdef_directive<Item>,
                    while_directive<Item>, for_directive<Item>, switch_directive<Item>,
                    include_directive<Item>, macro_definition, undef_directive, version_directive,
                    debug_directive, warning_directive, error_directive, default_block,
                    unsupported_directive, unknown_directive>> {};

// ---------------------------------------------------------------- modifiers

HEXANT_KEYWORD(kw_translate, "translate");
HEXANT_KEYWORD(kw_rotate, "rotate");
HEXANT_KEYWORD(kw_scale, "scale");
HEXANT_KEYWORD(kw_matrix, "matrix");
HEXANT_KEYWORD(kw_transform, "transform");
HEXANT_KEYWORD(kw_inverse, "inverse");

struct transform_amount : p::seq<expression> {};
struct translate_step : p::seq<kw_translate, p::must<transform_amount>> {};
struct rotate_step : p::seq<kw_rotate, p::must<transform_amount>> {};
struct scale_step : p::seq<kw_scale, p::must<transform_amount>> {};
struct matrix_entry : p::seq<sum> {};
struct matrix_open : langle {};
struct matrix_close : rangle {};
struct matrix_step
    : p::seq<kw_matrix, p::must<matrix_open>, frame_open, p::must<matrix_entry>,
             p::star<comma, p::must<matrix_entry>>, p::must<matrix_close>> {};
struct transform_block;
struct transform_reference : p::seq<expression> {};
struct transform_argument : p::sor<transform_block, transform_reference> {};
struct transform_step : p::seq<kw_transform, p::must<transform_argument>> {};
struct transformation
    : p::sor<translate_step, rotate_step, scale_step, matrix_step, transform_step> {};

// transform { [IDENT] steps [inverse] }
struct transform_open : p::seq<lbrace> {};
struct transform_inverse : kw_inverse {};
struct transform_item
    : p::sor<directive<transform_item>, macro_call<transform_item>, transformation,
             transform_inverse> {};
struct transform_base : p::seq<p::not_at<kw_inverse>, expression> {};
struct transform_block
    : p::seq<transform_open, p::opt<transform_base>, p::star<transform_item>, p::must<rbrace>> {};
struct transform_value : p::seq<kw_transform, p::must<transform_block>> {};

// hexant's deformations: twist <axis>, DEGREES_PER_UNIT; taper <axis>, FACTOR;
// bend <axis>, DEGREES.
struct deformation_name
    : p::sor<TAO_PEGTL_KEYWORD("twist"), TAO_PEGTL_KEYWORD("taper"), TAO_PEGTL_KEYWORD("bend")> {};
struct deformation_axis : p::seq<sum> {};
struct deformation_amount : p::seq<expression> {};
struct deformation
    : p::seq<deformation_name, ws, p::must<deformation_axis>, p::must<comma>,
             p::must<deformation_amount>> {};

// ---------------------------------------------------------------- textures

HEXANT_KEYWORD(kw_pigment, "pigment");
HEXANT_KEYWORD(kw_finish, "finish");
HEXANT_KEYWORD(kw_texture, "texture");
HEXANT_KEYWORD(kw_normal, "normal");
HEXANT_KEYWORD(kw_interior, "interior");
HEXANT_KEYWORD(kw_material, "material");

// Patterns POV-Ray has and hexant does not: parsed, kept by name, an error
// only where a scene uses them.
struct unsupported_pattern_name
    : p::sor<TAO_PEGTL_KEYWORD("average"), TAO_PEGTL_KEYWORD("facets"),
             TAO_PEGTL_KEYWORD("function"), TAO_PEGTL_KEYWORD("julia"), TAO_PEGTL_KEYWORD("pavement"),
             TAO_PEGTL_KEYWORD("tiling"), TAO_PEGTL_KEYWORD("cubic"), TAO_PEGTL_KEYWORD("object"),
             TAO_PEGTL_KEYWORD("slope"), TAO_PEGTL_KEYWORD("aoi"), TAO_PEGTL_KEYWORD("density_file"),
             TAO_PEGTL_KEYWORD("image_pattern"), TAO_PEGTL_KEYWORD("bump_map"),
             TAO_PEGTL_KEYWORD("wave")> {};
struct unsupported_pattern : p::seq<unsupported_pattern_name, skip::until_rbrace> {};
// uv_mapping in a pigment, a normal or a texture: what follows in the
// block is read at the surface's (u, v, 0) (runtime/texture/material.hpp).
struct uv_mapping : p::seq<TAO_PEGTL_KEYWORD("uv_mapping"), ws> {};

// The patterns hexant has (runtime/texture/pattern/kinds.hpp, whose list
// gives these words), each followed by what its kind takes: a vector
// (gradient), a number (spiral1, spiral2, mandel) or a list of colours (the
// block patterns).
struct pattern_words {
    static constexpr auto list = runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::keywords;
};
struct pattern_name : one_word_of<pattern_words> {};
struct pattern_argument : p::seq<sum> {};
struct pattern_kind
    : p::seq<pattern_name, ws, frame_open,
             p::opt<pattern_argument, p::star<p::opt<comma>, pattern_argument>>> {};
// The pattern modifiers (POV-Ray's Parse_Pattern), each with one value:
// those of every pattern, and the kinds' own (mortar, metric, ...: each
// kind's file declares its settings).
struct pattern_kind_setting_words {
    static constexpr auto list = runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::settings;
};
struct pattern_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("frequency"), TAO_PEGTL_KEYWORD("phase"),
             TAO_PEGTL_KEYWORD("turbulence"), TAO_PEGTL_KEYWORD("octaves"),
             TAO_PEGTL_KEYWORD("omega"), TAO_PEGTL_KEYWORD("lambda"),
             TAO_PEGTL_KEYWORD("noise_generator"), one_word_of<pattern_kind_setting_words>> {};
struct pattern_setting_value : p::seq<expression> {};
struct pattern_setting : p::seq<pattern_setting_name, ws, p::must<pattern_setting_value>> {};
struct pattern_wave_name
    : p::sor<TAO_PEGTL_KEYWORD("ramp_wave"), TAO_PEGTL_KEYWORD("sine_wave"),
             TAO_PEGTL_KEYWORD("triangle_wave"), TAO_PEGTL_KEYWORD("scallop_wave"),
             TAO_PEGTL_KEYWORD("cubic_wave"), TAO_PEGTL_KEYWORD("poly_wave")> {};
struct pattern_wave : p::seq<pattern_wave_name, ws, frame_open, p::opt<pattern_argument>> {};
// warp { turbulence <x, y, z> [octaves N] [omega W] [lambda L] }
struct warp_turbulence_keyword : TAO_PEGTL_KEYWORD("turbulence") {};
struct warp_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("octaves"), TAO_PEGTL_KEYWORD("omega"), TAO_PEGTL_KEYWORD("lambda")> {};
struct warp_setting : p::seq<warp_setting_name, ws, p::must<pattern_setting_value>> {};
struct warp_open : p::seq<TAO_PEGTL_KEYWORD("warp"), ws, p::must<lbrace>> {};
struct warp_turbulence : p::seq<pattern_setting_value> {};
struct warp_block
    : p::seq<warp_open, p::must<warp_turbulence_keyword>, ws, p::must<warp_turbulence>,
             p::star<warp_setting>, p::must<rbrace>> {};

// color_map { [value colour] ... }, or a declared one; POV-Ray's older
// [value1, value2 colour1 colour2] too.
struct colour_map_open
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("color_map"), TAO_PEGTL_KEYWORD("colour_map")>, ws, p::must<lbrace>> {};
// (A name followed by '(' is a macro writing the entries, not a declared map.)
struct colour_map_base : p::seq<p::not_at<p::identifier, ws, lparen>, expression> {};
struct colour_map_item : p::seq<sum> {};
struct colour_map_entry
    : p::seq<lbracket, frame_open, p::must<colour_map_item>,
             p::star<p::opt<comma>, colour_map_item>, p::must<rbracket>> {};
// (Directives and macros may write the entries: #for, #if, a macro that
// expands to [v colour].)
struct colour_map_element
    : p::sor<directive<colour_map_element>, macro_call<colour_map_element>, colour_map_entry> {};
struct colour_map_block
    : p::seq<colour_map_open, p::opt<colour_map_base>, p::star<colour_map_element>, p::must<rbrace>> {};
struct pigment_colour_map : p::seq<colour_map_block> {};

struct pigment_open : p::seq<kw_pigment, p::must<lbrace>> {};
struct pigment_base : p::seq<p::not_at<pattern_name>, expression> {};
struct pigment_item;
// pigment_map { [value PIGMENT_BODY] ... }: each entry a pigment's inside
// (a declared pigment, a colour, or a pattern with its modifiers).
struct pigment_map_value : p::seq<sum> {};
struct pigment_map_pigment_open : p::success {};
struct pigment_map_entry
    : p::seq<lbracket, p::must<pigment_map_value>, p::opt<comma>, pigment_map_pigment_open,
             p::opt<pigment_base>, p::star<pigment_item>, p::must<rbracket>> {};
struct pigment_map_open : p::seq<TAO_PEGTL_KEYWORD("pigment_map"), ws, p::must<lbrace>> {};
struct pigment_map_element
    : p::sor<directive<pigment_map_element>, macro_call<pigment_map_element>, pigment_map_entry> {};
struct pigment_map_block : p::seq<pigment_map_open, p::star<pigment_map_element>, p::must<rbrace>> {};
// image_map { [TYPE] "file" [gamma G] [premultiplied B] settings }: POV-Ray's
// Parse_Image and Parse_Image_Map.
struct image_map_open : p::seq<TAO_PEGTL_KEYWORD("image_map"), ws, p::must<lbrace>> {};
struct image_file_type
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("png"), TAO_PEGTL_KEYWORD("exr"), TAO_PEGTL_KEYWORD("gif"),
                    TAO_PEGTL_KEYWORD("tga"), TAO_PEGTL_KEYWORD("iff"), TAO_PEGTL_KEYWORD("ppm"),
                    TAO_PEGTL_KEYWORD("pgm"), TAO_PEGTL_KEYWORD("jpeg"), TAO_PEGTL_KEYWORD("tiff"),
                    TAO_PEGTL_KEYWORD("bmp"), TAO_PEGTL_KEYWORD("hdr"), TAO_PEGTL_KEYWORD("sys")>,
             ws> {};
struct image_map_file : p::seq<sum> {};
struct image_map_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("map_type"), TAO_PEGTL_KEYWORD("interpolate"), TAO_PEGTL_KEYWORD("premultiplied"),
             TAO_PEGTL_KEYWORD("repeat"), TAO_PEGTL_KEYWORD("offset")> {};
struct image_map_setting : p::seq<image_map_setting_name, ws, p::must<pattern_setting_value>> {};
// gamma G, or gamma srgb.
struct image_map_gamma_srgb : p::seq<TAO_PEGTL_KEYWORD("srgb"), ws> {};
struct image_map_gamma
    : p::seq<TAO_PEGTL_KEYWORD("gamma"), ws, p::sor<image_map_gamma_srgb, p::must<pattern_setting_value>>> {};
struct image_map_flag
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("once"), TAO_PEGTL_KEYWORD("use_colour"), TAO_PEGTL_KEYWORD("use_color"),
                    TAO_PEGTL_KEYWORD("use_index")>,
             ws> {};
// filter all F, transmit all T; filter N F (a palette entry's).
struct image_map_all : p::seq<TAO_PEGTL_KEYWORD("all"), ws> {};
struct image_map_amount : p::seq<sum> {};
struct image_map_filter_name : p::sor<TAO_PEGTL_KEYWORD("filter"), TAO_PEGTL_KEYWORD("transmit")> {};
struct image_map_filter
    : p::seq<image_map_filter_name, ws, frame_open,
             p::opt<image_map_all>, p::must<image_map_amount>, p::opt<p::opt<comma>, image_map_amount>> {};
struct image_map_item : p::sor<image_map_gamma, image_map_setting, image_map_flag, image_map_filter> {};
struct image_map_block
    : p::seq<image_map_open, p::opt<image_file_type>, p::must<image_map_file>, p::star<image_map_item>,
             p::must<rbrace>> {};
struct pigment_block;
// A block pattern's pigments: checker pigment { } pigment { }.
struct pigment_list_pigment : p::seq<pigment_block, p::opt<comma>> {};
struct pigment_item
    : p::sor<directive<pigment_item>, macro_call<pigment_item>, pattern_kind, pattern_setting,
             pattern_wave, warp_block, pigment_colour_map, pigment_map_block, image_map_block, pigment_list_pigment,
             uv_mapping, unsupported_pattern, transformation> {};
struct pigment_block
    : p::seq<pigment_open, p::opt<pigment_base>, p::star<pigment_item>, p::must<rbrace>> {};

struct finish_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("ambient"), TAO_PEGTL_KEYWORD("diffuse"),
             TAO_PEGTL_KEYWORD("brilliance"), TAO_PEGTL_KEYWORD("phong_size"),
             TAO_PEGTL_KEYWORD("phong"), TAO_PEGTL_KEYWORD("specular"),
             TAO_PEGTL_KEYWORD("roughness"), TAO_PEGTL_KEYWORD("emission"),
             TAO_PEGTL_KEYWORD("crand")> {};
struct finish_setting_value : p::seq<expression> {};
struct finish_setting : p::seq<finish_setting_name, ws, p::must<finish_setting_value>> {};
struct reflection_value : p::seq<expression> {};
struct reflection_option
    : p::sor<p::seq<p::sor<TAO_PEGTL_KEYWORD("falloff"), TAO_PEGTL_KEYWORD("exponent"),
                           TAO_PEGTL_KEYWORD("metallic")>,
                    ws, p::must<ignored_value>>,
             p::seq<TAO_PEGTL_KEYWORD("fresnel"), ws, p::opt<ignored_value>>,
             p::seq<comma, p::opt<ignored_value>>> {};  // the maximum: hexant uses the minimum
struct reflection_ignored_option : reflection_option {};
struct reflection_block
    : p::seq<lbrace, p::must<reflection_value>, p::star<reflection_ignored_option>,
             p::must<rbrace>> {};
struct reflection_amount : p::sor<reflection_block, reflection_value> {};
struct reflection_setting
    : p::seq<TAO_PEGTL_KEYWORD("reflection"), ws, p::must<reflection_amount>> {};
struct finish_flag
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("conserve_energy"), TAO_PEGTL_KEYWORD("fresnel"),
                    TAO_PEGTL_KEYWORD("metallic")>,
             ws, p::opt<ignored_value>> {};
struct finish_ignored_block
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("irid"), TAO_PEGTL_KEYWORD("subsurface")>, ws, skip::braced, ws> {};
struct finish_open : p::seq<kw_finish, p::must<lbrace>> {};
struct finish_base : p::seq<expression> {};
struct finish_item
    : p::sor<directive<finish_item>, macro_call<finish_item>, finish_setting, reflection_setting,
             finish_flag, finish_ignored_block> {};
struct finish_block
    : p::seq<finish_open, p::opt<finish_base>, p::star<finish_item>, p::must<rbrace>> {};

// normal { PATTERN [AMOUNT] modifiers }, or a declared one: the same
// pattern rules as a pigment's, with bump_size, accuracy, no_bump_scale.
struct normal_open : p::seq<kw_normal, p::must<lbrace>> {};
struct normal_base : p::seq<p::not_at<pattern_name>, expression> {};
struct normal_setting_name : p::sor<TAO_PEGTL_KEYWORD("bump_size"), TAO_PEGTL_KEYWORD("accuracy")> {};
struct normal_setting : p::seq<normal_setting_name, ws, p::must<pattern_setting_value>> {};
struct normal_no_bump_scale : p::seq<TAO_PEGTL_KEYWORD("no_bump_scale"), ws> {};
struct normal_item;
// normal_map { [value NORMAL_BODY] ... }: each entry a normal's inside.
struct normal_map_value : p::seq<sum> {};
struct normal_map_normal_open : p::success {};
struct normal_map_entry
    : p::seq<lbracket, p::must<normal_map_value>, p::opt<comma>, normal_map_normal_open, p::opt<normal_base>,
             p::star<normal_item>, p::must<rbracket>> {};
struct normal_map_open : p::seq<TAO_PEGTL_KEYWORD("normal_map"), ws, p::must<lbrace>> {};
struct normal_map_element
    : p::sor<directive<normal_map_element>, macro_call<normal_map_element>, normal_map_entry> {};
struct normal_map_block : p::seq<normal_map_open, p::star<normal_map_element>, p::must<rbrace>> {};
// slope_map { [value <height, slope>] ... }
struct slope_map_item : p::seq<sum> {};
struct slope_map_entry
    : p::seq<lbracket, frame_open, p::must<slope_map_item>, p::opt<comma>, p::must<slope_map_item>,
             p::must<rbracket>> {};
struct slope_map_open : p::seq<TAO_PEGTL_KEYWORD("slope_map"), ws, p::must<lbrace>> {};
struct slope_map_element
    : p::sor<directive<slope_map_element>, macro_call<slope_map_element>, slope_map_entry> {};
struct slope_map_block : p::seq<slope_map_open, p::star<slope_map_element>, p::must<rbrace>> {};
struct normal_block;
// A block pattern's normals: checker normal { } normal { }.
struct normal_list_normal : p::seq<normal_block, p::opt<comma>> {};
struct normal_item
    : p::sor<directive<normal_item>, macro_call<normal_item>, pattern_kind, pattern_setting, pattern_wave,
             warp_block, normal_setting, normal_no_bump_scale, normal_map_block, slope_map_block,
             normal_list_normal, uv_mapping, unsupported_pattern, transformation> {};
struct normal_block : p::seq<normal_open, p::opt<normal_base>, p::star<normal_item>, p::must<rbrace>> {};
struct texture_normal : p::seq<normal_block> {};
struct object_normal : p::seq<normal_block> {};
struct camera_normal : p::seq<normal_block> {};

struct interior_open : p::seq<kw_interior, p::must<lbrace>> {};
struct interior_base : p::seq<expression> {};
struct ior_value : p::seq<expression> {};
struct ior_setting : p::seq<TAO_PEGTL_KEYWORD("ior"), ws, p::must<ior_value>> {};
struct interior_ignored_setting
    : p::sor<p::seq<p::sor<TAO_PEGTL_KEYWORD("caustics"), TAO_PEGTL_KEYWORD("dispersion"),
                           TAO_PEGTL_KEYWORD("dispersion_samples"),
                           TAO_PEGTL_KEYWORD("fade_distance"), TAO_PEGTL_KEYWORD("fade_power"),
                           TAO_PEGTL_KEYWORD("fade_color"), TAO_PEGTL_KEYWORD("fade_colour")>,
                    ws, p::must<ignored_value>>,
             p::seq<TAO_PEGTL_KEYWORD("media"), ws, p::must<skipped_block>, ws>> {};
struct interior_item
    : p::sor<directive<interior_item>, macro_call<interior_item>, ior_setting,
             interior_ignored_setting> {};
struct interior_block
    : p::seq<interior_open, p::opt<interior_base>, p::star<interior_item>, p::must<rbrace>> {};

struct texture_open : p::seq<kw_texture, p::must<lbrace>> {};
struct texture_base : p::seq<p::not_at<pattern_name>, expression> {};
struct texture_pigment : p::seq<pigment_block> {};
struct texture_finish : p::seq<finish_block> {};
struct texture_item;
// texture_map { [value TEXTURE_BODY] ... }: each entry a texture's inside.
struct texture_map_value : p::seq<sum> {};
struct texture_map_texture_open : p::success {};
struct texture_map_entry
    : p::seq<lbracket, p::must<texture_map_value>, p::opt<comma>, texture_map_texture_open,
             p::opt<texture_base>, p::star<texture_item>, p::must<rbracket>> {};
struct texture_map_open : p::seq<TAO_PEGTL_KEYWORD("texture_map"), ws, p::must<lbrace>> {};
struct texture_map_element
    : p::sor<directive<texture_map_element>, macro_call<texture_map_element>, texture_map_entry> {};
struct texture_map_block : p::seq<texture_map_open, p::star<texture_map_element>, p::must<rbrace>> {};
struct texture_block;
// A block pattern's textures: checker texture { } texture { }.
struct texture_list_texture : p::seq<texture_block, p::opt<comma>> {};
// A patterned texture: a pattern and its modifiers, then its map.
struct texture_item
    : p::sor<directive<texture_item>, macro_call<texture_item>, texture_pigment, texture_finish,
             texture_normal, pattern_kind, pattern_setting, pattern_wave, warp_block, texture_map_block,
             texture_list_texture, uv_mapping, transformation> {};
struct texture_block
    : p::seq<texture_open, p::opt<texture_base>, p::star<texture_item>, p::must<rbrace>> {};

// material { texture { } interior { } }
struct material_open : p::seq<kw_material, p::must<lbrace>> {};
struct material_base : p::seq<expression> {};
struct material_texture : p::seq<texture_block> {};
struct material_interior : p::seq<interior_block> {};
struct material_item
    : p::sor<directive<material_item>, material_texture, material_interior, transformation> {};
struct material_block
    : p::seq<material_open, p::opt<material_base>, p::star<material_item>, p::must<rbrace>> {};

// ---------------------------------------------------------------- objects

struct object_value;
struct object_modifier;
struct object_modifiers : p::star<object_modifier> {};
struct object_close : rbrace {};

// A shape's leading arguments: values separated by commas, which POV-Ray
// lets one leave out.
struct shape_argument : p::seq<sum> {};
// Where a comma is left out, a macro call starts the modifiers, not another
// argument: sphere { 0, R Move() } (as in POV-Ray, whose expressions end there).
struct macro_ahead_item {};
HEXANT_CUSTOM_RULE(macro_ahead_rule, macro_ahead);
struct macro_ahead : macro_ahead_rule<macro_ahead_item> {};
// A conditional directive among the arguments (POV-Ray reads directives
// anywhere): `#if`, `#ifdef` or `#ifndef` whose condition is followed by a
// value, as in smooth_triangle { #if (Flip) <0,0,0>, -y, ... #else ... #end }
// or cylinder { 0, #if (A) x #else y #end, 1 }. It is told from a directive
// among the modifiers (sphere { 0, 1 #if (A) translate x #end }) by the
// first word or character after the condition, before anything runs: the
// interpreter runs directives as it reads, so they cannot be tried twice
// (Interpreter::argument_directive_ahead says which words are values).
struct argument_directive_ahead_item {};
HEXANT_CUSTOM_RULE(argument_directive_ahead_rule, argument_directive_ahead);
struct argument_directive_ahead : argument_directive_ahead_rule<argument_directive_ahead_item> {};
struct shape_argument_item;
struct argument_directive : p::seq<argument_directive_ahead, directive<shape_argument_item>> {};
// What a directive's branch among the arguments holds: arguments, commas
// and further such directives.
struct shape_argument_item
    : p::sor<argument_directive, comma, p::seq<p::not_at<macro_ahead>, shape_argument>> {};
struct first_shape_argument : p::sor<argument_directive, shape_argument> {};
struct shape_arguments
    : p::seq<frame_open, first_shape_argument,
             p::star<p::sor<argument_directive, p::seq<comma, p::must<first_shape_argument>>,
                            p::seq<p::not_at<macro_ahead>, shape_argument>>>> {};

// A registered object kind (runtime/objects/kinds.hpp): its keyword, the
// option words it may take before its values (prism's linear_sweep), its
// values, and modifiers. The kind itself reads what it was given.
struct shape_keyword_words {
    static constexpr auto list = runtime::objects::KindWords<runtime::ShapeKinds>::block_keywords;
};
struct shape_option_words {
    static constexpr auto list = runtime::objects::KindWords<runtime::ShapeKinds>::options;
};
struct shape_keyword : one_word_of<shape_keyword_words> {};
struct shape_open : p::seq<shape_keyword, ws, p::must<lbrace>> {};
struct shape_option : p::seq<one_word_of<shape_option_words>, ws> {};
struct shape_block
    : p::seq<shape_open, p::star<shape_option>, p::must<shape_arguments>, object_modifiers,
             p::must<object_close>> {};

HEXANT_KEYWORD(kw_union, "union");
HEXANT_KEYWORD(kw_merge, "merge");
HEXANT_KEYWORD(kw_intersection, "intersection");
HEXANT_KEYWORD(kw_difference, "difference");
HEXANT_KEYWORD(kw_motion_blur, "motion_blur");
struct csg_kind : p::sor<kw_union, kw_merge, kw_intersection, kw_difference, kw_motion_blur> {};
struct csg_open : p::seq<csg_kind, p::must<lbrace>> {};
struct unsupported_block;
struct csg_child : p::sor<object_value, unsupported_block> {};
struct csg_item
    : p::sor<directive<csg_item>, macro_call<csg_item>, csg_child, object_modifier> {};
struct csg_block : p::seq<csg_open, p::star<csg_item>, p::must<object_close>> {};

// object { IDENT modifiers } or object { shape modifiers }
HEXANT_KEYWORD(kw_object, "object");
struct object_base : p::sor<object_value, expression> {};
struct object_block
    : p::seq<kw_object, p::must<lbrace>, p::must<object_base>, object_modifiers,
             p::must<object_close>> {};

// light_source { <position>, colour modifiers }
HEXANT_KEYWORD(kw_light_source, "light_source");
// The colour may be left out (POV-Ray: white).
struct light_arguments
    : p::seq<frame_open, p::must<shape_argument>,
             p::opt<p::opt<comma>, p::not_at<macro_ahead>, shape_argument>> {};
struct light_flag
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("shadowless"), TAO_PEGTL_KEYWORD("spotlight"),
                    TAO_PEGTL_KEYWORD("cylinder"), TAO_PEGTL_KEYWORD("parallel"),
                    TAO_PEGTL_KEYWORD("jitter"), TAO_PEGTL_KEYWORD("circular"),
                    TAO_PEGTL_KEYWORD("orient")>,
             ws> {};
struct light_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("point_at"), TAO_PEGTL_KEYWORD("radius"),
             TAO_PEGTL_KEYWORD("falloff"), TAO_PEGTL_KEYWORD("tightness"),
             TAO_PEGTL_KEYWORD("adaptive"), TAO_PEGTL_KEYWORD("fade_distance"),
             TAO_PEGTL_KEYWORD("fade_power"), TAO_PEGTL_KEYWORD("media_interaction"),
             TAO_PEGTL_KEYWORD("media_attenuation")> {};
struct light_setting_value : p::seq<expression> {};
struct light_setting : p::seq<light_setting_name, ws, p::must<light_setting_value>> {};
struct area_light_argument : p::seq<sum> {};
// (The commas are optional, as POV-Ray's Parse_Comma.)
struct area_light
    : p::seq<TAO_PEGTL_KEYWORD("area_light"), ws, frame_open, p::must<area_light_argument>,
             p::opt<comma>, p::must<area_light_argument>, p::opt<comma>,
             p::must<area_light_argument>, p::opt<comma>, p::must<area_light_argument>> {};
// looks_like { OBJECT modifiers }, as object { }; POV-Ray moves the object
// to the light before its modifiers (looks_like_base).
struct looks_like_base : object_base {};
struct light_looks_like
    : p::seq<TAO_PEGTL_KEYWORD("looks_like"), ws, p::must<lbrace>, p::must<looks_like_base>, object_modifiers,
             p::must<object_close>> {};
struct light_projected_through
    : p::seq<TAO_PEGTL_KEYWORD("projected_through"), ws, p::must<skipped_block>, ws> {};
struct light_item
    : p::sor<directive<light_item>, macro_call<light_item>, light_flag, light_setting,
             area_light, light_looks_like, light_projected_through, transformation> {};
struct light_block
    : p::seq<kw_light_source, p::must<lbrace>, p::must<light_arguments>, p::star<light_item>,
             p::must<object_close>> {};

// Object kinds POV-Ray has and hexant does not: kept as source, an error
// only where used. Also `function { }` and the *_map blocks.
struct unsupported_kind_words {
    static constexpr std::array<std::string_view, 23> list = {
        "bicubic_patch", "color_map", "colour_map", "cubic", "density", "density_map",
        "function", "isosurface", "julia_fractal", "lemon",
        "media", "normal_map", "ovus", "parametric", "photons", "pigment_map",
        "poly", "polynomial", "quadric", "quartic", "rainbow", "slope_map",
        "texture_map"};
};
struct unsupported_kind : one_word_of<unsupported_kind_words> {};
struct unsupported_block
    : p::seq<unsupported_kind, ws, p::opt<skip::parenthesized, ws>, p::must<skipped_block>, ws> {};

// mesh { triangle { .. } smooth_triangle { .. } ... modifiers }: its
// triangles are read as objects and taken apart (runtime/objects/mesh/).
struct mesh_open : p::seq<TAO_PEGTL_KEYWORD("mesh"), ws, p::must<lbrace>> {};
struct mesh_triangle : p::seq<object_value> {};
struct mesh_inside_vector_value : p::seq<expression> {};
struct mesh_inside_vector
    : p::seq<TAO_PEGTL_KEYWORD("inside_vector"), ws, p::must<mesh_inside_vector_value>> {};
// hierarchy on|off: read; hexant's mesh always has its hierarchy.
struct mesh_hierarchy_value : p::seq<expression> {};
struct mesh_hierarchy
    : p::seq<TAO_PEGTL_KEYWORD("hierarchy"), ws, p::opt<mesh_hierarchy_value>> {};
struct mesh_item
    : p::sor<directive<mesh_item>, macro_call<mesh_item>, mesh_inside_vector, mesh_hierarchy,
             mesh_triangle, object_modifier> {};
struct mesh_block : p::seq<mesh_open, p::star<mesh_item>, p::must<object_close>> {};

// mesh2 { vertex_vectors { N, <..> ... } normal_vectors { } uv_vectors { }
// texture_list { N, texture { } ... } face_indices { N, <a, b, c> [, t
// [, t2, t3]] ... } normal_indices { } uv_indices { } modifiers }
struct mesh2_open : p::seq<TAO_PEGTL_KEYWORD("mesh2"), ws, p::must<lbrace>> {};
struct mesh2_section_name
    : p::sor<TAO_PEGTL_KEYWORD("vertex_vectors"), TAO_PEGTL_KEYWORD("normal_vectors"),
             TAO_PEGTL_KEYWORD("uv_vectors"), TAO_PEGTL_KEYWORD("face_indices"),
             TAO_PEGTL_KEYWORD("normal_indices"), TAO_PEGTL_KEYWORD("uv_indices")> {};
// A section's values, commas between them optional; directives may write
// them (#while and #for loops, as meshmaker.inc's macros do).
// Each value is taken into the section as it is read (a million-face mesh
// would otherwise hold millions of values at once).
struct mesh2_value : p::seq<sum> {};
struct mesh2_value_item;
struct mesh2_value_item : p::sor<directive<mesh2_value_item>, comma, mesh2_value> {};
struct mesh2_values : p::seq<frame_open, p::star<mesh2_value_item>> {};
struct mesh2_section
    : p::seq<mesh2_section_name, ws, p::must<lbrace>, p::must<mesh2_values>, p::must<rbrace>> {};
struct mesh2_texture_count : p::seq<sum> {};
struct mesh2_texture_list
    : p::seq<TAO_PEGTL_KEYWORD("texture_list"), ws, p::must<lbrace>, frame_open,
             p::must<mesh2_texture_count>, p::star<p::opt<comma>, texture_block>, p::must<rbrace>> {};
struct mesh2_item
    : p::sor<directive<mesh2_item>, macro_call<mesh2_item>, mesh2_section, mesh2_texture_list,
             mesh_inside_vector, mesh_hierarchy, object_modifier> {};
struct mesh2_block : p::seq<mesh2_open, p::star<mesh2_item>, p::must<object_close>> {};

// blob { threshold T  sphere { <C>, R, [strength] S }  cylinder { <A>, <B>,
// R, [strength] S }  component S, R, <C>  modifiers } (runtime/objects/blob/):
// each component is added as it is read; threshold and hierarchy are the
// blob's settings, read among its modifiers.
struct blob_open : p::seq<TAO_PEGTL_KEYWORD("blob"), ws, p::must<lbrace>> {};
struct blob_component_kind : p::sor<TAO_PEGTL_KEYWORD("sphere"), TAO_PEGTL_KEYWORD("cylinder")> {};
struct blob_strength_word : p::seq<TAO_PEGTL_KEYWORD("strength"), ws> {};
// A component's own modifiers, which POV-Ray reads and hexant refuses.
struct blob_component_modifier
    : p::sor<TAO_PEGTL_KEYWORD("texture"), TAO_PEGTL_KEYWORD("pigment"), TAO_PEGTL_KEYWORD("normal"),
             TAO_PEGTL_KEYWORD("finish"), TAO_PEGTL_KEYWORD("translate"), TAO_PEGTL_KEYWORD("rotate"),
             TAO_PEGTL_KEYWORD("scale"), TAO_PEGTL_KEYWORD("matrix"), TAO_PEGTL_KEYWORD("transform")> {};
struct blob_component_item;
struct blob_component_item
    : p::sor<directive<blob_component_item>, comma, blob_strength_word, blob_component_modifier,
             shape_argument> {};
struct blob_component
    : p::seq<blob_component_kind, ws, p::must<lbrace>, frame_open, p::star<blob_component_item>,
             p::must<rbrace>> {};
struct blob_old_component
    : p::seq<TAO_PEGTL_KEYWORD("component"), ws, frame_open, p::must<shape_argument>,
             p::opt<comma>, p::must<shape_argument>, p::opt<comma>, p::must<shape_argument>> {};
struct blob_item
    : p::sor<directive<blob_item>, macro_call<blob_item>, blob_component, blob_old_component,
             object_modifier> {};
struct blob_block : p::seq<blob_open, p::star<blob_item>, p::must<object_close>> {};

struct object_value
    : p::sor<mesh_block, mesh2_block, blob_block, shape_block, csg_block, object_block, light_block> {};

// Things that modify an object, in any order.
struct object_texture : p::seq<texture_block> {};
struct object_pigment : p::seq<pigment_block> {};
struct object_finish : p::seq<finish_block> {};
struct object_interior : p::seq<interior_block> {};
struct object_material : p::seq<material_block> {};
struct object_flag_name
    : p::sor<TAO_PEGTL_KEYWORD("no_shadow"), TAO_PEGTL_KEYWORD("hollow"),
             TAO_PEGTL_KEYWORD("inverse"), TAO_PEGTL_KEYWORD("sturm"),
             TAO_PEGTL_KEYWORD("no_image"), TAO_PEGTL_KEYWORD("no_reflection"),
             TAO_PEGTL_KEYWORD("no_radiosity"), TAO_PEGTL_KEYWORD("double_illuminate")> {};
struct object_flag_value : p::seq<p::not_at<p::one<'<'>>, expression> {};
struct object_flag : p::seq<object_flag_name, ws, frame_open, p::opt<object_flag_value>> {};
// A setting of the object's own kind (a cylinder's `open`), with an
// optional value; the kind says what it takes.
struct shape_setting_words {
    static constexpr auto list = runtime::objects::KindWords<runtime::ShapeKinds>::settings;
};
struct shape_setting_name : one_word_of<shape_setting_words> {};
struct shape_setting_value : p::seq<p::not_at<p::one<'<'>>, expression> {};
struct shape_setting : p::seq<shape_setting_name, ws, frame_open, p::opt<shape_setting_value>> {};
// A setting whose values are vectors: a mesh triangle's uv_vectors <u1, v1>,
// <u2, v2>, <u3, v3> (runtime/objects/triangle/triangle.hpp).
struct shape_vectors_setting_name : TAO_PEGTL_KEYWORD("uv_vectors") {};
struct shape_vectors_setting_value : p::seq<expression> {};
struct shape_vectors_setting
    : p::seq<shape_vectors_setting_name, ws, frame_open, p::must<shape_vectors_setting_value>,
             p::star<comma, p::must<shape_vectors_setting_value>>> {};
struct object_ignored_block
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("bounded_by"), TAO_PEGTL_KEYWORD("clipped_by"),
                    TAO_PEGTL_KEYWORD("photons"), TAO_PEGTL_KEYWORD("radiosity")>,
             ws, p::must<skipped_block>, ws> {};
struct object_modifier
    : p::sor<directive<object_modifier>, macro_call<object_modifier>, transformation,
             deformation, object_texture, object_pigment, object_finish, object_normal,
             object_interior, object_material, object_flag, shape_vectors_setting, shape_setting,
             object_ignored_block> {};

// ---------------------------------------------------------------- scene items

HEXANT_KEYWORD(kw_camera, "camera");
struct camera_open : p::seq<kw_camera, p::must<lbrace>> {};
struct camera_base : p::seq<expression> {};
struct camera_vector_name
    : p::sor<TAO_PEGTL_KEYWORD("location"), TAO_PEGTL_KEYWORD("look_at"),
             TAO_PEGTL_KEYWORD("direction"), TAO_PEGTL_KEYWORD("right"), TAO_PEGTL_KEYWORD("up"),
             TAO_PEGTL_KEYWORD("sky")> {};
struct camera_vector_value : p::seq<expression> {};
struct camera_setting : p::seq<camera_vector_name, ws, p::must<camera_vector_value>> {};
// angle [A] (orthographic: the value may be left out, POV-Ray's
// Allow_Float); spherical: angle H [, V].
struct camera_angle_value : p::seq<sum> {};
struct camera_angle
    : p::seq<TAO_PEGTL_KEYWORD("angle"), ws, frame_open,
             p::opt<camera_angle_value, p::opt<p::opt<comma>, camera_angle_value>>> {};
// The projection (POV-Ray's camera types; the type comes first).
struct camera_type
    : p::sor<TAO_PEGTL_KEYWORD("perspective"), TAO_PEGTL_KEYWORD("orthographic"),
             TAO_PEGTL_KEYWORD("fisheye"), TAO_PEGTL_KEYWORD("panoramic"),
             TAO_PEGTL_KEYWORD("spherical")> {};
struct camera_unsupported_type
    : p::sor<TAO_PEGTL_KEYWORD("ultra_wide_angle"), TAO_PEGTL_KEYWORD("omnimax"),
             TAO_PEGTL_KEYWORD("cylinder")> {};
// Focal blur: aperture A, focal_point <P>, blur_samples [MIN,] MAX;
// confidence and variance are POV-Ray's stopping rule, read and ignored
// (hexant's samples are --spp or --target-error's).
struct camera_blur_name
    : p::sor<TAO_PEGTL_KEYWORD("aperture"), TAO_PEGTL_KEYWORD("blur_samples"),
             TAO_PEGTL_KEYWORD("focal_point")> {};
struct camera_blur_argument : p::seq<sum> {};
struct camera_blur_setting
    : p::seq<camera_blur_name, ws, frame_open, p::must<camera_blur_argument>,
             p::opt<p::opt<comma>, p::not_at<camera_blur_name>, camera_blur_argument>> {};
struct camera_ignored_setting
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("confidence"), TAO_PEGTL_KEYWORD("variance")>,
             ws, p::must<ignored_value>> {};
struct camera_item
    : p::sor<directive<camera_item>, macro_call<camera_item>, p::seq<camera_type, ws>, camera_setting,
             camera_angle, camera_blur_setting, camera_ignored_setting, camera_normal, transformation,
             camera_unsupported_type> {};
struct camera_block
    : p::seq<camera_open, p::opt<camera_base>, p::star<camera_item>, p::must<rbrace>> {};

HEXANT_KEYWORD(kw_background, "background");
struct background_colour : p::seq<expression> {};
struct background_block
    : p::seq<kw_background, p::must<lbrace>, p::must<background_colour>, p::must<rbrace>> {};

// sky_sphere { [a declared one] pigment { } ... [emission COLOUR] transforms }
struct sky_sphere_open : p::seq<TAO_PEGTL_KEYWORD("sky_sphere"), ws, p::must<lbrace>> {};
struct sky_sphere_base : p::seq<expression> {};
struct sky_sphere_pigment : p::seq<pigment_block> {};
struct sky_sphere_emission : p::seq<TAO_PEGTL_KEYWORD("emission"), ws, p::must<pattern_setting_value>> {};
struct sky_sphere_item
    : p::sor<directive<sky_sphere_item>, macro_call<sky_sphere_item>, sky_sphere_pigment,
             sky_sphere_emission, transformation> {};
struct sky_sphere_block
    : p::seq<sky_sphere_open, p::opt<sky_sphere_base>, p::star<sky_sphere_item>, p::must<rbrace>> {};

// fog { [COLOUR] distance D fog_type 1|2 fog_offset fog_alt up turbulence
// octaves omega lambda turb_depth rotate scale }
struct fog_open : p::seq<TAO_PEGTL_KEYWORD("fog"), ws, p::must<lbrace>> {};
struct fog_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("distance"), TAO_PEGTL_KEYWORD("fog_type"), TAO_PEGTL_KEYWORD("fog_alt"),
             TAO_PEGTL_KEYWORD("fog_offset"), TAO_PEGTL_KEYWORD("turb_depth"), TAO_PEGTL_KEYWORD("up"),
             TAO_PEGTL_KEYWORD("turbulence"), TAO_PEGTL_KEYWORD("octaves"), TAO_PEGTL_KEYWORD("omega"),
             TAO_PEGTL_KEYWORD("lambda")> {};
struct fog_setting : p::seq<fog_setting_name, ws, p::must<pattern_setting_value>> {};
struct fog_colour : p::seq<expression> {};
struct fog_item
    : p::sor<directive<fog_item>, macro_call<fog_item>, fog_setting, transformation, fog_colour> {};
struct fog_block : p::seq<fog_open, p::star<fog_item>, p::must<rbrace>> {};

HEXANT_KEYWORD(kw_global_settings, "global_settings");
struct global_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("assumed_gamma"), TAO_PEGTL_KEYWORD("max_trace_level"),
             TAO_PEGTL_KEYWORD("ambient_light"), TAO_PEGTL_KEYWORD("noise_generator")> {};
struct global_setting_value : p::seq<expression> {};
struct global_setting : p::seq<global_setting_name, ws, p::must<global_setting_value>> {};
struct charset_name : p::identifier {};
struct global_charset : p::seq<TAO_PEGTL_KEYWORD("charset"), ws, p::must<charset_name>, ws> {};
// Any other setting: a name and a { } block or a value; warned and ignored.
struct global_ignored_name : p::seq<p::identifier, ws> {};
struct global_ignored_setting
    : p::seq<global_ignored_name, frame_open, p::sor<p::seq<skip::braced, ws>, expression>> {};
// MegaPOV's motion_blur SAMPLES, TIME (real-animation case 17).
struct global_motion_blur
    : p::seq<TAO_PEGTL_KEYWORD("motion_blur"), ws, frame_open, p::must<global_setting_value>, p::opt<comma>,
             p::must<global_setting_value>> {};
struct global_item
    : p::sor<directive<global_item>, global_setting, global_charset, global_motion_blur,
             global_ignored_setting> {};
struct global_settings_block
    : p::seq<kw_global_settings, p::must<lbrace>, p::star<global_item>, p::must<rbrace>> {};

// #default { texture { } | pigment { } | finish { } }
struct default_item : p::sor<texture_block, pigment_block, finish_block> {};
struct default_block
    : p::seq<kw_default, p::must<lbrace>, p::star<default_item>, p::must<rbrace>> {};

// ---------------------------------------------------------------- values

// array[N][M] { ... }
HEXANT_KEYWORD(kw_array, "array");
struct array_size : p::seq<expression> {};
struct array_dimension : p::seq<lbracket, p::must<array_size>, p::must<index_close>> {};
struct array_dimensions : p::seq<frame_open, p::plus<array_dimension>> {};
struct array_element;
struct array_initializer_close : rbrace {};
struct array_initializer
    : p::seq<lbrace, frame_open, p::opt<array_element, p::star<comma, array_element>>,
             p::opt<comma>, p::must<array_initializer_close>> {};
struct array_element : p::sor<array_initializer, value> {};
struct array_value : p::seq<kw_array, p::must<array_dimensions>, p::opt<array_initializer>> {};

// spline { [kind] t, value ... }
HEXANT_KEYWORD(kw_spline, "spline");
struct spline_open : p::seq<kw_spline, p::must<lbrace>> {};
struct spline_kind
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("linear_spline"), TAO_PEGTL_KEYWORD("quadratic_spline"),
                    TAO_PEGTL_KEYWORD("cubic_spline"), TAO_PEGTL_KEYWORD("natural_spline")>,
             ws> {};
struct spline_key_time : p::seq<sum> {};
struct spline_key_value : p::seq<sum> {};
struct spline_key
    : p::seq<spline_key_time, p::opt<comma>, p::must<spline_key_value>, p::opt<comma>> {};
struct spline_item : p::sor<directive<spline_item>, spline_kind, spline_key> {};
// spline { S ... } starts from a declared spline S.
struct spline_base
    : p::seq<p::at<reference, p::sor<rbrace, spline_kind>>, p::seq<expression>> {};
struct spline_block
    : p::seq<spline_open, p::opt<spline_base>, p::star<spline_item>, p::must<rbrace>> {};

// texture { } texture { } ...: POV-Ray's layered texture.
struct texture_layer : p::seq<texture_block> {};
// A declared material is kept as source (hexant has no material values yet).
struct material_value : p::seq<material_block> {};
struct texture_value : p::seq<texture_block, p::star<texture_layer>> {};

struct value
    : p::sor<object_value, camera_block, texture_value, pigment_block, normal_block, colour_map_block,
             sky_sphere_block, finish_block,
             interior_block, material_value, transform_value, array_value, spline_block,
             unsupported_block, expression> {};

// A macro called where a value is wanted holds values (and directives).
struct value_item : p::sor<directive<value_item>, value> {};

// ---------------------------------------------------------------- the scene

struct scene_object : p::seq<object_value> {};
struct scene_unsupported : p::seq<unsupported_block> {};
struct scene_camera : p::seq<camera_block> {};
struct scene_sky_sphere : p::seq<sky_sphere_block> {};
struct scene_item
    : p::sor<directive<scene_item>, macro_call<scene_item>, scene_object, scene_camera,
             background_block, scene_sky_sphere, fog_block, global_settings_block, scene_unsupported,
             semicolon> {};
struct scene_end : p::eof {};
struct scene_file : p::seq<ws, p::star<scene_item>, p::must<scene_end>> {};

}  // namespace hexant::language::grammar

// For analyze<>(): each custom rule consumes input when it succeeds.
namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, hexant::language::grammar::name> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, hexant::language::grammar::block_comment_body> : analyze_any_traits<> {};
template <typename Name, typename Words>
struct analyze_traits<Name, hexant::language::grammar::one_word_of<Words>> : analyze_any_traits<> {};
#define HEXANT_CUSTOM_ANALYZE(rule)                                                         \
    template <typename Name, typename Item>                                                \
    struct analyze_traits<Name, hexant::language::grammar::rule<Item>> : analyze_any_traits<> {}
HEXANT_CUSTOM_ANALYZE(macro_call);
HEXANT_CUSTOM_ANALYZE(if_directive);
HEXANT_CUSTOM_ANALYZE(ifdef_directive);
HEXANT_CUSTOM_ANALYZE(while_directive);
HEXANT_CUSTOM_ANALYZE(for_directive);
HEXANT_CUSTOM_ANALYZE(switch_directive);
HEXANT_CUSTOM_ANALYZE(include_directive);
HEXANT_CUSTOM_ANALYZE(macro_definition_rule);
HEXANT_CUSTOM_ANALYZE(declared_value_rule);
#undef HEXANT_CUSTOM_ANALYZE
// macro_ahead and argument_directive_ahead only look.
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::macro_ahead_rule<Item>> : analyze_opt_traits<> {};
template <typename Name, typename Item>
struct analyze_traits<Name, hexant::language::grammar::argument_directive_ahead_rule<Item>>
    : analyze_opt_traits<> {};
}  // namespace tao::pegtl
