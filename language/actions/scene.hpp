// The camera, global settings, fog, sky and the scene's other items.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/global_lighting.hpp"
#include "language/actions/lights.hpp"

namespace hexant::language {

// ------------------------------------------------------------ camera and scene

template <>
struct action<g::camera_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::CameraRecord>);
    }
};
template <>
struct action<g::camera_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::CameraRecord>())
            throw ValueError("camera { } starts with a camera, not a " + type_name(v));
        st.blocks.edit<runtime::CameraRecord>(in.position(), "a camera") =
            v.as<runtime::CameraRecord>();
    }
};
template <>
struct action<g::camera_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& camera = st.blocks.edit<runtime::CameraRecord>(in.position(), name.c_str());
        runtime::CameraItem item;
        using K = runtime::CameraItem::Kind;
        item.kind = name == "location"    ? K::Location
                    : name == "look_at"   ? K::LookAt
                    : name == "direction" ? K::Direction
                    : name == "right"     ? K::Right
                    : name == "up"        ? K::Up
                                          : K::Sky;
        item.vector = to_vector3(v, "the camera's " + name);
        camera.items.push_back(std::move(item));
    }
};
template <>
struct action<g::mesh_camera_smooth> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.values.push(Value{std::string("smooth")});  // (the last of the block's values)
    }
};
// The camera's type item. POV-Ray reads the type before any other item
// (the last of several types in a row wins), and not at all after a camera
// identifier (then only transforms may follow).
template <typename Position>
void add_camera_type(const Position& position, Interpreter& st, const std::string& name,
                     runtime::CameraType type) {
    auto& camera = st.blocks.edit<runtime::CameraRecord>(position, name.c_str());
    const bool only_types =
        std::all_of(camera.items.begin(), camera.items.end(),
                    [](const auto& item) { return item.kind == runtime::CameraItem::Kind::Type; });
    if (!only_types || !camera.pieces.empty() || camera.normal)
        throw ValueError("the camera's type (" + name +
                         ") must come first in camera { }, before its other "
                         "items and not after a declared camera (as POV-Ray requires)");
    runtime::CameraItem item;
    item.kind = runtime::CameraItem::Kind::Type;
    item.type = type;
    camera.items.push_back(std::move(item));
}
// mesh_camera { }: its numbers as POV-Ray reads them (Parse_Float,
// truncated to unsigned), the meshes each with the faces a mesh camera
// counts (mesh { } drops its degenerate triangles, mesh2 { } keeps them).
template <>
struct action<g::camera_mesh_camera> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const bool smooth = !given.empty() && given.back().is<std::string>();
        if (smooth) given.pop_back();
        std::vector<double> numbers;
        std::vector<runtime::MeshCamera::Mesh> meshes;
        for (const Value& v : given) {
            if (!v.is<runtime::ObjectPtr>()) {
                if (!meshes.empty() || numbers.size() == 3)
                    throw ValueError("mesh_camera takes its numbers before its meshes");
                numbers.push_back(to_constant(v, "mesh_camera's numbers"));
                continue;
            }
            const runtime::ObjectRecord& object = *v.as<runtime::ObjectPtr>();
            const auto* mesh = std::get_if<runtime::Mesh>(&object.shape);
            if (!mesh) throw ValueError("mesh_camera takes mesh and mesh2 objects only");
            if (object.transform.has_deformation())
                throw ValueError(
                    "a mesh camera's mesh may be moved, turned and scaled, not "
                    "deformed");
            runtime::MeshCamera::Mesh m{mesh->data, {}, object.transform};
            const auto& data = *mesh->data;
            for (const std::uint32_t at : data.read_index) {
                const auto& face = data.faces[at];
                const glm::dvec3 &p1 = data.vertices[face.vertex[0]],
                                 &p2 = data.vertices[face.vertex[1]],
                                 &p3 = data.vertices[face.vertex[2]];
                const glm::dvec3 n = glm::cross(p1 - p2, p3 - p2);  // (Mesh::Degenerate)
                if (!data.mesh2 && glm::dot(n, n) == 0.0) continue;
                m.faces.push_back(at);
            }
            meshes.push_back(std::move(m));
        }
        const auto whole = [](double v, const char* what) {
            if (!(v >= 0.0 && v < 4294967296.0))
                throw ValueError(std::string("mesh_camera's ") + what +
                                 " must be a whole number from 0");
            return static_cast<unsigned>(v);
        };
        const unsigned rays = whole(numbers.at(0), "rays per pixel");
        const unsigned distribution = whole(numbers.at(1), "distribution type");
        const double max_distance = numbers.size() > 2 ? numbers[2] : 0.0;
        if (max_distance != 0.0)
            throw ValueError(
                "mesh_camera's max distance is not supported by hexant yet (leave it out or 0)");
        std::shared_ptr<const runtime::MeshCamera> camera;
        try {
            camera = std::make_shared<const runtime::MeshCamera>(rays, distribution, max_distance,
                                                                 smooth, std::move(meshes));
        } catch (const std::invalid_argument& e) {
            throw ValueError(std::string("mesh_camera: ") + e.what());
        }
        if (distribution == 3 && camera->meshes().size() > 1)
            st.warn(in.position(),
                    "mesh_camera: additional meshes after the first are ignored for "
                    "distribution method #3 (as in POV-Ray)");
        add_camera_type(in.position(), st, "mesh_camera", runtime::CameraType::Mesh);
        st.blocks.edit<runtime::CameraRecord>(in.position(), "mesh_camera").items.back().mesh =
            std::move(camera);
    }
};
template <>
struct action<g::camera_type> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string name = word(in);
        using T = runtime::CameraType;
        add_camera_type(in.position(), st, name,
                        name == "orthographic"       ? T::Orthographic
                        : name == "fisheye"          ? T::Fisheye
                        : name == "panoramic"        ? T::Panoramic
                        : name == "spherical"        ? T::Spherical
                        : name == "ultra_wide_angle" ? T::UltraWideAngle
                        : name == "omnimax"          ? T::Omnimax
                                                     : T::Perspective);
    }
};
template <>
struct action<g::camera_cylinder> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        // POV-Ray's Parse_Float, truncated to an integer (parser.cpp).
        const double kind = to_constant(given.at(0), "the cylinder camera's type");
        using T = runtime::CameraType;
        const int n = std::isfinite(kind) ? static_cast<int>(std::trunc(kind)) : 0;
        if (n < 1 || n > 4)
            throw ValueError("invalid cylinder camera type, valid are types 1 to 4 (as POV-Ray's)");
        add_camera_type(in.position(), st, "cylinder",
                        n == 1   ? T::Cylinder1
                        : n == 2 ? T::Cylinder2
                        : n == 3 ? T::Cylinder3
                                 : T::Cylinder4);
    }
};
template <>
struct action<g::camera_angle> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        auto& camera = st.blocks.edit<runtime::CameraRecord>(in.position(), "angle");
        using T = runtime::CameraType;
        T type = T::Perspective;
        for (const auto& item : camera.items)
            if (item.kind == runtime::CameraItem::Kind::Type) type = item.type;
        const char* name = type == T::Perspective      ? "perspective"
                           : type == T::Orthographic   ? "orthographic"
                           : type == T::Fisheye        ? "fisheye"
                           : type == T::Panoramic      ? "panoramic"
                           : type == T::Spherical      ? "spherical"
                           : type == T::UltraWideAngle ? "ultra_wide_angle"
                           : type == T::Omnimax        ? "omnimax"
                           : type == T::Mesh           ? "mesh_camera"
                                                       : "cylinder";
        // POV-Ray's Parse_Camera: an orthographic angle may be left out (0);
        // only a spherical camera takes a second (vertical) angle.
        if (given.empty() && type != T::Orthographic)
            throw ValueError(std::string("a ") + name + " camera's angle needs a value");
        if (given.size() > 1 && type != T::Spherical)
            throw ValueError(std::string("a ") + name +
                             " camera's angle takes one value (two: a spherical camera's)");
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Angle;
        item.angle = given.empty() ? TimeFunction(0.0) : to_float(given[0], "the camera's angle");
        if (item.angle.is_constant()) {
            const double a = item.angle.constant();
            if (type == T::Perspective && (a <= 0.0 || a >= 180.0))
                throw ValueError("a perspective camera's angle must lie between 0 and 180 degrees");
            if (type == T::Orthographic && (a < 0.0 || a >= 180.0))
                throw ValueError("an orthographic camera's angle must lie in [0, 180) degrees");
            if (!(a >= 0.0))
                throw ValueError(std::string("a ") + name + " camera's angle must not be negative");
        }
        camera.items.push_back(item);
        if (given.size() > 1) {
            runtime::CameraItem vertical;
            vertical.kind = runtime::CameraItem::Kind::VerticalAngle;
            vertical.angle = to_float(given[1], "the spherical camera's vertical angle");
            if (vertical.angle.is_constant() && !(vertical.angle.constant() >= 0.0))
                throw ValueError("a spherical camera's vertical angle must not be negative");
            camera.items.push_back(std::move(vertical));
        }
    }
};
template <>
struct action<g::camera_blur_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        auto& camera = st.blocks.edit<runtime::CameraRecord>(in.position(), name.c_str());
        runtime::CameraItem item;
        using K = runtime::CameraItem::Kind;
        if (given.size() > 1 && name != "blur_samples") throw ValueError(name + " takes one value");
        if (name == "focal_point") {
            item.kind = K::FocalPoint;
            item.vector = to_vector3(given[0], "the camera's focal_point");
        } else {
            item.kind = name == "aperture" ? K::Aperture : K::BlurSamples;
            // (blur_samples MIN, MAX: POV-Ray's most is what counts here.)
            item.angle = to_float(given.back(), "the camera's " + name);
            if (name == "blur_samples") {
                // POV-Ray's rules: whole numbers (truncated) of 1 or more,
                // the least not above the most.
                double least = 1.0, most = 1.0;
                for (std::size_t k = 0; k < given.size(); ++k) {
                    const TimeFunction f = to_float(given[k], "the camera's blur_samples");
                    if (!f.is_constant()) continue;
                    const double v = std::trunc(f.constant());
                    if (!(v >= 1.0))
                        throw ValueError(
                            "blur_samples must be 1 or more (POV-Ray: illegal number of focal blur "
                            "samples)");
                    (k + 1 == given.size() ? most : least) = v;
                }
                if (given.size() > 1 && least > most)
                    throw ValueError("blur_samples' least must not be above its most");
            }
        }
        camera.items.push_back(std::move(item));
    }
};
template <>
struct action<g::camera_ignored_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.not_rendered(in.position(), word(in));
    }
};
template <>
struct action<g::camera_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v{std::get<runtime::CameraRecord>(st.blocks.top())};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::scene_camera> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        ++st.camera_sets;  // (under a branch on clock: piecewise, split_time)
        st.scene.camera = st.values.pop().as<runtime::CameraRecord>();
        if (auto problem = runtime::bad_parameter(st.scene.camera, st.scene.animation))
            throw ValueError(*problem);
    }
};
template <>
struct action<g::background_colour> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        ++st.background_sets;
        st.scene.background = to_colour(st.values.pop(), "the background");
    }
};
template <>
struct action<g::sky_sphere_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::SkySphere>);
    }
};
template <>
struct action<g::sky_sphere_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::SkySphere>())
            throw ValueError("sky_sphere { } starts with a sky_sphere, not a " + type_name(v));
        st.blocks.edit<runtime::SkySphere>(in.position(), "a sky_sphere") =
            v.as<runtime::SkySphere>();
    }
};
template <>
struct action<g::sky_sphere_pigment> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        // (POV-Ray: "The 'uv_mapping' pattern cannot be used" without a surface.)
        if (v.as<runtime::Pigment>().uv_mapping != runtime::UvMapping::Off)
            throw ValueError("uv_mapping needs a surface's (u, v): not in a sky_sphere");
        st.blocks.edit<runtime::SkySphere>(in.position(), "a pigment")
            .pigments.push_back(v.as<runtime::Pigment>());
    }
};
template <>
struct action<g::sky_sphere_emission> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::SkySphere>(in.position(), "emission").emission =
            to_colour(v, "emission");
    }
};
template <>
struct action<g::sky_sphere_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& sky = st.blocks.edit<runtime::SkySphere>(in.position(), "a sky_sphere");
        if (sky.pigments.empty())
            throw ValueError("a sky_sphere needs a pigment (POV-Ray: empty sky_sphere statement)");
        Value v{std::move(sky)};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::scene_sky_sphere> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "a sky_sphere");
        runtime::SkySphere sky = st.values.pop().as<runtime::SkySphere>();
        for (const auto& pigment : sky.pigments) check_pigment(pigment);
        st.scene.sky_sphere = std::move(sky);
    }
};

