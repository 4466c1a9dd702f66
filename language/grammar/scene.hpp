// Scene items: camera, lights, global settings, fog, sky; values; the scene file.
// Part of the grammar (language/grammar.hpp).
#pragma once

#include "language/grammar/objects.hpp"

namespace hexant::language::grammar {

// ---------------------------------------------------------------- scene items

HEXANT_KEYWORD(kw_camera, "camera");
struct camera_open : p::seq<kw_camera, p::must<lbrace>> {};
struct camera_base : p::seq<expression> {};
struct camera_vector_name : p::sor<TAO_PEGTL_KEYWORD("location"), TAO_PEGTL_KEYWORD("look_at"),
                                   TAO_PEGTL_KEYWORD("direction"), TAO_PEGTL_KEYWORD("right"),
                                   TAO_PEGTL_KEYWORD("up"), TAO_PEGTL_KEYWORD("sky")> {};
struct camera_vector_value : p::seq<expression> {};
struct camera_setting : p::seq<camera_vector_name, ws, p::must<camera_vector_value>> {};
// angle [A] (orthographic: the value may be left out, POV-Ray's
// Allow_Float); spherical: angle H [, V].
struct camera_angle_value : p::seq<sum> {};
struct camera_angle
    : p::seq<TAO_PEGTL_KEYWORD("angle"), ws, frame_open,
             p::opt<camera_angle_value, p::opt<p::opt<comma>, camera_angle_value>>> {};
// The projection (POV-Ray's camera types; the type comes first).
struct camera_type : p::sor<TAO_PEGTL_KEYWORD("perspective"), TAO_PEGTL_KEYWORD("orthographic"),
                            TAO_PEGTL_KEYWORD("fisheye"), TAO_PEGTL_KEYWORD("panoramic"),
                            TAO_PEGTL_KEYWORD("spherical"), TAO_PEGTL_KEYWORD("ultra_wide_angle"),
                            TAO_PEGTL_KEYWORD("omnimax")> {};
// cylinder N: POV-Ray's cylinder cameras 1 to 4.
struct camera_cylinder_value : p::seq<sum> {};
struct camera_cylinder
    : p::seq<TAO_PEGTL_KEYWORD("cylinder"), ws, frame_open, p::must<camera_cylinder_value>> {};
// mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { } ... [smooth] }
// (POV-Ray's Parse_Mesh_Camera; runtime/scene/mesh_camera.hpp): its
// numbers, then the meshes, which directives and macros may write.
struct mesh_camera_value : p::seq<sum> {};
struct mesh_camera_mesh : p::sor<keyword_around_object, mesh_block, mesh2_block> {};
struct mesh_camera_item
    : p::sor<directive<mesh_camera_item>, macro_call<mesh_camera_item>, mesh_camera_mesh> {};
struct mesh_camera_smooth : p::seq<TAO_PEGTL_KEYWORD("smooth"), ws> {};
struct camera_mesh_camera
    : p::seq<TAO_PEGTL_KEYWORD("mesh_camera"), ws, p::must<lbrace>, frame_open,
             p::must<mesh_camera_value>, p::opt<comma>, p::must<mesh_camera_value>,
             p::opt<p::opt<comma>, mesh_camera_value>, p::star<mesh_camera_item>,
             p::opt<mesh_camera_smooth>, p::must<rbrace>> {};
// Focal blur: aperture A, focal_point <P>, blur_samples [MIN,] MAX;
// confidence and variance are POV-Ray's stopping rule, read and ignored
// (hexant's samples are --spp or --target-error's).
struct camera_blur_name : p::sor<TAO_PEGTL_KEYWORD("aperture"), TAO_PEGTL_KEYWORD("blur_samples"),
                                 TAO_PEGTL_KEYWORD("focal_point")> {};
struct camera_blur_argument : p::seq<sum> {};
struct camera_blur_setting
    : p::seq<camera_blur_name, ws, frame_open, p::must<camera_blur_argument>,
             p::opt<p::opt<comma>, p::not_at<camera_blur_name>, camera_blur_argument>> {};
struct camera_ignored_setting
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("confidence"), TAO_PEGTL_KEYWORD("variance")>, ws,
             p::must<ignored_value>> {};
struct camera_item
    : p::sor<directive<camera_item>, macro_call<camera_item>, p::seq<camera_type, ws>,
             camera_cylinder, camera_setting, camera_angle, camera_blur_setting,
             camera_ignored_setting, camera_normal, transformation, camera_mesh_camera> {};
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
struct sky_sphere_emission
    : p::seq<TAO_PEGTL_KEYWORD("emission"), ws, p::must<pattern_setting_value>> {};
struct sky_sphere_item : p::sor<directive<sky_sphere_item>, macro_call<sky_sphere_item>,
                                sky_sphere_pigment, sky_sphere_emission, transformation> {};
struct sky_sphere_block
    : p::seq<sky_sphere_open, p::opt<sky_sphere_base>, p::star<sky_sphere_item>, p::must<rbrace>> {
};

// fog { [COLOUR] distance D fog_type 1|2 fog_offset fog_alt up turbulence
// octaves omega lambda turb_depth rotate scale }
struct fog_open : p::seq<TAO_PEGTL_KEYWORD("fog"), ws, p::must<lbrace>> {};
struct fog_setting_name : p::sor<TAO_PEGTL_KEYWORD("distance"), TAO_PEGTL_KEYWORD("fog_type"),
                                 TAO_PEGTL_KEYWORD("fog_alt"), TAO_PEGTL_KEYWORD("fog_offset"),
                                 TAO_PEGTL_KEYWORD("turb_depth"), TAO_PEGTL_KEYWORD("up"),
                                 TAO_PEGTL_KEYWORD("turbulence"), TAO_PEGTL_KEYWORD("octaves"),
                                 TAO_PEGTL_KEYWORD("omega"), TAO_PEGTL_KEYWORD("lambda")> {};
struct fog_setting : p::seq<fog_setting_name, ws, p::must<pattern_setting_value>> {};
struct fog_colour : p::seq<expression> {};
struct fog_item
    : p::sor<directive<fog_item>, macro_call<fog_item>, fog_setting, transformation, fog_colour> {};
struct fog_block : p::seq<fog_open, p::star<fog_item>, p::must<rbrace>> {};
// rainbow { angle A width W distance D direction V up V jitter J arc_angle A
// falloff_angle A color_map { } } (runtime/scene/rainbow.hpp).
struct rainbow_open : p::seq<TAO_PEGTL_KEYWORD("rainbow"), ws, p::must<lbrace>> {};
struct rainbow_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("angle"), TAO_PEGTL_KEYWORD("width"), TAO_PEGTL_KEYWORD("distance"),
             TAO_PEGTL_KEYWORD("direction"), TAO_PEGTL_KEYWORD("up"), TAO_PEGTL_KEYWORD("jitter"),
             TAO_PEGTL_KEYWORD("arc_angle"), TAO_PEGTL_KEYWORD("falloff_angle")> {};
struct rainbow_setting : p::seq<rainbow_setting_name, ws, p::must<pattern_setting_value>> {};
struct rainbow_colour_map : p::seq<colour_map_block> {};
struct rainbow_item : p::sor<directive<rainbow_item>, macro_call<rainbow_item>, rainbow_setting,
                             rainbow_colour_map> {};
struct rainbow_block : p::seq<rainbow_open, p::star<rainbow_item>, p::must<rbrace>> {};

HEXANT_KEYWORD(kw_global_settings, "global_settings");
struct global_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("assumed_gamma"), TAO_PEGTL_KEYWORD("max_trace_level"),
             TAO_PEGTL_KEYWORD("ambient_light"), TAO_PEGTL_KEYWORD("noise_generator"),
             TAO_PEGTL_KEYWORD("irid_wavelength"), TAO_PEGTL_KEYWORD("number_of_waves")> {};
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
    : p::seq<TAO_PEGTL_KEYWORD("motion_blur"), ws, frame_open, p::must<global_setting_value>,
             p::opt<comma>, p::must<global_setting_value>> {};
// hf_gray_16 [on|off|FLOAT]: POV-Ray 3.7 reads and ignores it (grey output
// is a command-line option there), and so does hexant.
struct global_hf_gray_16
    : p::seq<p::sor<TAO_PEGTL_KEYWORD("hf_gray_16"), TAO_PEGTL_KEYWORD("hf_grey_16")>, ws,
             p::opt<p::sor<p::at<p::sor<TAO_PEGTL_KEYWORD("on"), TAO_PEGTL_KEYWORD("off"),
                                        TAO_PEGTL_KEYWORD("true"), TAO_PEGTL_KEYWORD("false"),
                                        TAO_PEGTL_KEYWORD("yes"), TAO_PEGTL_KEYWORD("no")>>,
                           p::not_at<p::identifier>>,
                    ignored_value>> {};
// radiosity { NAME VALUE [, VALUE] ... } (runtime/scene/radiosity_settings.hpp):
// each setting one or two values (count and nearest_count take a second),
// load_file and save_file a string; directives and macros among them, as
// rad_def.inc's Rad_Settings writes them.
struct radiosity_open : p::seq<TAO_PEGTL_KEYWORD("radiosity"), ws, p::must<lbrace>> {};
struct radiosity_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("adc_bailout"), TAO_PEGTL_KEYWORD("always_sample"),
             TAO_PEGTL_KEYWORD("brightness"), TAO_PEGTL_KEYWORD("brilliance"),
             TAO_PEGTL_KEYWORD("count"), TAO_PEGTL_KEYWORD("error_bound"),
             TAO_PEGTL_KEYWORD("gray_threshold"), TAO_PEGTL_KEYWORD("load_file"),
             TAO_PEGTL_KEYWORD("low_error_factor"), TAO_PEGTL_KEYWORD("max_sample"),
             TAO_PEGTL_KEYWORD("maximum_reuse"), TAO_PEGTL_KEYWORD("media"),
             TAO_PEGTL_KEYWORD("minimum_reuse"), TAO_PEGTL_KEYWORD("nearest_count"),
             TAO_PEGTL_KEYWORD("normal"), TAO_PEGTL_KEYWORD("pretrace_end"),
             TAO_PEGTL_KEYWORD("pretrace_start"), TAO_PEGTL_KEYWORD("recursion_limit"),
             TAO_PEGTL_KEYWORD("save_file"), TAO_PEGTL_KEYWORD("subsurface")> {};
struct radiosity_setting
    : p::seq<radiosity_setting_name, ws, frame_open, p::must<global_setting_value>,
             p::opt<comma, p::must<global_setting_value>>> {};
struct radiosity_item;
struct radiosity_item
    : p::sor<directive<radiosity_item>, macro_call<radiosity_item>, radiosity_setting> {};
struct global_radiosity : p::seq<radiosity_open, p::star<radiosity_item>, p::must<rbrace>> {};
// photons { NAME VALUE [, VALUE ...] ... } (runtime/scene/photon_settings.hpp):
// gather, media and expand_thresholds take two values, radius up to four.
struct photons_global_open : p::seq<TAO_PEGTL_KEYWORD("photons"), ws, p::must<lbrace>> {};
struct photons_setting_name
    : p::sor<TAO_PEGTL_KEYWORD("spacing"), TAO_PEGTL_KEYWORD("count"), TAO_PEGTL_KEYWORD("gather"),
             TAO_PEGTL_KEYWORD("media"), TAO_PEGTL_KEYWORD("jitter"),
             TAO_PEGTL_KEYWORD("max_trace_level"), TAO_PEGTL_KEYWORD("adc_bailout"),
             TAO_PEGTL_KEYWORD("autostop"), TAO_PEGTL_KEYWORD("expand_thresholds"),
             TAO_PEGTL_KEYWORD("radius"), TAO_PEGTL_KEYWORD("load_file"),
             TAO_PEGTL_KEYWORD("save_file")> {};
struct photons_setting
    : p::seq<photons_setting_name, ws, frame_open,
             p::opt<p::not_at<photons_setting_name>, p::not_at<rbrace>, global_setting_value>,
             p::star<comma, p::must<global_setting_value>>> {};
struct photons_global_item;
struct photons_global_item
    : p::sor<directive<photons_global_item>, macro_call<photons_global_item>, photons_setting> {};
struct global_photons : p::seq<photons_global_open, p::star<photons_global_item>, p::must<rbrace>> {
};
struct global_item
    : p::sor<directive<global_item>, global_setting, global_charset, global_motion_blur,
             global_hf_gray_16, global_radiosity, global_photons, global_ignored_setting> {};
struct global_settings_block
    : p::seq<kw_global_settings, p::must<lbrace>, p::star<global_item>, p::must<rbrace>> {};

// #default { texture { } | pigment { } | normal { } | finish { } }, also
// written without its '#' (POV-Ray 3.7 reads both: the distribution's
// colors.pov and laser.pov).
// #default { radiosity { importance I } } (the default importance).
struct default_radiosity_importance
    : p::seq<TAO_PEGTL_KEYWORD("importance"), ws, frame_open, p::must<radiosity_importance_value>> {
};
struct default_radiosity : p::seq<TAO_PEGTL_KEYWORD("radiosity"), ws, p::must<lbrace>,
                                  p::star<default_radiosity_importance>, p::must<rbrace>> {};
struct default_value : p::sor<texture_block, pigment_block, normal_block, finish_block> {};
struct default_item : p::sor<default_value, default_radiosity> {};
struct default_open : p::seq<kw_default, p::must<lbrace>> {};
struct default_block : p::seq<default_open, p::star<default_item>, p::must<rbrace>> {};

// ---------------------------------------------------------------- values

// array[N][M] { ... }
HEXANT_KEYWORD(kw_array, "array");
struct array_size : p::seq<expression> {};
struct array_dimension : p::seq<lbracket, p::must<array_size>, p::must<index_close>> {};
struct array_dimensions : p::seq<frame_open, p::plus<array_dimension>> {};
struct array_element;
struct array_initializer_close : rbrace {};
// Commas between elements are optional (POV-Ray's Parse_Comma), and an
// element is a sum, not a comparison (its Parse_Rel_Factor): a vector
// followed by the next one's '<' ends there (`<1, 2> <3, 4>`).
struct array_initializer
    : p::seq<lbrace, frame_open, p::opt<array_element, p::star<p::opt<comma>, array_element>>,
             p::opt<comma>, p::must<array_initializer_close>> {};
struct array_vector_element
    : p::seq<p::at<vector_literal, ws, p::one<'<'>, p::not_at<p::one<'='>>>, sum> {};
struct array_element : p::sor<array_initializer, array_vector_element, value> {};
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
struct spline_base : p::seq<p::at<reference, p::sor<rbrace, spline_kind>>, p::seq<expression>> {};
struct spline_block
    : p::seq<spline_open, p::opt<spline_base>, p::star<spline_item>, p::must<rbrace>> {};
// function { spline { } }: a spline function, F(t) the spline's vector at t.
struct function_spline_open
    : p::seq<kw_function, lbrace, p::at<TAO_PEGTL_KEYWORD("spline"), ws, lbrace>> {};
struct function_spline : p::seq<function_spline_open, spline_block, p::must<rbrace>> {};
// function { transform { } }: F(x, y, z) the transformed point (as
// transforms.inc's vtransform uses it).
struct function_transform_open
    : p::seq<kw_function, lbrace, p::at<TAO_PEGTL_KEYWORD("transform"), ws, lbrace>> {};
struct function_transform
    : p::seq<function_transform_open, kw_transform, transform_block, p::must<rbrace>> {};

// texture { } texture { } ...: POV-Ray's layered texture.
struct texture_layer : p::seq<texture_block> {};
// A declared material: its texture and interior, each when written.
struct material_value : p::seq<material_block> {};
struct texture_value : p::seq<texture_block, p::star<texture_layer>> {};

struct value : p::sor<object_value, camera_block, texture_value, pigment_block, normal_block,
                      colour_map_block, sky_sphere_block, finish_block, interior_block, media_block,
                      density_block, material_value, transform_value, array_value, spline_block,
                      function_pigment, function_spline, function_transform, function_pattern_value,
                      function_value, unsupported_block, expression> {};

// A macro called where a value is wanted holds values (and directives);
// a ';' after its value is read and dropped, as POV-Ray does with a macro
// that ends `Q;` (tracevines.pov).
struct value_item : p::sor<directive<value_item>, value, semicolon> {};

// ---------------------------------------------------------------- the scene

struct scene_object : p::seq<object_value> {};
struct scene_unsupported : p::seq<unsupported_block> {};
struct scene_camera : p::seq<camera_block> {};
struct scene_sky_sphere : p::seq<sky_sphere_block> {};
// media { } at the top: the atmosphere's (runtime/scene/media.hpp).
struct scene_media : p::seq<media_block> {};
struct scene_item
    : p::sor<directive<scene_item>, macro_call<scene_item>, scene_object, scene_camera,
             background_block, scene_sky_sphere, fog_block, rainbow_block, scene_media,
             global_settings_block, default_block, scene_unsupported, semicolon> {};
struct scene_end : p::eof {};
struct scene_file : p::seq<ws, p::star<scene_item>, p::must<scene_end>> {};

}  // namespace hexant::language::grammar
