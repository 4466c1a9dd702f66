// POV-Ray's height_field { png "FILE.png" [smooth] [water_level W]
// [hierarchy B] }: a grid of heights from an image's pixels over
// <0, 0, 0> .. <1, 1, 1> (height_field_geometry.hpp, height_field_data.hpp).
// The object kind (runtime/objects/shape_kind.hpp).
//
// The image is read when the scene is read, once per file however many
// height fields name it, and shared by every copy. Its type word may be
// any of POV-Ray's that image::read_stored_image reads (png, exr, jpeg,
// gif, pot, tga, tiff, ppm, pgm, bmp, hdr), or none (then the file's
// extension says, as POV-Ray infers it); sys and iff are refused by name.
// The water level may be a function of time; `hierarchy` is read and
// ignored (hexant always builds its own).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>

#include "runtime/objects/height_field/height_field_data.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class HeightFieldModel;
}  // namespace objects

struct HeightField {
    static constexpr std::string_view keyword = "height_field";
    // POV-Ray 3.7's image type words (Parse_Image).
    static constexpr std::array<std::string_view, 13> options{"bmp",  "exr", "gif", "hdr", "iff",
                                                              "jpeg", "pgm", "png", "pot", "ppm",
                                                              "sys",  "tga", "tiff"};
    static constexpr std::array<std::string_view, 3> settings{"hierarchy", "smooth", "water_level"};
    using Model = objects::HeightFieldModel;

    std::string file;  // as the scene names it
    std::string type;  // the type word, or empty
    std::shared_ptr<const objects::HeightFieldData> data;
    bool smooth = false;
    TimeFunction water_level = 0.0;

    // Throws through `a` (an image type hexant does not read, a file not
    // found or unreadable, an image smaller than 2 x 2).
    static HeightField read(const objects::ShapeArguments& a);
    void set(std::string_view setting, const objects::ShapeArguments& value);
    template <class F>
    void parameters(F&& f) const {
        f("file", "file", file);
        f("heights", "heights",
          objects::DescribedParameter{data ? std::to_string(data->width()) + " x " +
                                                 std::to_string(data->depth())
                                           : std::string("none")});
        f("smooth", "smooth", smooth);
        f("water_level", "water level", water_level);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/height_field/height_field_model.hpp"
