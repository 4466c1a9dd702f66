// media { } and its density { } (runtime/scene/media.hpp), after POV-Ray
// 3.7's Parse_Media and Parse_Media_Density_Pattern: in an interior, at the
// top of the scene (the atmosphere), or declared.
#pragma once

#include "language/grammar/textures.hpp"

namespace hexant::language::grammar {

// density { [D | COLOUR] PATTERN ... density_map { [v DENSITY_BODY] ... } }:
// a pigment in all but name (POV-Ray parses it with Parse_Pattern), whose
// map's entries are densities.
struct density_item;
struct density_open : p::seq<TAO_PEGTL_KEYWORD("density"), ws, p::must<lbrace>> {};
struct density_map_value : p::seq<p::not_at<unsupported_pattern_name>, sum> {};
struct density_map_density_open : p::success {};
struct density_map_entry
    : p::seq<lbracket, p::must<density_map_value>, p::opt<comma>, density_map_density_open,
             p::opt<pigment_base>, p::opt<map_entry_unsupported_pattern>, p::star<density_item>,
             p::must<rbracket>> {};
struct density_map_open : p::seq<TAO_PEGTL_KEYWORD("density_map"), ws, p::must<lbrace>> {};
struct density_map_element
    : p::sor<directive<density_map_element>, macro_call<density_map_element>, density_map_entry> {};
struct density_map_block : p::seq<density_map_open, p::star<density_map_element>, p::must<rbrace>> {
};
struct density_item
    : p::sor<directive<density_item>, macro_call<density_item>, density_map_block, pigment_item> {};
struct density_block
    : p::seq<density_open, p::opt<pigment_base>, p::star<density_item>, p::must<rbrace>> {};

// media { [M] settings scattering { } density { } transformations }
struct media_open : p::seq<TAO_PEGTL_KEYWORD("media"), ws, p::must<lbrace>> {};
struct media_base : p::seq<expression> {};
struct media_setting_name : p::sor<TAO_PEGTL_KEYWORD("intervals"), TAO_PEGTL_KEYWORD("method"),
                                   TAO_PEGTL_KEYWORD("jitter"), TAO_PEGTL_KEYWORD("aa_threshold"),
                                   TAO_PEGTL_KEYWORD("aa_level"), TAO_PEGTL_KEYWORD("absorption"),
                                   TAO_PEGTL_KEYWORD("emission"), TAO_PEGTL_KEYWORD("confidence"),
                                   TAO_PEGTL_KEYWORD("variance"), TAO_PEGTL_KEYWORD("ratio")> {};
struct media_setting_value : p::seq<expression> {};
struct media_setting : p::seq<media_setting_name, ws, p::must<media_setting_value>> {};
// samples MIN [, MAX] (MAX defaults to MIN).
struct media_samples_value : p::seq<expression> {};
struct media_samples : p::seq<TAO_PEGTL_KEYWORD("samples"), ws, frame_open,
                              p::must<media_samples_value>, p::opt<comma, media_samples_value>> {};
// collect [BOOL] (media photons; hexant shoots none).
struct media_collect
    : p::seq<TAO_PEGTL_KEYWORD("collect"), ws, frame_open, p::opt<metallic_amount>> {};
// scattering { TYPE, COLOUR [eccentricity E] [extinction X] }
struct scattering_open : p::seq<TAO_PEGTL_KEYWORD("scattering"), ws, p::must<lbrace>> {};
struct scattering_type : p::seq<expression> {};
struct scattering_colour : p::seq<expression> {};
struct scattering_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("eccentricity"), TAO_PEGTL_KEYWORD("extinction")> {};
struct scattering_setting_value : p::seq<expression> {};
struct scattering_setting : p::seq<scattering_setting_name, ws, p::must<scattering_setting_value>> {
};
struct scattering_block
    : p::seq<scattering_open, p::must<scattering_type>, p::opt<comma>, p::must<scattering_colour>,
             p::star<scattering_setting>, p::must<rbrace>> {};
struct media_density : p::seq<density_block> {};
struct media_item
    : p::sor<directive<media_item>, macro_call<media_item>, media_setting, media_samples,
             media_collect, scattering_block, media_density, transformation> {};
struct media_block : p::seq<media_open, p::opt<media_base>, p::star<media_item>, p::must<rbrace>> {
};

}  // namespace hexant::language::grammar
