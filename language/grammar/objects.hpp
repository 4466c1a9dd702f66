// Objects: the registered kinds, CSG and the kinds' own sections.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/functions.hpp"
#include "language/grammar/media.hpp"

namespace hexant::language::grammar {

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
// A #while or #for after a comma among the arguments writes arguments
// (grenadine's lemon.inc: `prism { bezier_spline -0.5, 0.5, 24, #while (J <
// 24) #declare P = BS1[J]; P #declare J = J + 1; #end scale ... }`): its
// body holds arguments, commas and any directive.
struct loop_argument_ahead : p::at<p::one<'#'>, skip::blanks,
                                   p::sor<TAO_PEGTL_KEYWORD("while"), TAO_PEGTL_KEYWORD("for")>> {};
struct shape_loop_item;
struct shape_loop_item : p::sor<directive<shape_loop_item>, comma, shape_argument> {};
struct loop_argument : p::seq<loop_argument_ahead, directive<shape_loop_item>> {};
struct first_shape_argument : p::sor<argument_directive, loop_argument, shape_argument> {};
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
struct shape_block : p::seq<shape_open, p::star<shape_option>, p::must<shape_arguments>,
                            object_modifiers, p::must<object_close>> {};

HEXANT_KEYWORD(kw_union, "union");
HEXANT_KEYWORD(kw_merge, "merge");
HEXANT_KEYWORD(kw_intersection, "intersection");
HEXANT_KEYWORD(kw_difference, "difference");
HEXANT_KEYWORD(kw_motion_blur, "motion_blur");
HEXANT_KEYWORD(kw_light_group, "light_group");
struct csg_kind
    : p::sor<kw_union, kw_merge, kw_intersection, kw_difference, kw_motion_blur, kw_light_group> {};
struct csg_open : p::seq<csg_kind, p::must<lbrace>> {};
struct unsupported_block;
struct csg_child : p::sor<object_value, unsupported_block> {};
struct csg_item : p::sor<directive<csg_item>, macro_call<csg_item>, csg_child, object_modifier> {};
struct csg_block : p::seq<csg_open, p::star<csg_item>, p::must<object_close>> {};

// object { IDENT modifiers } or object { shape modifiers }
HEXANT_KEYWORD(kw_object, "object");
struct object_base : p::sor<object_value, expression> {};
// object { MACRO(...) modifiers } where the macro's body gives the object
// and then modifiers of it (object_pattern.pov's `Obj rotate Angle*y`):
// read as POV-Ray's tokens are, the body's first value the object.
HEXANT_CUSTOM_RULE(object_macro_base, call_object_macro);
HEXANT_CUSTOM_RULE(object_macro_first, object_macro_first);
struct object_macro_item : p::sor<directive<object_macro_item>, macro_call<object_macro_item>,
                                  object_macro_first<object_macro_item>, object_modifier> {};
struct object_block : p::seq<kw_object, p::must<lbrace>,
                             p::sor<object_macro_base<object_macro_item>, p::must<object_base>>,
                             object_modifiers, p::must<object_close>> {};

// light_source { <position>, colour modifiers }
HEXANT_KEYWORD(kw_light_source, "light_source");
// The colour may be left out (POV-Ray: white).
struct light_arguments : p::seq<frame_open, p::must<shape_argument>,
                                p::opt<p::opt<comma>, p::not_at<macro_ahead>, shape_argument>> {};
struct light_flag : p::seq<p::sor<TAO_PEGTL_KEYWORD("shadowless"), TAO_PEGTL_KEYWORD("spotlight"),
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
    : p::seq<TAO_PEGTL_KEYWORD("looks_like"), ws, p::must<lbrace>, p::must<looks_like_base>,
             object_modifiers, p::must<object_close>> {};
// projected_through { OBJECT modifiers }, as object { }: the light shines
// only where its rays pass through the object (POV-Ray's
// Projected_Through_Object).
struct projected_through_base : object_base {};
struct light_projected_through
    : p::seq<TAO_PEGTL_KEYWORD("projected_through"), ws, p::must<lbrace>,
             p::must<projected_through_base>, object_modifiers, p::must<object_close>> {};
// photons { NAME [VALUE] ... } in an object or a light (POV-Ray 3.7's
// Parse_Object_Mods and Parse_Light_Source; runtime/scene/photon_settings.hpp):
// target, collect, pass_through and area_light take an optional value,
// refraction and reflection one.
struct photons_flag_name
    : p::sor<TAO_PEGTL_KEYWORD("target"), TAO_PEGTL_KEYWORD("refraction"),
             TAO_PEGTL_KEYWORD("reflection"), TAO_PEGTL_KEYWORD("collect"),
             TAO_PEGTL_KEYWORD("pass_through"), TAO_PEGTL_KEYWORD("split_union"),
             TAO_PEGTL_KEYWORD("area_light")> {};
struct photons_flag_value : p::seq<expression> {};
struct photons_flag_body
    : p::seq<photons_flag_name, ws, frame_open,
             p::opt<p::not_at<photons_flag_name>, p::not_at<rbrace>, photons_flag_value>> {};
struct photons_open : p::seq<TAO_PEGTL_KEYWORD("photons"), ws, p::must<lbrace>> {};
struct light_photons_flag : p::seq<photons_flag_body> {};
struct light_photons_item;
struct light_photons_item : p::sor<directive<light_photons_item>, light_photons_flag> {};
struct light_photons : p::seq<photons_open, p::star<light_photons_item>, p::must<rbrace>, ws> {};
struct light_item
    : p::sor<directive<light_item>, macro_call<light_item>, light_flag, light_setting, area_light,
             light_looks_like, light_projected_through, transformation, light_photons> {};
struct light_block : p::seq<kw_light_source, p::must<lbrace>, p::must<light_arguments>,
                            p::star<light_item>, p::must<object_close>> {};

// Object kinds POV-Ray has and hexant does not: kept as source, an error
// only where used. Also `function { }` and the *_map blocks.
struct unsupported_kind_words {
    static constexpr std::array<std::string_view, 11> list = {
        "color_map",  "colour_map",  "function", "lemon",     "normal_map", "ovus",
        "parametric", "pigment_map", "rainbow",  "slope_map", "texture_map"};
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
struct mesh_hierarchy : p::seq<TAO_PEGTL_KEYWORD("hierarchy"), ws, p::opt<mesh_hierarchy_value>> {};
struct mesh_item : p::sor<directive<mesh_item>, macro_call<mesh_item>, mesh_inside_vector,
                          mesh_hierarchy, mesh_triangle, object_modifier> {};
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
             p::must<mesh2_texture_count>, p::star<p::opt<comma>, texture_block>, p::must<rbrace>> {
};
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
// A component's own modifiers (POV-Ray's Parse_Blob_Element_Mods): its
// transforms and texture, read into a block of its own (the actions'
// blob_component_kind) by the objects' own rules.
struct object_texture;
struct object_pigment;
struct object_finish;
struct object_normal;
struct blob_component_modifier
    : p::sor<transformation, object_texture, object_pigment, object_finish, object_normal> {};
struct blob_component_item;
struct blob_component_item : p::sor<directive<blob_component_item>, comma, blob_strength_word,
                                    blob_component_modifier, shape_argument> {};
struct blob_component : p::seq<blob_component_kind, ws, p::must<lbrace>, frame_open,
                               p::star<blob_component_item>, p::must<rbrace>> {};
struct blob_old_component
    : p::seq<TAO_PEGTL_KEYWORD("component"), ws, frame_open, p::must<shape_argument>, p::opt<comma>,
             p::must<shape_argument>, p::opt<comma>, p::must<shape_argument>> {};
struct blob_item : p::sor<directive<blob_item>, macro_call<blob_item>, blob_component,
                          blob_old_component, object_modifier> {};
struct blob_block : p::seq<blob_open, p::star<blob_item>, p::must<object_close>> {};

// isosurface { function { F } contained_by { box { A, B } | sphere { C, R } }
// evaluate a, b, c  modifiers } (runtime/objects/isosurface/): threshold,
// accuracy, max_gradient, max_trace, all_intersections and open are the
// kind's settings, read among its modifiers.
struct isosurface_open : p::seq<TAO_PEGTL_KEYWORD("isosurface"), ws, p::must<lbrace>> {};
struct isosurface_function : p::seq<function_value> {};
struct contained_by_kind : p::sor<TAO_PEGTL_KEYWORD("box"), TAO_PEGTL_KEYWORD("sphere")> {};
struct contained_by_shape
    : p::seq<contained_by_kind, ws, p::must<lbrace>, frame_open, p::must<shape_argument>,
             p::opt<comma>, p::must<shape_argument>, p::must<rbrace>> {};
struct isosurface_contained_by : p::seq<TAO_PEGTL_KEYWORD("contained_by"), ws, p::must<lbrace>,
                                        p::must<contained_by_shape>, p::must<rbrace>> {};
struct isosurface_evaluate
    : p::seq<TAO_PEGTL_KEYWORD("evaluate"), ws, frame_open, p::must<shape_argument>, p::opt<comma>,
             p::must<shape_argument>, p::opt<comma>, p::must<shape_argument>> {};
struct isosurface_item;
struct isosurface_item
    : p::sor<directive<isosurface_item>, macro_call<isosurface_item>, isosurface_function,
             isosurface_contained_by, isosurface_evaluate, object_modifier> {};
struct isosurface_block : p::seq<isosurface_open, p::star<isosurface_item>, p::must<object_close>> {
};

// julia_fractal { <c> [quaternion | hypercomplex] [sqr | cube | reciprocal |
// exp | ln | sin | asin | sinh | asinh | cos | acos | cosh | acosh | tan |
// atan | tanh | atanh | pwr(X, Y)] [max_iteration N] [precision P]
// [slice <S>, D] modifiers } (runtime/objects/julia_fractal/; POV-Ray's
// Parse_Julia_Fractal, which reads its words before the modifiers; hexant
// reads them among them).
struct julia_open : p::seq<TAO_PEGTL_KEYWORD("julia_fractal"), ws, p::must<lbrace>> {};
struct julia_parameter : p::seq<frame_open, shape_argument> {};
struct julia_word
    : p::sor<TAO_PEGTL_KEYWORD("quaternion"), TAO_PEGTL_KEYWORD("hypercomplex"),
             TAO_PEGTL_KEYWORD("sqr"), TAO_PEGTL_KEYWORD("cube"), TAO_PEGTL_KEYWORD("reciprocal"),
             TAO_PEGTL_KEYWORD("exp"), TAO_PEGTL_KEYWORD("ln"), TAO_PEGTL_KEYWORD("sin"),
             TAO_PEGTL_KEYWORD("asin"), TAO_PEGTL_KEYWORD("sinh"), TAO_PEGTL_KEYWORD("asinh"),
             TAO_PEGTL_KEYWORD("cos"), TAO_PEGTL_KEYWORD("acos"), TAO_PEGTL_KEYWORD("cosh"),
             TAO_PEGTL_KEYWORD("acosh"), TAO_PEGTL_KEYWORD("tan"), TAO_PEGTL_KEYWORD("atan"),
             TAO_PEGTL_KEYWORD("tanh"), TAO_PEGTL_KEYWORD("atanh")> {};
struct julia_flag : p::seq<julia_word, ws> {};
struct julia_value : p::seq<sum> {};
struct julia_pwr
    : p::seq<TAO_PEGTL_KEYWORD("pwr"), ws, p::must<lparen>, frame_open, p::must<julia_value>,
             p::must<comma>, p::must<julia_value>, p::must<rparen>> {};
struct julia_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("max_iteration"), TAO_PEGTL_KEYWORD("precision")> {};
struct julia_setting : p::seq<julia_setting_name, ws, frame_open, p::must<julia_value>> {};
struct julia_slice : p::seq<TAO_PEGTL_KEYWORD("slice"), ws, frame_open, p::must<julia_value>,
                            p::opt<comma>, p::must<julia_value>> {};
struct julia_item;
struct julia_item : p::sor<directive<julia_item>, macro_call<julia_item>, julia_flag, julia_pwr,
                           julia_setting, julia_slice, object_modifier> {};
struct julia_block
    : p::seq<julia_open, p::must<julia_parameter>, p::star<julia_item>, p::must<object_close>> {};

// bicubic_patch { [type T] [flatness F] [u_steps U] [v_steps V] [accuracy A]
// [uv_vectors <s0>, <s1>, <s2>, <s3>] [,] P00, P01, ..., P33 modifiers }
// (runtime/objects/bicubic_patch/; POV-Ray's Parse_Bicubic_Patch: its words
// in any order before the points, uv_vectors the last of them; the commas
// between the points may be left out, but none may follow the last, as in
// POV-Ray 3.7.0). Every point written is read; the action counts them.
struct bicubic_open : p::seq<TAO_PEGTL_KEYWORD("bicubic_patch"), ws, p::must<lbrace>> {};
struct bicubic_value : p::seq<sum> {};
struct bicubic_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("type"), TAO_PEGTL_KEYWORD("flatness"), TAO_PEGTL_KEYWORD("u_steps"),
             TAO_PEGTL_KEYWORD("v_steps"), TAO_PEGTL_KEYWORD("accuracy")> {};
struct bicubic_setting : p::seq<bicubic_setting_name, ws, frame_open, p::must<bicubic_value>> {};
struct bicubic_uv_vectors
    : p::seq<TAO_PEGTL_KEYWORD("uv_vectors"), ws, frame_open, p::must<bicubic_value>, p::opt<comma>,
             p::must<bicubic_value>, p::opt<comma>, p::must<bicubic_value>, p::opt<comma>,
             p::must<bicubic_value>> {};
struct bicubic_points
    : p::seq<frame_open, first_shape_argument,
             p::star<p::sor<argument_directive, p::seq<comma, p::must<first_shape_argument>>,
                            p::seq<p::not_at<macro_ahead>, shape_argument>>>> {};
struct bicubic_block
    : p::seq<bicubic_open, p::star<bicubic_setting>, p::opt<bicubic_uv_vectors>, p::opt<comma>,
             p::must<bicubic_points>, object_modifiers, p::must<object_close>> {};

// cubic { <20 coefficients> }, quartic { <35> }, poly { ORDER, <..> } and
// polynomial { ORDER, xyz(i, j, k): c, ... } (runtime/objects/poly/poly.hpp);
// quadric is a generic shape.
struct poly_keyword : p::sor<TAO_PEGTL_KEYWORD("cubic"), TAO_PEGTL_KEYWORD("quartic"),
                             TAO_PEGTL_KEYWORD("polynomial"), TAO_PEGTL_KEYWORD("poly")> {};
struct poly_open : p::seq<poly_keyword, ws, p::must<lbrace>> {};
struct poly_order : p::seq<sum> {};
struct poly_coefficients
    : p::seq<vector_open, frame_open, p::must<vector_component>,
             p::star<p::sor<p::seq<comma, p::not_at<vector_close>, p::must<vector_component>>,
                            vector_component>>,
             p::opt<comma>, p::must<vector_close>> {};
struct polynomial_power : p::seq<sum> {};
struct polynomial_coefficient : p::seq<sum> {};
struct polynomial_term
    : p::seq<TAO_PEGTL_KEYWORD("xyz"), ws, p::must<lparen>, frame_open, p::must<polynomial_power>,
             p::must<comma>, p::must<polynomial_power>, p::must<comma>, p::must<polynomial_power>,
             p::must<rparen>, p::must<colon>, p::must<polynomial_coefficient>> {};
struct poly_values
    : p::sor<poly_coefficients, p::seq<polynomial_term, p::star<p::opt<comma>, polynomial_term>>> {
};
struct poly_block : p::seq<poly_open, p::opt<p::not_at<p::one<'<'>>, poly_order, p::opt<comma>>,
                           p::must<poly_values>, object_modifiers, p::must<object_close>> {};

// height_field { function W, H { F } modifiers }, F an expression of x
// and y or a pigment { }: the heights of F sampled on a W x H grid
// (POV-Ray's Parse_Image FUNCTION_TOKEN, Make_Pattern_Image;
// language/actions/height_field_function.hpp).
struct height_field_function_head
    : p::seq<TAO_PEGTL_KEYWORD("height_field"), ws, lbrace, kw_function> {};
struct height_field_function_open : p::seq<height_field_function_head> {};
struct height_field_function_size : p::seq<sum> {};
struct height_field_function_pigment
    : p::seq<lbrace, p::at<kw_pigment>, pigment_block, p::must<rbrace>> {};
struct height_field_function_expression
    : p::seq<lbrace, function_open, p::must<function_content>, p::must<function_close>> {};
struct height_field_function_body
    : p::sor<height_field_function_pigment, height_field_function_expression> {};
struct height_field_function_block
    : p::seq<p::at<height_field_function_head>, height_field_function_open,
             p::must<height_field_function_size>, p::opt<comma>,
             p::must<height_field_function_size>, p::must<height_field_function_body>,
             object_modifiers, p::must<object_close>> {};

// KIND { OBJECT modifiers }: an object's keyword around a declared object,
// read as object { OBJECT modifiers } (POV-Ray's Parse_Object_Id at the
// start of every object's block: `mesh { Declared_Mesh translate x }`).
struct declared_object_ahead_item {};
HEXANT_CUSTOM_RULE(declared_object_ahead_rule, declared_object_ahead);
struct declared_object_ahead : declared_object_ahead_rule<declared_object_ahead_item> {};
struct around_shape_keyword : one_word_of<shape_keyword_words> {};
struct around_object_keyword
    : p::sor<TAO_PEGTL_KEYWORD("mesh"), TAO_PEGTL_KEYWORD("mesh2"), TAO_PEGTL_KEYWORD("blob"),
             TAO_PEGTL_KEYWORD("isosurface"), TAO_PEGTL_KEYWORD("julia_fractal"),
             TAO_PEGTL_KEYWORD("bicubic_patch"), poly_keyword, TAO_PEGTL_KEYWORD("union"),
             TAO_PEGTL_KEYWORD("merge"), TAO_PEGTL_KEYWORD("intersection"),
             TAO_PEGTL_KEYWORD("difference"), around_shape_keyword> {};
struct keyword_around_object : p::seq<around_object_keyword, ws, lbrace, declared_object_ahead,
                                      object_base, object_modifiers, p::must<object_close>> {};
struct object_value
    : p::sor<keyword_around_object, mesh_block, mesh2_block, blob_block, isosurface_block,
             julia_block, bicubic_block, poly_block, height_field_function_block, shape_block,
             csg_block, object_block, light_block> {};

// Things that modify an object, in any order.
struct object_texture : p::seq<texture_block> {};
struct object_interior_texture : p::seq<interior_texture_block> {};
struct object_pigment : p::seq<pigment_block> {};
struct object_finish : p::seq<finish_block> {};
struct object_interior : p::seq<interior_block> {};
struct object_material : p::seq<material_block> {};
// no_shadow and inverse take no value (POV-Ray's Set_Flag: what follows is
// the next modifier, `no_shadow Placement()` a macro's transform); the
// others an optional one (its Allow_Float).
struct object_bare_flag_name
    : p::sor<TAO_PEGTL_KEYWORD("no_shadow"), TAO_PEGTL_KEYWORD("inverse")> {};
struct object_flag_name
    : p::sor<TAO_PEGTL_KEYWORD("hollow"), TAO_PEGTL_KEYWORD("sturm"), TAO_PEGTL_KEYWORD("no_image"),
             TAO_PEGTL_KEYWORD("no_reflection"), TAO_PEGTL_KEYWORD("no_radiosity"),
             TAO_PEGTL_KEYWORD("double_illuminate"), TAO_PEGTL_KEYWORD("global_lights")> {};
struct object_flag_value : p::seq<p::not_at<p::one<'<'>>, expression> {};
struct object_flag : p::sor<p::seq<object_bare_flag_name, ws, frame_open>,
                            p::seq<object_flag_name, ws, frame_open, p::opt<object_flag_value>>> {};
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
struct object_photons_flag : p::seq<photons_flag_body> {};
struct object_photons_item;
struct object_photons_item : p::sor<directive<object_photons_item>, object_photons_flag> {};
struct object_photons_block
    : p::seq<photons_open, p::star<object_photons_item>, p::must<rbrace>, ws> {};
// radiosity { importance I } (POV-Ray's Parse_Object_Mods).
struct radiosity_importance_value : p::seq<expression> {};
struct object_radiosity_importance
    : p::seq<TAO_PEGTL_KEYWORD("importance"), ws, frame_open, p::must<radiosity_importance_value>> {
};
struct object_radiosity_block : p::seq<TAO_PEGTL_KEYWORD("radiosity"), ws, p::must<lbrace>,
                                       p::star<object_radiosity_importance>, p::must<rbrace>> {};
// clipped_by { OBJECTS } and bounded_by { OBJECTS } (runtime/objects/object.hpp,
// ObjectLimits); `clipped_by { bounded_by }` clips by the bound and
// `bounded_by { clipped_by }` bounds by the clip (POV-Ray's Parse_Object_Mods).
struct limit_word : p::sor<TAO_PEGTL_KEYWORD("clipped_by"), TAO_PEGTL_KEYWORD("bounded_by")> {};
struct limit_open : p::seq<limit_word, ws, p::must<lbrace>> {};
struct limit_same
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("clipped_by"), TAO_PEGTL_KEYWORD("bounded_by")>, ws> {};
struct limit_object : p::sor<object_value, unsupported_block> {};
struct limit_item;
struct limit_item : p::sor<directive<limit_item>, macro_call<limit_item>, limit_object> {};
struct limit_close : rbrace {};
struct limit_block
    : p::seq<limit_open, p::sor<limit_same, p::star<limit_item>>, p::must<limit_close>> {};
struct object_modifier
    : p::sor<directive<object_modifier>, macro_call<object_modifier>, transformation, deformation,
             object_texture, object_interior_texture, object_pigment, object_finish, object_normal,
             object_interior, object_material, object_flag, shape_vectors_setting, shape_setting,
             limit_block, object_photons_block, object_radiosity_block> {};

}  // namespace hexant::language::grammar
