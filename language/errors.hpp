// What the reader says when a rule that must match does not: one message per
// place that can fail, attached from outside the grammar with PEGTL's
// must_if, as in PEGTL's json_errors.hpp.
#pragma once

#include <string>

#include <tao/pegtl.hpp>

#include "language/grammar.hpp"
#include "language/nesting_guard.hpp"

namespace hexant::language {

template <typename Rule>
inline constexpr const char* error_message = nullptr;

#define HEXANT_ERROR(rule, text) \
    template <>                  \
    inline constexpr auto error_message<grammar::rule> = text

HEXANT_ERROR(unterminated_comment, "unterminated comment: this '/*' has no '*/'");
HEXANT_ERROR(number_end, "malformed number");
HEXANT_ERROR(string_close, "unterminated string: expected '\"' before the end of the line");
HEXANT_ERROR(paren_content, "expected an expression after '('");
HEXANT_ERROR(paren_close, "expected ')'");
HEXANT_ERROR(vector_component, "expected a vector component after '<' or ','");
HEXANT_ERROR(vector_close, "expected ',' or '>' to close the vector");
HEXANT_ERROR(call_open, "expected '(' after the function's name");
HEXANT_ERROR(call_argument, "expected an argument after ','");
HEXANT_ERROR(call_close, "expected ',' or ')' after the argument");
HEXANT_ERROR(trace_normal_name, "expected the name of a declared vector for trace()'s normal");
HEXANT_ERROR(defined_name, "expected a name inside defined( )");
HEXANT_ERROR(colour_model_argument, "expected a colour value after the colour keyword");
HEXANT_ERROR(colour_component_value, "expected a value after the colour component keyword");
HEXANT_ERROR(index_value, "expected an index after '['");
HEXANT_ERROR(index_close, "expected ']'");
HEXANT_ERROR(unary_operand, "expected an operand after the operator");
HEXANT_ERROR(product_operand, "expected an operand after the operator");
HEXANT_ERROR(sum_operand, "expected an operand after the comparison");
HEXANT_ERROR(comparison_operand, "expected an operand after '&' or '|'");
HEXANT_ERROR(conditional_branch, "expected an expression in the '? :' operator");
HEXANT_ERROR(colon, "expected ':' in the '? :' operator");
HEXANT_ERROR(skip::braced_close, "unterminated block: '{' without '}'");
HEXANT_ERROR(skip::parenthesized_close, "unterminated '(': expected ')'");
HEXANT_ERROR(skip::nested_end, "directive block without #end");
HEXANT_ERROR(ignored_value, "expected a value");
HEXANT_ERROR(skipped_block, "expected '{'");
HEXANT_ERROR(declare_target, "expected a name to declare after #declare or #local");
HEXANT_ERROR(declare_equals, "expected '=' after the declared name");
HEXANT_ERROR(declared_value, "expected a value after '='");
HEXANT_ERROR(undef_name, "expected a declared name after #undef");
HEXANT_ERROR(version_value, "expected a version number after #version");
HEXANT_ERROR(message_text, "expected a string after the directive");
HEXANT_ERROR(condition_value, "expected a condition");
HEXANT_ERROR(condition_close, "expected ')' after the condition");
HEXANT_ERROR(macro_parameter, "expected a parameter name after ','");
HEXANT_ERROR(for_variable, "expected a loop variable name after '#for ('");
HEXANT_ERROR(for_bound, "expected a number in #for ( )");
HEXANT_ERROR(comma, "expected ','");
HEXANT_ERROR(lparen, "expected '('");
HEXANT_ERROR(rparen, "expected ')'");
HEXANT_ERROR(lbrace, "expected '{'");
HEXANT_ERROR(rbrace, "expected '}' or a modifier that belongs in this block");
HEXANT_ERROR(transform_amount, "expected a vector after the transformation");
HEXANT_ERROR(matrix_open, "expected '<' after matrix");
HEXANT_ERROR(matrix_entry, "expected a number in the matrix");
HEXANT_ERROR(matrix_close, "expected ',' or '>' in the matrix");
HEXANT_ERROR(transform_argument, "expected '{' or a declared transform after transform");
HEXANT_ERROR(transform_block, "expected '{' after transform");
HEXANT_ERROR(deformation_axis, "expected an axis vector after the deformation");
HEXANT_ERROR(deformation_amount, "expected an amount after the deformation's axis");
HEXANT_ERROR(pattern_setting_value, "expected a value after the pattern modifier");
HEXANT_ERROR(shape_vectors_setting_value,
             "expected a <u, v> vector after uv_vectors (three, one a corner)");
HEXANT_ERROR(warp_kind,
             "expected a warp in warp { }: turbulence, repeat, black_hole, planar, cylindrical, "
             "spherical, toroidal or cubic");
HEXANT_ERROR(warp_turbulence, "expected the turbulence's amount (a vector or a number)");
HEXANT_ERROR(warp_repeat_direction, "expected the repeat's direction (a vector along one axis)");
HEXANT_ERROR(warp_black_hole_center, "expected the black hole's centre (a vector)");
HEXANT_ERROR(warp_black_hole_radius, "expected the black hole's radius after its centre");
HEXANT_ERROR(warp_planar_distance, "expected the planar warp's distance after its normal");
HEXANT_ERROR(colour_map_value, "expected a value and a colour in the colour map's entry");
HEXANT_ERROR(pigment_map_value, "expected the value of the pigment map's entry");
HEXANT_ERROR(pattern_pair_value, "expected the modifier's type and factor: TYPE, FACTOR");
HEXANT_ERROR(magnet_type, "expected magnet's type, 1 or 2");
HEXANT_ERROR(magnet_form, "expected 'mandel' or 'julia' after magnet's type");
HEXANT_ERROR(magnet_point, "expected the julia magnet's point <cr, ci>");
HEXANT_ERROR(magnet_iterations, "expected magnet's iterations");
HEXANT_ERROR(slope_written, "expected slope's direction, or its block { DIRECTION ... }");
HEXANT_ERROR(slope_direction, "expected slope's direction (a vector)");
HEXANT_ERROR(altitude_direction, "expected the altitude's direction (a vector) after 'altitude'");
HEXANT_ERROR(texture_map_value, "expected the value of the texture map's entry");
HEXANT_ERROR(tiles_texture, "expected the first tile's texture { } in tiles { }");
HEXANT_ERROR(tile2_keyword, "expected tile2 and the second tile's texture in tiles { }");
HEXANT_ERROR(tile2_texture, "expected the second tile's texture { } after tile2");
HEXANT_ERROR(material_map_texture, "expected a texture { } in material_map { } (one at least)");
HEXANT_ERROR(normal_map_value, "expected the value of the normal map's entry");
HEXANT_ERROR(slope_map_item, "expected a slope map entry: [value <height, slope>]");
HEXANT_ERROR(image_map_file, "expected the image's file name (a string)");
HEXANT_ERROR(image_map_amount, "expected the amount of filter or transmit");
HEXANT_ERROR(rbracket, "expected ']'");
HEXANT_ERROR(finish_setting_value, "expected a value after the finish setting");
HEXANT_ERROR(reflection_amount, "expected a value or '{' after reflection");
HEXANT_ERROR(reflection_value, "expected a value in reflection { }");
HEXANT_ERROR(irid_amount, "expected the amount of iridescence in irid { }");
HEXANT_ERROR(irid_setting_value, "expected a value after thickness or turbulence in irid { }");
HEXANT_ERROR(reflection_number_value,
             "expected a number after falloff or exponent in reflection { }");
HEXANT_ERROR(ior_value, "expected a value after ior");
HEXANT_ERROR(dispersion_setting_value, "expected a value after dispersion or dispersion_samples");
HEXANT_ERROR(fade_setting_value,
             "expected a value after fade_distance, fade_power, fade_colour or caustics");
HEXANT_ERROR(projected_through_base, "expected an object in projected_through { }");
HEXANT_ERROR(density_file_type, "expected df3 after density_file (its only file type)");
HEXANT_ERROR(density_file_name, "expected the density file's name (a string) after df3");
HEXANT_ERROR(object_pattern_object,
             "expected an object (a name or an object block) after object {");
HEXANT_ERROR(object_pattern_close,
             "expected the object pattern's colours, pigments, normals or textures, or '}'");
HEXANT_ERROR(density_map_value, "expected the value of a density_map entry after '['");
HEXANT_ERROR(media_setting_value, "expected a value after a media setting");
HEXANT_ERROR(media_samples_value, "expected the number of samples after samples in media { }");
HEXANT_ERROR(scattering_type,
             "expected the scattering type (1 to 5) at the start of scattering { }");
HEXANT_ERROR(scattering_colour, "expected the scattering colour after its type in scattering { }");
HEXANT_ERROR(scattering_setting_value, "expected a value after eccentricity or extinction");
HEXANT_ERROR(shape_arguments, "expected the object's parameters");
HEXANT_ERROR(mesh2_values, "expected the section's count and values");
HEXANT_ERROR(mesh2_texture_count, "expected the number of textures");
HEXANT_ERROR(mesh_inside_vector_value, "expected the inside_vector's direction");
HEXANT_ERROR(shape_argument, "expected a parameter");
HEXANT_ERROR(first_shape_argument, "expected a parameter");
HEXANT_ERROR(polynomial_power, "expected a power of x, y or z");
HEXANT_ERROR(julia_parameter, "expected the julia_fractal's 4D parameter <x, y, z, t>");
HEXANT_ERROR(julia_value, "expected a value");
HEXANT_ERROR(bicubic_value, "expected a value");
HEXANT_ERROR(bicubic_points, "expected the bicubic_patch's 16 control points");
HEXANT_ERROR(polynomial_coefficient, "expected the term's coefficient");
HEXANT_ERROR(declare_index, "expected '[' and an array index");
HEXANT_ERROR(fopen_id, "expected the file's name for the scene (an identifier)");
HEXANT_ERROR(fopen_path, "expected the file's name on disk, a string");
HEXANT_ERROR(fopen_mode, "expected read, write or append");
HEXANT_ERROR(fclose_id, "expected the name of an open file");
HEXANT_ERROR(file_id, "expected the name of an open file");
HEXANT_ERROR(write_binary_value, "expected a float or a vector to write");
HEXANT_ERROR(file_close, "expected ')' or another item");
HEXANT_ERROR(poly_values, "expected <coefficients> or xyz(i, j, k): coefficient");
HEXANT_ERROR(limit_close, "expected '}' or an object");
HEXANT_ERROR(object_close, "expected '}' or a modifier that belongs in this object");
HEXANT_ERROR(function_parameter, "expected a parameter's name after ','");
HEXANT_ERROR(function_internal_number, "expected internal()'s number");
HEXANT_ERROR(function_close, "expected '}' to end the function's body");
HEXANT_ERROR(height_field_function_size,
             "expected the height_field function's grid size: function WIDTH, HEIGHT { }");
HEXANT_ERROR(height_field_function_body,
             "expected the height_field function's body in braces: an expression of x and y, "
             "or a pigment { }");
HEXANT_ERROR(contained_by_shape, "expected box { corner, corner } or sphere { centre, radius }");
HEXANT_ERROR(function_content, "expected the function's body, an expression of its parameters");
HEXANT_ERROR(object_base, "expected an object or a declared object's name");
HEXANT_ERROR(looks_like_base, "expected an object or a declared object's name");
HEXANT_ERROR(light_arguments, "expected the light's position and colour");
HEXANT_ERROR(light_setting_value, "expected a value after the light setting");
HEXANT_ERROR(area_light_argument, "expected area_light <axis1>, <axis2>, size1, size2");
HEXANT_ERROR(camera_cylinder_value, "expected the cylinder camera's type (1 to 4)");
HEXANT_ERROR(mesh_camera_value,
             "expected mesh_camera's rays per pixel and distribution type (then its meshes)");
HEXANT_ERROR(camera_blur_argument, "expected a value for aperture, focal_point or blur_samples");
HEXANT_ERROR(camera_vector_value, "expected a value after the camera setting");
HEXANT_ERROR(background_colour, "expected a colour in background { }");
HEXANT_ERROR(global_setting_value, "expected a value after the global setting");
HEXANT_ERROR(radiosity_importance_value, "expected a value after importance");
HEXANT_ERROR(charset_name, "expected a character set name after charset");
HEXANT_ERROR(array_dimensions, "expected '[' and a size after array");
HEXANT_ERROR(array_size, "expected the array's size");
HEXANT_ERROR(array_initializer_close, "expected ',' or '}' in the array's elements");
HEXANT_ERROR(spline_key_value, "expected the spline key's value after its time");
HEXANT_ERROR(scene_end,
             "expected a scene item (an object, camera, light_source, background, "
             "global_settings) or a directive");

HEXANT_ERROR(condition, "expected '(' and a condition");
HEXANT_ERROR(for_header, "expected ( NAME, START, END [, STEP] ) after #for");
HEXANT_ERROR(range_header, "expected ( LOW, HIGH ) after #range");
HEXANT_ERROR(include_name, "expected a file name after #include");
HEXANT_ERROR(macro_body_end,
             "this does not belong here: expected an item of the block the macro is called in, "
             "or a directive");
HEXANT_ERROR(include_end,
             "this does not belong here: expected an item of the block the file is included in, "
             "or a directive");

#undef HEXANT_ERROR

struct error_messages {
    template <typename Rule>
    static constexpr auto message = error_message<Rule>;
    // Only a failed must<> is an error; elsewhere failing means trying the
    // next alternative.
    template <typename Rule>
    static constexpr bool raise_on_failure = false;
};

// The text of the token where a failure was found, for "... but found 'x'".
template <typename ParseInput>
std::string found_text(const ParseInput& in) {
    const char* b = in.current();
    const char* e = in.end();
    if (b == e) return " but found the end of the file";
    if (*b == '\n' || *b == '\r') return " but found the end of the line";
    if (const unsigned char c = static_cast<unsigned char>(*b);
        (c < 0x20 && c != '\t') || c == 0x7F) {
        // A control character (a NUL, an escape) named, not printed: it
        // would cut the message short or reach the terminal.
        static const char* const kHex = "0123456789ABCDEF";
        return std::string(" but found the control character 0x") + kHex[c >> 4] + kHex[c & 15];
    }
    const char* q = b;
    if (*q == '#') ++q;  // a directive: show its name
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    if (q != e && word(*q))
        while (q != e && word(*q) && q - b < 40) ++q;
    else if (q == b)
        ++q;
    return " but found '" + std::string(b, q) + "'";
}

// The rules each level of nesting passes through: where the reader checks
// its stack (nesting_guard.hpp).
template <typename Rule>
inline constexpr bool kNests =
    std::is_same_v<Rule, grammar::unary> || std::is_same_v<Rule, grammar::vector_literal> ||
    std::is_same_v<Rule, grammar::skip::nested> || std::is_same_v<Rule, grammar::skip::braced> ||
    std::is_same_v<Rule, grammar::skip::parenthesized> ||
    std::is_same_v<Rule, grammar::object_value> || std::is_same_v<Rule, grammar::csg_block> ||
    std::is_same_v<Rule, grammar::scene_item> || std::is_same_v<Rule, grammar::hash>;

template <typename Rule>
struct control : tao::pegtl::must_if<error_messages, tao::pegtl::normal, true>::control<Rule> {
    using base = typename tao::pegtl::must_if<error_messages, tao::pegtl::normal,
                                              true>::template control<Rule>;

    template <typename ParseInput, typename... States>
    static void start(const ParseInput& in, States&&... states) {
        if constexpr (kNests<Rule>) NestingGuard::check(in);
        base::start(in, states...);
    }

    template <typename ParseInput, typename... States>
    [[noreturn]] static void raise(const ParseInput& in, States&&...) {
        static_assert(error_messages::message<Rule> != nullptr,
                      "every rule under must<> needs an error_message");
        if constexpr (std::is_same_v<Rule, grammar::unterminated_comment>)
            throw tao::pegtl::parse_error(error_messages::message<Rule>, in);  // at its '/*'
        else
            throw tao::pegtl::parse_error(
                std::string(error_messages::message<Rule>) + found_text(in), in);
    }
};

}  // namespace hexant::language
