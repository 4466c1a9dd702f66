#include "runtime/objects/height_field/height_field.hpp"

#include <map>
#include <mutex>
#include <tuple>
#include <utility>

namespace hexant::runtime {

namespace {

// Images by file and type, read once per process however many height
// fields name them (weak: freed with the last scene that used them). The
// limit is in the key: a scene of a lower --max-pixels reads the file
// again, and is refused as it would have been alone.
std::shared_ptr<const objects::HeightFieldData> field_at(const std::filesystem::path& path,
                                                         const std::string& type,
                                                         std::size_t max_pixels) {
    static std::mutex mutex;
    static std::map<std::tuple<std::filesystem::path, std::string, std::size_t>,
                    std::weak_ptr<const objects::HeightFieldData>>
        fields;
    const std::lock_guard<std::mutex> lock(mutex);
    auto& slot = fields[{path, type, max_pixels}];
    if (auto field = slot.lock()) return field;
    auto field = objects::read_height_field(path, type, max_pixels);
    slot = field;
    return field;
}

}  // namespace

HeightField HeightField::read(const objects::ShapeArguments& a) {
    const auto& options = a.options();
    if (options.size() > 1)
        a.fail("height_field takes one image type word before its file name, not " +
               std::to_string(options.size()));
    HeightField field;
    // (Every word of `options`: read_height_field refuses sys and iff, with
    // POV-Ray's reasons.)
    if (!options.empty()) field.type = options.front();
    a.need(1, 1, "an image file name");
    field.file = a.string(0, "height_field's image file name");
    try {
        field.data = field_at(a.file(0, "height_field image"), field.type, a.max_image_pixels());
    } catch (const objects::HeightFieldError& e) {
        a.fail(e.what());
    }
    return field;
}

void HeightField::set(std::string_view setting, const objects::ShapeArguments& value) {
    if (setting == "smooth") {
        smooth = objects::flag(value);
    } else if (setting == "water_level") {
        value.need(1, 1, "a water level");
        water_level = value.number(0, "height_field's water level");
    } else if (setting == "hierarchy") {
        // POV-Ray's switch for its own block hierarchy: read, ignored.
        if (value.size() > 0) (void)value.constant(0, "height_field's hierarchy");
    }
}

}  // namespace hexant::runtime
