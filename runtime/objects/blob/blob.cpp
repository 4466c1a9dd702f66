#include "runtime/objects/blob/blob.hpp"

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Blob_Element_Mods and Parse_Blob (parse.cpp): a
// sphere is <centre>, radius, then the strength (the word `strength`
// optional); a cylinder two ends first; the old `component` strength,
// radius, <centre>. POV-Ray takes the radius's square, so a negative radius
// is the positive one.
void Blob::add_component(std::string_view kind, const objects::ShapeArguments& args) {
    using Kind = geometry::BlobComponent::Kind;
    if (kind == "cylinder") {
        args.need(4, 4, "two ends, a radius and a strength");
        kinds.push_back(Kind::cylinder);
        a.push_back(args.vector3(0, "a blob cylinder's base"));
        b.push_back(args.vector3(1, "a blob cylinder's apex"));
        radii.push_back(args.number(2, "a blob cylinder's radius"));
        strengths.push_back(args.number(3, "a blob cylinder's strength"));
        transforms.emplace_back();
        texture_index.push_back(-1);
        return;
    }
    kinds.push_back(Kind::sphere);
    if (kind == "component") {
        args.need(3, 3, "a strength, a radius and a centre");
        strengths.push_back(args.number(0, "a blob component's strength"));
        radii.push_back(args.number(1, "a blob component's radius"));
        a.push_back(args.vector3(2, "a blob component's centre"));
    } else {
        args.need(3, 3, "a centre, a radius and a strength");
        a.push_back(args.vector3(0, "a blob sphere's centre"));
        radii.push_back(args.number(1, "a blob sphere's radius"));
        strengths.push_back(args.number(2, "a blob sphere's strength"));
    }
    b.push_back(a.back());
    transforms.emplace_back();
    texture_index.push_back(-1);
}

void Blob::set_component_modifiers(Transform transform, std::optional<Texture> texture) {
    if (kinds.empty()) return;
    transforms.back() = std::move(transform);
    if (texture) {
        texture_index.back() = static_cast<int>(textures.size());
        textures.push_back(std::move(*texture));
    }
}

void Blob::set(std::string_view setting, const objects::ShapeArguments& value) {
    if (setting == "threshold") {
        value.need(1, 1, "a threshold");
        threshold = value.number(0, "a blob's threshold");
    } else if (setting == "hierarchy") {
        // POV-Ray's switch for its bounding hierarchy: read, ignored.
        if (value.size() > 0) (void)value.constant(0, "a blob's hierarchy");
    }
}

}  // namespace hexant::runtime
