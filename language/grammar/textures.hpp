// Textures: pigments, patterns, maps, normals, finishes, interiors.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/functions.hpp"
#include "language/grammar/modifiers.hpp"

namespace hexant::language::grammar {

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
    : p::sor<TAO_PEGTL_KEYWORD("facets"), TAO_PEGTL_KEYWORD("pavement"),
             TAO_PEGTL_KEYWORD("tiling"), TAO_PEGTL_KEYWORD("cubic"), TAO_PEGTL_KEYWORD("object"),
             TAO_PEGTL_KEYWORD("aoi"), TAO_PEGTL_KEYWORD("image_pattern"),
             TAO_PEGTL_KEYWORD("bump_map"), TAO_PEGTL_KEYWORD("wave")> {};
struct unsupported_pattern : p::seq<unsupported_pattern_name, skip::until_rbrace> {};
// uv_mapping in a pigment, a normal or a texture: what follows in the
// block is read at the surface's (u, v, 0) (runtime/texture/material.hpp).
struct uv_mapping : p::seq<TAO_PEGTL_KEYWORD("uv_mapping"), ws> {};

// The patterns hexant has (runtime/texture/pattern/kinds.hpp, whose list
// gives these words), each followed by what its kind takes: a vector
// (gradient), a number (spiral1, spiral2, mandel), a point and a number
// (julia) or a list of colours (the block patterns).
struct pattern_words {
    static constexpr auto list =
        runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::keywords;
};
struct pattern_name : one_word_of<pattern_words> {};
struct pattern_argument : p::seq<sum> {};
struct pattern_kind : p::seq<pattern_name, ws, frame_open,
                             p::opt<pattern_argument, p::star<p::opt<comma>, pattern_argument>>> {};
// The pattern modifiers (POV-Ray's Parse_Pattern), each with one value:
// those of every pattern, and the kinds' own (mortar, metric, ...: each
// kind's file declares its settings).
struct pattern_kind_setting_words {
    static constexpr auto list =
        runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::settings;
};
struct pattern_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("frequency"), TAO_PEGTL_KEYWORD("phase"),
             TAO_PEGTL_KEYWORD("turbulence"), TAO_PEGTL_KEYWORD("octaves"),
             TAO_PEGTL_KEYWORD("omega"), TAO_PEGTL_KEYWORD("lambda"),
             TAO_PEGTL_KEYWORD("noise_generator"), one_word_of<pattern_kind_setting_words>> {};
struct pattern_setting_value : p::seq<expression> {};
struct pattern_setting : p::seq<pattern_setting_name, ws, p::must<pattern_setting_value>> {};
// The kinds' settings of two numbers, TYPE [,] FACTOR (a fractal's exterior
// and interior: POV-Ray's Parse_Float, Parse_Comma, Parse_Float).
struct pattern_pair_setting_words {
    static constexpr auto list =
        runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::pair_settings;
};
struct pattern_pair_name : one_word_of<pattern_pair_setting_words> {};
struct pattern_pair_value : p::seq<sum> {};
struct pattern_pair_setting : p::seq<pattern_pair_name, ws, frame_open, p::must<pattern_pair_value>,
                                     p::opt<comma>, p::must<pattern_pair_value>> {};
// The kinds' settings that are a word alone (crackle's solid).
struct pattern_flag_setting_words {
    static constexpr auto list =
        runtime::pattern::PatternWords<runtime::pattern::PatternKinds>::flag_settings;
};
struct pattern_flag_setting : p::seq<one_word_of<pattern_flag_setting_words>, ws> {};
struct pattern_wave_name
    : p::sor<TAO_PEGTL_KEYWORD("ramp_wave"), TAO_PEGTL_KEYWORD("sine_wave"),
             TAO_PEGTL_KEYWORD("triangle_wave"), TAO_PEGTL_KEYWORD("scallop_wave"),
             TAO_PEGTL_KEYWORD("cubic_wave"), TAO_PEGTL_KEYWORD("poly_wave")> {};
struct pattern_wave : p::seq<pattern_wave_name, ws, frame_open, p::opt<pattern_argument>> {};
// warp { ... } (POV-Ray's Parse_Warp): one warp a block, each kind's
// settings after its keyword (runtime/texture/pattern/warps/).
struct warp_open : p::seq<TAO_PEGTL_KEYWORD("warp"), ws, p::must<lbrace>> {};
// A warp's setting with a value; Name lists those of its kind.
template <class Name>
struct warp_option : p::seq<Name, ws, p::must<pattern_setting_value>> {};
// turbulence <x, y, z> [octaves N] [omega W] [lambda L]
struct warp_turbulence_keyword : TAO_PEGTL_KEYWORD("turbulence") {};
struct warp_setting_name : p::sor<TAO_PEGTL_KEYWORD("octaves"), TAO_PEGTL_KEYWORD("omega"),
                                  TAO_PEGTL_KEYWORD("lambda")> {};
struct warp_setting : p::seq<warp_setting_name, ws, p::must<pattern_setting_value>> {};
struct warp_turbulence : p::seq<pattern_setting_value> {};
struct warp_turbulence_body
    : p::seq<warp_turbulence_keyword, ws, p::must<warp_turbulence>, p::star<warp_setting>> {};
// repeat <direction> [offset <v>] [flip <v>]
struct warp_repeat_keyword : TAO_PEGTL_KEYWORD("repeat") {};
struct warp_repeat_direction : p::seq<pattern_setting_value> {};
struct warp_repeat_option_name : p::sor<TAO_PEGTL_KEYWORD("offset"), TAO_PEGTL_KEYWORD("flip")> {};
struct warp_repeat_body : p::seq<warp_repeat_keyword, ws, p::must<warp_repeat_direction>,
                                 p::star<warp_option<warp_repeat_option_name>>> {};
// black_hole <center> [,] radius [strength S] [falloff F] [inverse]
// [repeat <v>] [turbulence <v>] [type T]
struct warp_black_hole_keyword : TAO_PEGTL_KEYWORD("black_hole") {};
struct warp_black_hole_center : p::seq<pattern_setting_value> {};
struct warp_black_hole_radius : p::seq<pattern_setting_value> {};
struct warp_black_hole_option_name
    : p::sor<TAO_PEGTL_KEYWORD("strength"), TAO_PEGTL_KEYWORD("falloff"),
             TAO_PEGTL_KEYWORD("repeat"), TAO_PEGTL_KEYWORD("turbulence"),
             TAO_PEGTL_KEYWORD("type")> {};
struct warp_black_hole_inverse : p::seq<TAO_PEGTL_KEYWORD("inverse"), ws> {};
struct warp_black_hole_body
    : p::seq<warp_black_hole_keyword, ws, p::must<warp_black_hole_center>, p::opt<comma>,
             p::must<warp_black_hole_radius>,
             p::star<p::sor<warp_black_hole_inverse, warp_option<warp_black_hole_option_name>>>> {};
// planar [<normal> [,] distance]
struct warp_planar_keyword : TAO_PEGTL_KEYWORD("planar") {};
struct warp_planar_normal : p::seq<pattern_setting_value> {};
struct warp_planar_distance : p::seq<pattern_setting_value> {};
struct warp_planar_body
    : p::seq<warp_planar_keyword, ws,
             p::opt<warp_planar_normal, p::opt<comma>, p::must<warp_planar_distance>>> {};
// cylindrical, spherical [orientation <v>] [dist_exp E]; toroidal, which
// takes major_radius R too; cubic
struct warp_round_keyword
    : p::sor<TAO_PEGTL_KEYWORD("cylindrical"), TAO_PEGTL_KEYWORD("spherical")> {};
struct warp_round_option_name
    : p::sor<TAO_PEGTL_KEYWORD("orientation"), TAO_PEGTL_KEYWORD("dist_exp")> {};
struct warp_round_body
    : p::seq<warp_round_keyword, ws, p::star<warp_option<warp_round_option_name>>> {};
struct warp_toroidal_keyword : TAO_PEGTL_KEYWORD("toroidal") {};
struct warp_toroidal_option_name
    : p::sor<TAO_PEGTL_KEYWORD("orientation"), TAO_PEGTL_KEYWORD("dist_exp"),
             TAO_PEGTL_KEYWORD("major_radius")> {};
struct warp_toroidal_body
    : p::seq<warp_toroidal_keyword, ws, p::star<warp_option<warp_toroidal_option_name>>> {};
struct warp_cubic_keyword : TAO_PEGTL_KEYWORD("cubic") {};
struct warp_cubic_body : p::seq<warp_cubic_keyword, ws> {};
struct warp_kind : p::sor<warp_turbulence_body, warp_repeat_body, warp_black_hole_body,
                          warp_planar_body, warp_round_body, warp_toroidal_body, warp_cubic_body> {
};
struct warp_block : p::seq<warp_open, p::must<warp_kind>, p::must<rbrace>> {};

// What may follow a pattern of its own syntax in a normal: [,] its amount
// (POV-Ray's Parse_Pattern: Parse_Comma, Allow_Float after any pattern).
struct own_pattern_amount : p::seq<sum> {};
struct own_pattern_tail : p::opt<p::opt<comma>, own_pattern_amount> {};

// slope { [point_at] DIRECTION [, LOW [, HIGH]] [altitude VECTOR [, LOW [, HIGH]]] },
// or slope DIRECTION (POV-Ray's SLOPE_TOKEN in Parse_Pattern;
// runtime/texture/pattern/kinds/slope.hpp).
struct slope_keyword : p::seq<TAO_PEGTL_KEYWORD("slope"), ws> {};
struct slope_point_at : p::seq<TAO_PEGTL_KEYWORD("point_at"), ws> {};
struct slope_direction : p::seq<sum> {};
struct slope_low : p::seq<sum> {};
struct slope_high : p::seq<sum> {};
struct altitude_keyword : p::seq<TAO_PEGTL_KEYWORD("altitude"), ws> {};
struct altitude_direction : p::seq<sum> {};
struct altitude_low : p::seq<sum> {};
struct altitude_high : p::seq<sum> {};
struct slope_altitude
    : p::seq<altitude_keyword, p::must<altitude_direction>, p::opt<p::opt<comma>, altitude_low>,
             p::opt<p::opt<comma>, altitude_high>> {};
struct slope_braced : p::seq<lbrace, p::opt<slope_point_at>, p::must<slope_direction>,
                             p::opt<p::opt<comma>, slope_low>, p::opt<p::opt<comma>, slope_high>,
                             p::opt<slope_altitude>, p::must<rbrace>> {};
struct slope_written : p::sor<slope_braced, slope_direction> {};
struct slope_pattern : p::seq<slope_keyword, p::must<slope_written>, own_pattern_tail> {};

// magnet 1|2 mandel ITERATIONS, magnet 1|2 julia <cr, ci> [,] ITERATIONS
// (POV-Ray's MAGNET_TOKEN in Parse_Pattern;
// runtime/texture/pattern/kinds/magnet.hpp).
struct magnet_keyword : p::seq<TAO_PEGTL_KEYWORD("magnet"), ws> {};
struct magnet_type : p::seq<sum> {};
struct magnet_mandel : p::seq<TAO_PEGTL_KEYWORD("mandel"), ws> {};
struct magnet_julia : p::seq<TAO_PEGTL_KEYWORD("julia"), ws> {};
struct magnet_point : p::seq<sum> {};
struct magnet_form
    : p::sor<magnet_mandel, p::seq<magnet_julia, p::must<magnet_point>, p::opt<comma>>> {};
struct magnet_iterations : p::seq<sum> {};
struct magnet_pattern : p::seq<magnet_keyword, p::must<magnet_type>, p::must<magnet_form>,
                               p::must<magnet_iterations>, own_pattern_tail> {};

// function { EXPRESSION }: the function pattern, its body a user
// function's (runtime/texture/pattern/kinds/function.hpp).
struct function_pattern_body : p::seq<function_value> {};
struct function_pattern : p::seq<function_pattern_body, own_pattern_tail> {};
// density_file df3 "FILE" (runtime/texture/pattern/kinds/density_file.hpp).
struct density_file_name : p::seq<expression> {};
struct density_file_type : TAO_PEGTL_KEYWORD("df3") {};
struct density_file_pattern
    : p::seq<TAO_PEGTL_KEYWORD("density_file"), ws, p::must<density_file_type>, ws,
             p::must<density_file_name>, own_pattern_tail> {};

// color_map { [value colour] ... }, or a declared one; POV-Ray's older
// [value1, value2 colour1 colour2] too.
struct colour_map_open
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("color_map"), TAO_PEGTL_KEYWORD("colour_map")>, ws,
             p::must<lbrace>> {};
// (A name followed by '(' is a macro writing the entries, not a declared map.)
struct colour_map_base : p::seq<p::not_at<p::identifier, ws, lparen>, expression> {};
// An entry's colour may be components alone, from black (`[0 blue 0.4]`),
// or a colour they change (`[0.5 White filter 0.5]`): POV-Ray's
// Parse_Colour.
struct bare_colour_start : p::success {};
struct bare_colour
    : p::seq<p::at<colour_component_name>, bare_colour_start, p::plus<colour_component_setting>> {};
struct colour_map_item : p::sor<bare_colour, p::seq<sum, p::star<colour_component_setting>>> {};
// (The first item is the entry's value: components after it start a colour.)
struct colour_map_value : p::seq<sum> {};
struct colour_map_entry : p::seq<lbracket, frame_open, p::must<colour_map_value>,
                                 p::star<p::opt<comma>, colour_map_item>, p::must<rbracket>> {};
// (Directives and macros may write the entries: #for, #if, a macro that
// expands to [v colour].)
struct colour_map_element
    : p::sor<directive<colour_map_element>, macro_call<colour_map_element>, colour_map_entry> {};
struct colour_map_block : p::seq<colour_map_open, p::opt<colour_map_base>,
                                 p::star<colour_map_element>, p::must<rbrace>> {};
struct pigment_colour_map : p::seq<colour_map_block> {};

struct pigment_open : p::seq<kw_pigment, p::must<lbrace>> {};
// (A call standing alone, NAME(...) with no operator after it, is a macro
// writing the pigment's items, read as such: its body may hold a pattern
// and its modifiers, or a colour, pigment_late_colour. A call in a sum,
// `Pick(Colours, S) * 0.5`, is the base's value.)
struct call_alone
    : p::seq<p::identifier, ws, skip::parenthesized, ws,
             p::not_at<p::one<'*', '/', '+', '-', '.', '[', '<', '>', '=', '!', '&', '|', '?'>>> {};
struct pigment_base : p::seq<p::not_at<pattern_name>, p::not_at<unsupported_pattern_name>,
                             p::not_at<call_alone>, expression> {};
struct pigment_item;
// A colour (or declared pigment) after the block's start: the first item
// of a directive's branch or a macro's body (`pigment { #switch (clock)
// #case (1) image_map { } #else Gray50 #end }`): POV-Ray's Parse_Pattern
// reads it as the pigment's first token, the directive around it unseen.
struct pigment_late_colour
    : p::seq<p::not_at<pattern_name>, p::not_at<unsupported_pattern_name>, expression> {};
// pigment_map { [value PIGMENT_BODY] ... }: each entry a pigment's inside
// (a declared pigment, a colour, or a pattern with its modifiers).
struct pigment_map_value
    : p::seq<p::not_at<unsupported_pattern_name>, p::not_at<kw_function>, sum> {};
// (An average's entry may leave its weight out: 1, POV-Ray's Allow_Float(1.0).
// A pattern hexant lacks is not a weight: `[function { } ...]` is that
// pattern's pigment, refused as such.)
struct pigment_map_weight : p::success {};
struct pigment_map_pigment_open : p::success {};
// A pattern hexant lacks in an entry: kept by name as in a pigment, its
// body skipped to the entry's ']' (not to the map's '}').
struct map_entry_skipped
    : p::sor<skip::braced, separator, skip::string_raw, p::not_one<'{', '}', ']'>> {};
struct map_entry_unsupported_pattern
    : p::seq<unsupported_pattern_name, p::star<map_entry_skipped>> {};
struct pigment_map_entry
    : p::seq<lbracket, p::sor<pigment_map_value, pigment_map_weight>, p::opt<comma>,
             pigment_map_pigment_open, p::opt<pigment_base>, p::opt<map_entry_unsupported_pattern>,
             p::star<pigment_item>, p::must<rbracket>> {};
struct pigment_map_open : p::seq<TAO_PEGTL_KEYWORD("pigment_map"), ws, p::must<lbrace>> {};
struct pigment_map_element
    : p::sor<directive<pigment_map_element>, macro_call<pigment_map_element>, pigment_map_entry> {};
struct pigment_map_block : p::seq<pigment_map_open, p::star<pigment_map_element>, p::must<rbrace>> {
};
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
    : p::sor<TAO_PEGTL_KEYWORD("map_type"), TAO_PEGTL_KEYWORD("interpolate"),
             TAO_PEGTL_KEYWORD("premultiplied"), TAO_PEGTL_KEYWORD("repeat"),
             TAO_PEGTL_KEYWORD("offset")> {};
struct image_map_setting : p::seq<image_map_setting_name, ws, p::must<pattern_setting_value>> {};
// gamma G, or gamma srgb.
struct image_map_gamma_srgb : p::seq<TAO_PEGTL_KEYWORD("srgb"), ws> {};
struct image_map_gamma : p::seq<TAO_PEGTL_KEYWORD("gamma"), ws,
                                p::sor<image_map_gamma_srgb, p::must<pattern_setting_value>>> {};
struct image_map_flag
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("once"), TAO_PEGTL_KEYWORD("use_colour"),
                    TAO_PEGTL_KEYWORD("use_color"), TAO_PEGTL_KEYWORD("use_index")>,
             ws> {};
// filter all F, transmit all T; filter N F (a palette entry's).
struct image_map_all : p::seq<TAO_PEGTL_KEYWORD("all"), ws> {};
struct image_map_amount : p::seq<sum> {};
struct image_map_filter_name : p::sor<TAO_PEGTL_KEYWORD("filter"), TAO_PEGTL_KEYWORD("transmit")> {
};
struct image_map_filter
    : p::seq<image_map_filter_name, ws, frame_open, p::opt<image_map_all>,
             p::must<image_map_amount>, p::opt<p::opt<comma>, image_map_amount>> {};
struct image_map_item
    : p::sor<image_map_gamma, image_map_setting, image_map_flag, image_map_filter> {};
struct image_map_block : p::seq<image_map_open, p::opt<image_file_type>, p::must<image_map_file>,
                                p::star<image_map_item>, p::must<rbrace>> {};
// pigment_pattern { PIGMENT_BODY }: a fresh pigment's inside, whose grey
// is the value (runtime/texture/pattern/kinds/pigment_pattern.hpp).
struct pigment_pattern_open : p::seq<TAO_PEGTL_KEYWORD("pigment_pattern"), ws, p::must<lbrace>> {};
struct pigment_pattern_body
    : p::seq<pigment_pattern_open, p::opt<pigment_base>, p::star<pigment_item>, p::must<rbrace>> {};
struct pigment_pattern : p::seq<pigment_pattern_body, own_pattern_tail> {};
struct pigment_block;
// A block pattern's pigments: checker pigment { } pigment { }.
struct pigment_list_pigment : p::seq<pigment_block, p::opt<comma>> {};
// A colour component after a plain pigment's colour, or alone: `White
// filter 0.9`, `red 0.7 green 0.2` (POV-Ray's Parse_Colour goes on reading
// components after a colour).
struct pigment_component : p::seq<colour_component_name, ws, p::must<colour_component_value>> {};
// quick_color COLOUR: POV-Ray's colour for its quality levels below 6;
// read and not used (language/keyword_rules.cpp: harmless).
// Components may follow the colour or stand alone, as in any colour of
// POV-Ray's (`quick_color red 0.95 green 0.62`).
// (Its own word rule: colour_component_name pushes the name for the value
// that reads it, and a quick_color's components are not read.)
struct quick_colour_component_name : one_word_of<colour_component_words> {};
struct quick_colour_component : p::seq<quick_colour_component_name, ws, p::must<ignored_value>> {};
struct pigment_quick_colour
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("quick_color"), TAO_PEGTL_KEYWORD("quick_colour")>, ws,
             p::sor<p::plus<quick_colour_component>,
                    p::seq<p::must<ignored_value>, p::star<quick_colour_component>>>> {};
// object { OBJECT LIST } in a pigment, normal or texture: POV-Ray's object
// pattern (runtime/texture/pattern/kinds/object.hpp). Its object is a name
// or an object block, without modifiers (POV-Ray's Parse_Bound_Clip); a
// blend list of two follows: colours, pigments, normals or textures.
struct object_value;
struct normal_list_normal;
struct texture_list_texture;
struct object_pattern_open : p::seq<TAO_PEGTL_KEYWORD("object"), ws, lbrace> {};
struct object_pattern_object : p::sor<object_value, expression> {};
struct object_pattern_colour : p::seq<expression, p::opt<comma>> {};
struct object_pattern_close : rbrace {};
struct object_pattern : p::seq<object_pattern_open, p::must<object_pattern_object>, p::opt<comma>,
                               p::star<p::sor<pigment_list_pigment, normal_list_normal,
                                              texture_list_texture, object_pattern_colour>>,
                               p::must<object_pattern_close>> {};
struct pigment_item
    : p::sor<directive<pigment_item>, macro_call<pigment_item>, slope_pattern, magnet_pattern,
             pigment_pattern, function_pattern, density_file_pattern, object_pattern, pattern_kind,
             pattern_flag_setting, pattern_setting, pattern_pair_setting, pattern_wave, warp_block,
             pigment_colour_map, pigment_map_block, image_map_block, pigment_list_pigment,
             pigment_quick_colour, pigment_component, uv_mapping, unsupported_pattern,
             transformation, pigment_late_colour> {};
struct pigment_block
    : p::seq<pigment_open, p::opt<pigment_base>, p::star<pigment_item>, p::must<rbrace>> {};
// function { pigment { } }: a pigment function, F(x, y, z) its colour
// (runtime/texture/pigment_function.hpp).
struct function_pigment_open : p::seq<kw_function, lbrace, p::at<kw_pigment>> {};
struct function_pigment : p::seq<function_pigment_open, pigment_block, p::must<rbrace>> {};
// function { pattern { PATTERN modifiers } }: a pattern function, F(x, y, z)
// the pattern's value there (POV-Ray's f_pattern).
struct function_pattern_value_open
    : p::seq<kw_function, lbrace, TAO_PEGTL_KEYWORD("pattern"), ws, lbrace> {};
struct function_pattern_value
    : p::seq<function_pattern_value_open, p::star<pigment_item>, p::must<rbrace>, p::must<rbrace>> {
};

struct finish_setting_name : p::sor<TAO_PEGTL_KEYWORD("ambient"), TAO_PEGTL_KEYWORD("diffuse"),
                                    TAO_PEGTL_KEYWORD("brilliance"),
                                    TAO_PEGTL_KEYWORD("phong_size"), TAO_PEGTL_KEYWORD("phong"),
                                    TAO_PEGTL_KEYWORD("specular"), TAO_PEGTL_KEYWORD("roughness"),
                                    TAO_PEGTL_KEYWORD("emission"), TAO_PEGTL_KEYWORD("crand")> {};
struct finish_setting_value : p::seq<expression> {};
// (diffuse A, B: B lights from behind, POV-Ray 3.7's DiffuseBack.)
struct finish_setting : p::seq<finish_setting_name, ws, frame_open, p::must<finish_setting_value>,
                               p::opt<comma, p::must<finish_setting_value>>> {};
struct reflection_value : p::seq<expression> {};
// metallic [AMOUNT]: POV-Ray's Allow_Float(1.0).
struct metallic_amount : p::seq<p::not_at<p::one<'<'>>, expression> {};
struct reflection_metallic
    : p::seq<TAO_PEGTL_KEYWORD("metallic"), ws, frame_open, p::opt<metallic_amount>> {};
// falloff F, exponent E, fresnel [BOOL] (POV-Ray's Parse_Finish).
struct reflection_number_name
    : p::sor<TAO_PEGTL_KEYWORD("falloff"), TAO_PEGTL_KEYWORD("exponent")> {};
struct reflection_number_value : p::seq<expression> {};
struct reflection_number : p::seq<reflection_number_name, ws, p::must<reflection_number_value>> {};
struct reflection_fresnel
    : p::seq<TAO_PEGTL_KEYWORD("fresnel"), ws, frame_open, p::opt<metallic_amount>> {};
struct reflection_option : p::sor<reflection_metallic, reflection_number, reflection_fresnel> {};
// The maximum with or without its comma (POV-Ray's Parse_Comma is
// optional): { 0.0 1.0 fresnel on }.
struct reflection_maximum_value : p::seq<expression> {};
struct reflection_maximum
    : p::seq<p::opt<comma>,
             p::not_at<
                 p::sor<TAO_PEGTL_KEYWORD("metallic"), TAO_PEGTL_KEYWORD("falloff"),
                        TAO_PEGTL_KEYWORD("exponent"), TAO_PEGTL_KEYWORD("fresnel"), p::one<'}'>>>,
             reflection_maximum_value> {};
struct reflection_open : lbrace {};
struct reflection_block
    : p::seq<reflection_open, p::must<reflection_value>, p::opt<reflection_maximum>,
             p::star<reflection_option>, p::must<rbrace>> {};
// `reflection V` alone (POV-Ray's old syntax) also resets the falloff.
struct reflection_plain_value : p::seq<expression> {};
struct reflection_amount : p::sor<reflection_block, reflection_plain_value> {};
struct reflection_setting
    : p::seq<TAO_PEGTL_KEYWORD("reflection"), ws, p::must<reflection_amount>> {};
// conserve_energy (no value in POV-Ray 3.7); a finish's own fresnel is
// POV-Ray 3.8's (warned).
struct finish_conserve_energy : p::seq<TAO_PEGTL_KEYWORD("conserve_energy"), ws> {};
struct finish_flag : p::seq<TAO_PEGTL_KEYWORD("fresnel"), ws, p::opt<ignored_value>> {};
struct finish_metallic
    : p::seq<TAO_PEGTL_KEYWORD("metallic"), ws, frame_open, p::opt<metallic_amount>> {};
struct finish_ignored_block : p::seq<TAO_PEGTL_KEYWORD("subsurface"), ws, skip::braced, ws> {};
// irid { AMOUNT [thickness T] [turbulence V] } (POV-Ray's Parse_Finish).
struct irid_open : p::seq<TAO_PEGTL_KEYWORD("irid"), ws, p::must<lbrace>> {};
struct irid_amount : p::seq<expression> {};
struct irid_setting_name : p::sor<TAO_PEGTL_KEYWORD("thickness"), TAO_PEGTL_KEYWORD("turbulence")> {
};
struct irid_setting_value : p::seq<expression> {};
struct irid_setting : p::seq<irid_setting_name, ws, p::must<irid_setting_value>> {};
struct irid_block
    : p::seq<irid_open, p::must<irid_amount>, p::star<irid_setting>, p::must<rbrace>> {};
struct finish_open : p::seq<kw_finish, p::must<lbrace>> {};
// A block's base is not a macro call whose body gives the block's items
// (interior { I_Glass_Exp(2) }): that is read as items (interpreter_state.hpp).
HEXANT_CUSTOM_RULE(items_macro_ahead, items_macro_ahead);
struct finish_item;
struct finish_base : p::seq<p::not_at<items_macro_ahead<finish_item>>, expression> {};
struct finish_item : p::sor<directive<finish_item>, macro_call<finish_item>, finish_setting,
                            reflection_setting, finish_metallic, finish_conserve_energy,
                            finish_flag, irid_block, finish_ignored_block> {};
struct finish_block
    : p::seq<finish_open, p::opt<finish_base>, p::star<finish_item>, p::must<rbrace>> {};

// normal { PATTERN [AMOUNT] modifiers }, or a declared one: the same
// pattern rules as a pigment's, with bump_size, accuracy, no_bump_scale.
struct normal_open : p::seq<kw_normal, p::must<lbrace>> {};
struct normal_base : p::seq<p::not_at<pattern_name>, expression> {};
struct normal_setting_name : p::sor<TAO_PEGTL_KEYWORD("bump_size"), TAO_PEGTL_KEYWORD("accuracy")> {
};
struct normal_setting : p::seq<normal_setting_name, ws, p::must<pattern_setting_value>> {};
struct normal_no_bump_scale : p::seq<TAO_PEGTL_KEYWORD("no_bump_scale"), ws> {};
struct normal_item;
// normal_map { [value NORMAL_BODY] ... }: each entry a normal's inside.
struct normal_map_value : p::seq<p::not_at<unsupported_pattern_name>, sum> {};
struct normal_map_weight : p::success {};  // (as pigment_map_weight)
struct normal_map_normal_open : p::success {};
struct normal_map_entry
    : p::seq<lbracket, p::sor<normal_map_value, normal_map_weight>, p::opt<comma>,
             normal_map_normal_open, p::opt<normal_base>, p::star<normal_item>, p::must<rbracket>> {
};
struct normal_map_open : p::seq<TAO_PEGTL_KEYWORD("normal_map"), ws, p::must<lbrace>> {};
struct normal_map_element
    : p::sor<directive<normal_map_element>, macro_call<normal_map_element>, normal_map_entry> {};
struct normal_map_block : p::seq<normal_map_open, p::star<normal_map_element>, p::must<rbrace>> {};
// slope_map { [value <height, slope>] ... }
struct slope_map_item : p::seq<sum> {};
struct slope_map_entry : p::seq<lbracket, frame_open, p::must<slope_map_item>, p::opt<comma>,
                                p::must<slope_map_item>, p::must<rbracket>> {};
struct slope_map_open : p::seq<TAO_PEGTL_KEYWORD("slope_map"), ws, p::must<lbrace>> {};
struct slope_map_element
    : p::sor<directive<slope_map_element>, macro_call<slope_map_element>, slope_map_entry> {};
struct slope_map_block : p::seq<slope_map_open, p::star<slope_map_element>, p::must<rbrace>> {};
struct normal_block;
// A block pattern's normals: checker normal { } normal { }.
struct normal_list_normal : p::seq<normal_block, p::opt<comma>> {};
// bump_map { [TYPE] FILE [gamma G] bump_size S map_type N interpolate N
// use_index|use_colour once repeat offset } in a normal (POV-Ray's
// Parse_Bump_Map), its file found and read as image_map's.
struct bump_map_open : p::seq<TAO_PEGTL_KEYWORD("bump_map"), ws, p::must<lbrace>> {};
struct bump_map_size : p::seq<TAO_PEGTL_KEYWORD("bump_size"), ws, p::must<pattern_setting_value>> {
};
struct bump_map_item : p::sor<image_map_gamma, image_map_setting, image_map_flag, bump_map_size> {};
struct bump_map_block : p::seq<bump_map_open, p::opt<image_file_type>, p::must<image_map_file>,
                               p::star<bump_map_item>, p::must<rbrace>> {};
struct normal_item
    : p::sor<directive<normal_item>, macro_call<normal_item>, bump_map_block, slope_pattern,
             magnet_pattern, pigment_pattern, function_pattern, density_file_pattern,
             object_pattern, pattern_kind, pattern_flag_setting, pattern_setting,
             pattern_pair_setting, pattern_wave, warp_block, normal_setting, normal_no_bump_scale,
             normal_map_block, slope_map_block, normal_list_normal, uv_mapping, unsupported_pattern,
             transformation> {};
struct normal_block
    : p::seq<normal_open, p::opt<normal_base>, p::star<normal_item>, p::must<rbrace>> {};
struct texture_normal : p::seq<normal_block> {};
struct object_normal : p::seq<normal_block> {};
struct camera_normal : p::seq<normal_block> {};

struct interior_open : p::seq<kw_interior, p::must<lbrace>> {};
struct interior_item;
struct interior_base : p::seq<p::not_at<items_macro_ahead<interior_item>>, expression> {};
struct ior_value : p::seq<expression> {};
struct ior_setting : p::seq<TAO_PEGTL_KEYWORD("ior"), ws, p::must<ior_value>> {};
// dispersion D, dispersion_samples N (runtime::Interior).
struct dispersion_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("dispersion"), TAO_PEGTL_KEYWORD("dispersion_samples")> {};
struct dispersion_setting_value : p::seq<expression> {};
struct dispersion_setting : p::seq<dispersion_setting_name, ws, p::must<dispersion_setting_value>> {
};
struct media_block;  // language/grammar/media.hpp
struct interior_media : p::seq<media_block> {};
// fade_distance D, fade_power P, fade_colour C, caustics C (runtime::Interior).
struct fade_setting_name : p::sor<TAO_PEGTL_KEYWORD("fade_distance"),
                                  TAO_PEGTL_KEYWORD("fade_power"), TAO_PEGTL_KEYWORD("fade_color"),
                                  TAO_PEGTL_KEYWORD("fade_colour"), TAO_PEGTL_KEYWORD("caustics")> {
};
struct fade_setting_value : p::seq<expression> {};
struct fade_setting : p::seq<fade_setting_name, ws, p::must<fade_setting_value>> {};
struct interior_item : p::sor<directive<interior_item>, macro_call<interior_item>, ior_setting,
                              fade_setting, interior_media, dispersion_setting> {};
struct interior_block
    : p::seq<interior_open, p::opt<interior_base>, p::star<interior_item>, p::must<rbrace>> {};

struct texture_open : p::seq<kw_texture, p::must<lbrace>> {};
struct texture_base : p::seq<p::not_at<pattern_name>, expression> {};
struct texture_pigment : p::seq<pigment_block> {};
struct texture_finish : p::seq<finish_block> {};
struct texture_item;
struct texture_body;
// texture_map { [value TEXTURE_BODY] ... }: each entry a texture's inside.
struct texture_map_value : p::seq<p::not_at<unsupported_pattern_name>, sum> {};
struct texture_map_weight : p::success {};  // (as pigment_map_weight)
struct texture_map_texture_open : p::success {};
struct texture_map_entry
    : p::seq<lbracket, p::sor<texture_map_value, texture_map_weight>, p::opt<comma>,
             texture_map_texture_open, texture_body, p::must<rbracket>> {};
struct texture_map_open : p::seq<TAO_PEGTL_KEYWORD("texture_map"), ws, p::must<lbrace>> {};
struct texture_map_element
    : p::sor<directive<texture_map_element>, macro_call<texture_map_element>, texture_map_entry> {};
struct texture_map_block : p::seq<texture_map_open, p::star<texture_map_element>, p::must<rbrace>> {
};
struct texture_block;
// A block pattern's textures: checker texture { } texture { }.
struct texture_list_texture : p::seq<texture_block, p::opt<comma>> {};
// A patterned texture: a pattern and its modifiers, then its map.
struct texture_item
    : p::sor<directive<texture_item>, macro_call<texture_item>, texture_pigment, texture_finish,
             texture_normal, slope_pattern, magnet_pattern, pigment_pattern, function_pattern,
             density_file_pattern, object_pattern, pattern_kind, pattern_flag_setting,
             pattern_setting, pattern_pair_setting, pattern_wave, warp_block, texture_map_block,
             texture_list_texture, uv_mapping, transformation> {};
// tiles { TEXTURE... tile2 TEXTURE... } [transforms]: POV-Ray's Parse_Tiles,
// a checker of two (layered) textures. As in POV-Ray's Parse_Texture it
// comes first, and only transforms follow it.
struct tiles_open : p::seq<TAO_PEGTL_KEYWORD("tiles"), ws, p::must<lbrace>> {};
struct tiles_texture : p::seq<texture_block> {};
struct tile2_keyword : p::seq<TAO_PEGTL_KEYWORD("tile2"), ws> {};
struct tile2_texture : p::seq<texture_block> {};
struct tiles_block
    : p::seq<tiles_open, p::must<tiles_texture>, p::star<tiles_texture>, p::must<tile2_keyword>,
             p::must<tile2_texture>, p::star<tile2_texture>, p::must<rbrace>> {};
struct texture_tiles : p::seq<tiles_block, p::star<transformation>> {};
// material_map { [TYPE] "FILE" [once] [interpolate N] [map_type N] ...
// texture { } ... }: POV-Ray's Parse_Material_Map, an image picking whole
// textures (runtime/texture/pattern/kinds/material_map.hpp). As tiles, it
// comes first in a texture, and only transforms follow it.
struct material_map_open : p::seq<TAO_PEGTL_KEYWORD("material_map"), ws, p::must<lbrace>> {};
struct material_map_texture : p::seq<texture_block> {};
struct material_map_block
    : p::seq<material_map_open, p::opt<image_file_type>, p::must<image_map_file>,
             p::star<image_map_item>, p::must<material_map_texture>, p::star<material_map_texture>,
             p::must<rbrace>> {};
struct texture_material_map : p::seq<material_map_block, p::star<transformation>> {};
// What follows a texture's start (and a texture_map entry's value): tiles
// and material_map only where nothing, not even a declared texture, came
// before them.
struct texture_body : p::sor<texture_tiles, texture_material_map,
                             p::seq<p::opt<texture_base>, p::star<texture_item>>> {};
struct texture_block : p::seq<texture_open, texture_body, p::must<rbrace>> {};
// interior_texture { TEXTURE_BODY }: an object's texture seen from inside.
struct interior_texture_open : p::seq<TAO_PEGTL_KEYWORD("interior_texture"), ws, p::must<lbrace>> {
};
struct interior_texture_block : p::seq<interior_texture_open, texture_body, p::must<rbrace>> {};

// material { texture { } interior { } }
struct material_open : p::seq<kw_material, p::must<lbrace>> {};
struct material_base : p::seq<expression> {};
struct material_texture : p::seq<texture_block> {};
struct material_interior : p::seq<interior_block> {};
struct material_item
    : p::sor<directive<material_item>, material_texture, material_interior, transformation> {};
struct material_block
    : p::seq<material_open, p::opt<material_base>, p::star<material_item>, p::must<rbrace>> {};

}  // namespace hexant::language::grammar