template <>
struct action<g::fog_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "a fog");
        st.blocks.open(std::in_place_type<runtime::Fog>);
    }
};
template <>
struct action<g::fog_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& fog = st.blocks.edit<runtime::Fog>(in.position(), name.c_str());
        const auto turbulence = [&]() -> runtime::pattern::Turbulence& {
            if (!fog.turbulence) fog.turbulence.emplace();
            return *fog.turbulence;
        };
        if (name == "distance")
            fog.distance = to_float(v, "distance");
        else if (name == "fog_type") {
            fog.type =
                static_cast<int>(checked_integer(to_constant(v, "fog_type"), "fog_type", 1, 2));
        } else if (name == "fog_alt")
            fog.alt = to_float(v, "fog_alt");
        else if (name == "fog_offset")
            fog.offset = to_float(v, "fog_offset");
        else if (name == "turb_depth")
            fog.turb_depth = to_float(v, "turb_depth");
        else if (name == "up")
            fog.up = to_vector3(v, "up");
        else if (name == "turbulence")
            turbulence().amount = to_vector3(v, "turbulence");
        else if (name == "octaves")
            turbulence().octaves = to_float(v, "octaves");
        else if (name == "omega")
            turbulence().omega = to_float(v, "omega");
        else
            turbulence().lambda = to_float(v, "lambda");
    }
};
template <>
struct action<g::fog_colour> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        auto& fog = st.blocks.edit<runtime::Fog>(in.position(), "a fog's colour");
        // A bare number is the distance, as POV-Ray reads it (with its
        // warning to write `distance`).
        if (v.is<TimeFunction>()) {
            st.warn(in.position(),
                    "a number in fog { } is its distance: write `distance` (as POV-Ray warns)");
            fog.distance = v.as<TimeFunction>();
        } else {
            fog.colour = to_colour(v, "a fog's colour");
        }
    }
};
// ---- rainbow { } (runtime/scene/rainbow.hpp)
template <>
struct action<g::rainbow_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.require_whole_time(in.position(), "a rainbow");
        st.blocks.open(std::in_place_type<runtime::Rainbow>);
    }
};
inline double rainbow_number(const Value& v, const std::string& name) {
    const TimeFunction f = to_float(v, "the rainbow's " + name);
    if (!f.is_constant()) throw ValueError("the rainbow's " + name + " cannot change with clock");
    if (!std::isfinite(f.constant()))
        throw ValueError("the rainbow's " + name + " must be a finite number");
    return f.constant();
}
template <>
struct action<g::rainbow_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& r = st.blocks.edit<runtime::Rainbow>(in.position(), name.c_str());
        if (name == "direction" || name == "up") {
            const runtime::Vector3Function f = to_vector3(v, "the rainbow's " + name);
            glm::dvec3 c;
            for (int i = 0; i < 3; ++i) c[i] = rainbow_number(Value{f.c[i]}, name);
            (name == "up" ? r.up : r.direction) = c;
            return;
        }
        const double x = rainbow_number(v, name);
        if (name == "angle")
            r.angle = x;
        else if (name == "width")
            r.width = x;
        else if (name == "distance")
            r.distance = x;
        else if (name == "jitter")
            r.jitter = x;
        else {
            // (POV-Ray's Parse_Rainbow refuses these outside 0 to 360.)
            if (!(x >= 0.0 && x <= 360.0))
                throw ValueError("the rainbow's " + name + " is 0 to 360 degrees, not " +
                                 std::to_string(x));
            if (name == "arc_angle")
                r.arc_angle = x, r.arc_given = true;
            else
                r.falloff_angle = x, r.falloff_given = true;
        }
    }
};
template <>
struct action<g::rainbow_colour_map> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const Value v = st.values.pop();
        auto& r = st.blocks.edit<runtime::Rainbow>(in.position(), "color_map");
        r.colour_map.clear();
        for (const auto& e : v.as<runtime::ColourMap>().entries) {
            runtime::Rainbow::Entry entry{rainbow_number(Value{e.value}, "color_map's value"), {}};
            for (std::size_t k = 0; k < 5; ++k)
                entry.colour[k] = rainbow_number(Value{e.colour.c[k]}, "color_map's colour");
            r.colour_map.push_back(entry);
        }
    }
};
template <>
struct action<g::rainbow_block> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        auto& r = st.blocks.edit<runtime::Rainbow>(in.position(), "a rainbow");
        if (const std::string problem = r.finish(); !problem.empty()) throw ValueError(problem);
        st.scene.rainbows.push_back(std::move(r));
        st.blocks.close();
    }
};

