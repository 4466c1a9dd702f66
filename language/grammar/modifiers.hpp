// Modifiers every object and texture takes: transforms, deformations and flags.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/directives.hpp"

namespace hexant::language::grammar {

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
struct matrix_step : p::seq<kw_matrix, p::must<matrix_open>, frame_open, p::must<matrix_entry>,
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
struct transform_item : p::sor<directive<transform_item>, macro_call<transform_item>,
                               transformation, transform_inverse> {};
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
struct deformation : p::seq<deformation_name, ws, p::must<deformation_axis>, p::must<comma>,
                            p::must<deformation_amount>> {};

}  // namespace hexant::language::grammar
