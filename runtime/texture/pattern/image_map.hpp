// POV-Ray's image_map: a pigment whose colour is read from an image laid
// on the pattern's space by a map type (planar, spherical, cylindrical,
// torus), tiled or `once`, its pixels taken as they are or interpolated
// (POV-Ray 3.7's imageutil.cpp: image_map, map_pos, no_interpolation,
// Interp, InterpolateBicubic).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/time/interval.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime::pattern {

// An image's pixels in the scene's working colour space (linear light for
// assumed_gamma 1), rows top to bottom, each red, green, blue and transmit
// (1 - alpha; 0 for an image without alpha), in single precision as
// POV-Ray keeps them.
struct ImagePixels {
    int width = 0, height = 0;
    std::vector<float> rgbt;  // width * height * 4
    // Colours premultiplied by alpha (OpenEXR's convention): interpolated
    // so, then divided by the alpha left after transmit all, as POV-Ray.
    bool premultiplied = false;
    // From a palette: `transmit all` sets each entry's transmit (a tRNS
    // chunk's included) instead of adding to it, as POV-Ray's
    // Parse_Image_Map does to a colour-mapped image.
    bool palette = false;
    // A palette image's index of each pixel (rows top to bottom) and its
    // palette's size; empty for other images.
    std::vector<std::uint8_t> indices;
    int palette_size = 0;
};

// `filter N, AMOUNT` and `transmit N, AMOUNT` of a palette image: entry
// N's own, set after the last `filter all` / `transmit all` (which set
// every entry's, POV-Ray's Parse_Image_Map).
struct PaletteEntryAmounts {
    bool has_filter = false, has_transmit = false;
    float filter = 0.0f, transmit = 0.0f;
};

struct ImageMap {
    enum class MapType { Planar = 0, Spherical = 1, Cylindrical = 2, Torus = 5 };
    enum class Interpolate { None = 0, Bilinear = 2, Bicubic = 3, NormalizedDistance = 4 };

    std::string file;  // as the scene named it (for messages and dump)
    // The image over each piece of time, in time order: one piece over all
    // time for a file named once; an image sequence when the file's name
    // changes with clock (concat("f", str(frame_number, -3, 0), ".png")).
    struct Piece {
        Interval time;
        std::shared_ptr<const ImagePixels> pixels;
    };
    std::vector<Piece> images;
    MapType map_type = MapType::Planar;
    Interpolate interpolate = Interpolate::None;
    bool once = false;
    // A bump_map's use_index: heights from palette indices, not greys.
    bool use_index = false;
    // repeat <u, v> and offset <u, v> as written (POV-Ray scales them by
    // each image's size).
    double repeat_u = 1.0, repeat_v = 1.0;
    double offset_u = 0.0, offset_v = 0.0;
    // filter all, transmit all: added to every pixel's (transmit all,
    // when written, replaces a palette image's).
    TimeFunction filter_all = 0.0, transmit_all = 0.0;
    bool transmit_all_written = false;
    // By palette index; entries past its end keep the file's (or all's).
    std::vector<PaletteEntryAmounts> palette_entries;

    // The image at time t (the piece holding t; before the first, the
    // first; after the last, the last).
    const ImagePixels& at(double t) const;
};

// The colour at `point` (in the image map's space: the pigment's point
// after its transforms and warps) at time t: red, green, blue, filter,
// transmit. Outside an image used `once`, clear (white, transmit 1), as
// POV-Ray.
std::array<double, 5> image_colour(const ImageMap& map, const glm::dvec3& point, double t,
                                   double filter_all, double transmit_all);

// material_map { }: the number of the texture at `point` (in the map's
// space) at time t, before it is taken modulo the textures' count: a
// palette image's index there, another image's red times 255, truncated;
// 0 off an image used `once` (POV-Ray 3.7's material_map, imageutil.cpp).
int material_number(const ImageMap& map, const glm::dvec3& point, double t);

// bump_map { }: the unit normal `normal` (pattern space) tilted by the
// image at `point` (POV-Ray 3.7's bump_map): the heights of three samples,
// here and one pixel down to each side, each `amount` times the grey of
// the image's values as the file holds them (or, with use_index on a
// palette image, its index), make a triangle whose normal is turned into
// a frame about `normal`. Off an image used `once`, `normal` unchanged.
glm::dvec3 bump_map_normal(const ImageMap& map, const glm::dvec3& point, double t, double amount,
                           const glm::dvec3& normal);

}  // namespace hexant::runtime::pattern