template <>
struct action<g::fog_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.scene.fogs.push_back(std::move(std::get<runtime::Fog>(st.blocks.top())));
        st.blocks.close();
    }
};

template <>
struct action<g::global_motion_blur> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "a global setting");
        std::vector<Value> items = st.values.close_frame();
        auto& g = st.scene.global;
        g.motion_blur_samples =
            static_cast<int>(checked_integer(to_constant(items.at(0), "motion_blur's samples"),
                                             "motion_blur's samples", 1, 1 << 20));
        g.motion_blur_time = to_constant(items.at(1), "motion_blur's time");
        if (!(*g.motion_blur_time >= 0.0) || !std::isfinite(*g.motion_blur_time))
            throw ValueError(
                "motion_blur's time must be a finite number of clock units, at least 0");
    }
};

template <>
struct action<g::global_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "a global setting");
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        if (name == "assumed_gamma") {
            st.scene.global.assumed_gamma = to_constant(v, name);
            st.assumed_gamma_set = true;
        } else if (name == "noise_generator") {
            st.scene.global.noise_generator =
                static_cast<int>(checked_integer(to_constant(v, name), name, 1, 3));
            if (st.patterns_written > 0)
                st.warn(in.position(),
                        "global noise_generator after patterns: hexant applies it to the patterns "
                        "written after it (POV-Ray to all; put global_settings first)");
        } else if (name == "number_of_waves") {
            // POV-Ray's (int)Parse_Float(), below 1 a warning and 1.
            long long waves = checked_integer(to_constant(v, name), name, -kMaxExactInteger,
                                              runtime::pattern::kMaxNumberOfWaves);
            if (waves < 1) {
                st.warn(in.position(), "number_of_waves " + std::to_string(waves) +
                                           " is below 1: 1 used, as in POV-Ray");
                waves = 1;
            }
            st.scene.global.number_of_waves = static_cast<int>(waves);
            if (st.patterns_written > 0)
                st.warn(in.position(),
                        "global number_of_waves after patterns: hexant applies it to the patterns "
                        "written after it (POV-Ray to all; put global_settings first)");
        } else if (name == "max_trace_level") {
            // As POV-Ray 3.7 (parser.cpp): at least 1, and above its limit
            // of 256 a warning and 256.
            long long level =
                checked_integer(to_constant(v, name), name, -kMaxExactInteger, kMaxExactInteger);
            if (level > 256) {
                st.warn(in.position(), "max_trace_level " + std::to_string(level) +
                                           " is above the limit: 256 used");
                level = 256;
            }
            st.scene.global.max_trace_level = static_cast<int>(std::max(1LL, level));
        } else if (name == "irid_wavelength") {
            const runtime::ColourFunction c = to_colour(v, name);
            glm::dvec3& w = st.scene.global.irid_wavelength;
            for (int k = 0; k < 3; ++k) {
                if (!c.c[k].is_constant())
                    throw ValueError("irid_wavelength must not depend on clock");
                w[k] = c.c[k].constant();
            }
            if (!(w.x != 0.0 && w.y != 0.0 && w.z != 0.0) || !std::isfinite(w.x + w.y + w.z))
                throw ValueError("irid_wavelength's wavelengths must be finite and not 0");
        } else
            st.scene.global.ambient_light = to_colour(v, name);
    }
};
template <>
struct action<g::global_ignored_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.values.close_frame();
        const std::string name = st.values.pop_name();
        // POV-Ray's other global settings are warned (or harmless); any
        // other word is no global setting at all, an error there.
        const KeywordRuleEntry* rule = find_keyword_rule(name);
        if (rule != nullptr && rule->rule == KeywordRule::Warned)
            st.not_rendered(in.position(), name);
        else if (rule == nullptr || rule->rule != KeywordRule::Harmless)
            throw ValueError("'" + name + "' is not a global setting");
    }
};
template <>
struct action<g::unsupported_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.values.push(Value{Unevaluated{st.values.pop_name(), in.position()}});
    }
};

}  // namespace hexant::language
