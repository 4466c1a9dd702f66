// Directives: #declare, #if, #while, #for, #switch, #macro, #include and the others.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/skipping.hpp"

namespace hexant::language::grammar {

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
struct declare_deprecation : p::seq<TAO_PEGTL_KEYWORD("deprecated"), ws,
                                    p::opt<TAO_PEGTL_KEYWORD("once"), ws>, p::must<ignored_value>> {
};
struct declare_directive
    : p::seq<declare_kind, p::opt<declare_deprecation>, p::must<declare_target>,
             p::must<declare_equals>, p::must<declared_value>, p::opt<semicolon>> {};

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
struct range_header : p::seq<lparen, p::must<condition_value>, p::must<comma>,
                             p::must<condition_value>, p::must<condition_close>> {};
struct macro_body_end : p::eof {};
struct include_end : p::eof {};

// #fopen NAME "file" read|write|append, #fclose NAME, #write (NAME, items)
// and #read (NAME, identifiers) (language/file_io.hpp).
struct fopen_id : identifier {};
struct fopen_path : p::seq<expression> {};
struct fopen_mode
    : p::sor<TAO_PEGTL_KEYWORD("read"), TAO_PEGTL_KEYWORD("write"), TAO_PEGTL_KEYWORD("append")> {};
struct fopen_directive : p::seq<TAO_PEGTL_KEYWORD("fopen"), ws, p::must<fopen_id>,
                                p::must<fopen_path>, p::must<fopen_mode>, ws> {};
struct fclose_id : identifier {};
struct fclose_directive : p::seq<TAO_PEGTL_KEYWORD("fclose"), ws, p::must<fclose_id>> {};
struct file_id : identifier {};
struct write_binary_word : p::sor<TAO_PEGTL_KEYWORD("sint8"), TAO_PEGTL_KEYWORD("uint8"),
                                  TAO_PEGTL_KEYWORD("sint16be"), TAO_PEGTL_KEYWORD("sint16le"),
                                  TAO_PEGTL_KEYWORD("uint16be"), TAO_PEGTL_KEYWORD("uint16le"),
                                  TAO_PEGTL_KEYWORD("sint32be"), TAO_PEGTL_KEYWORD("sint32le")> {};
struct write_binary_value : p::seq<expression> {};
struct write_binary : p::seq<write_binary_word, ws, p::must<write_binary_value>> {};
struct write_value : p::seq<expression> {};
struct file_close : rparen {};
struct write_directive
    : p::seq<TAO_PEGTL_KEYWORD("write"), ws, p::must<lparen>, p::must<file_id>,
             p::star<p::sor<comma, write_binary, write_value>>, p::must<file_close>> {};
struct read_target : identifier {};
struct read_directive : p::seq<TAO_PEGTL_KEYWORD("read"), ws, p::must<lparen>, p::must<file_id>,
                               p::star<p::sor<comma, read_target>>, p::must<file_close>> {};
struct unsupported_directive
    : p::sor<TAO_PEGTL_KEYWORD("render"), TAO_PEGTL_KEYWORD("statistics")> {};
// Anything after '#' that is not a directive, nor a block's divider.
struct unknown_directive : p::seq<p::not_at<skip::divider_word>, p::identifier_first> {};
// A '#' before what is not a word (`look_at <0, 2, 0>#` then `}`): POV-Ray's
// Parse_Directive ungets the token and reads on, so the '#' is ignored.
struct lone_hash : p::seq<p::not_at<p::identifier_first>, ws> {};

struct default_block;
template <typename Item>
struct directive
    : p::sor<escaped_branch_end<Item>,
             p::seq<hash,
                    p::sor<declare_directive, if_directive<Item>, ifdef_directive<Item>,
                           while_directive<Item>, for_directive<Item>, switch_directive<Item>,
                           include_directive<Item>, macro_definition, undef_directive,
                           version_directive, debug_directive, warning_directive, error_directive,
                           default_block, fopen_directive, fclose_directive, write_directive,
                           read_directive, unsupported_directive, unknown_directive, lone_hash>>> {
};

}  // namespace hexant::language::grammar
