#include "app/scene_dump.hpp"

#include <cstdio>
#include <map>
#include <string>

namespace hexant::app {

namespace {

using runtime::TimeFunction;

std::string number(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", v == 0.0 ? 0.0 : v);  // no "-0"
    return buffer;
}

std::string vector(const runtime::Vector3Function& v, double t) {
    return "<" + number(v.c[0](t)) + ", " + number(v.c[1](t)) + ", " + number(v.c[2](t)) + ">";
}
std::string vector(const glm::dvec3& v) {
    return "<" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ">";
}
std::string colour(const runtime::ColourFunction& c, double t) {
    std::string s = "<";
    for (int i = 0; i < 5; ++i) s += (i ? ", " : "") + number(c.c[i](t));
    return s + ">";
}

std::string transform(const runtime::Transform& transform, double t) {
    if (!transform.has_deformation()) {
        const glm::dmat4 m = transform.matrix_at(t);
        std::string s = "[";
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) s += (i || j ? ", " : "") + number(m[i][j]);
        return "transform=" + s + "]";
    }
    // With a deformation there is no one matrix: each step as written.
    static const char* names[] = {"translate", "rotate", "scale", "matrix",
                                  "twist",     "taper",  "bend"};
    std::string s = "steps=";
    bool first = true;
    for (const auto& step : transform.steps()) {
        s += std::string(first ? "" : ";") + names[static_cast<int>(step.kind)] +
             (step.inverse ? "^-1" : "") + "(";
        first = false;
        if (step.kind == runtime::TransformKind::Matrix) {
            s += "[";
            for (int i = 0; i < 12; ++i) s += (i ? ", " : "") + number(step.matrix[i](t));
            s += "]";
        } else if (step.is_deformation()) {
            s += "axis=" + vector(step.vector, t) + ",amount=" + number(step.amount(t));
        } else {
            s += vector(step.vector, t);
        }
        s += ")";
    }
    return s;
}

// A pattern's modifiers at t: frequency, phase, turbulence, its warps
// (turbulence amounts) and transforms counted.
std::string modifiers(const runtime::pattern::Pattern& p, double t) {
    std::string s = " frequency=" + number(p.frequency(t)) + " phase=" + number(p.phase(t));
    if (p.turbulence)
        s += " turbulence=<" + number(p.turbulence->amount.c[0](t)) + ", " +
             number(p.turbulence->amount.c[1](t)) + ", " + number(p.turbulence->amount.c[2](t)) +
             ">";
    if (!p.warps.empty()) s += " warps=" + std::to_string(p.warps.size());
    return s;
}

// The map entries of one line: a declared graph of maps may use one entry
// many times (T1 a checker of T0 and T0 scaled, T2 of T1 ...), exponential
// printed as a tree. An entry used more than once is printed in full the
// first time, as `[#k ...]`, and as `[#k]` after.
class Shared {
  public:
    // Counts the uses of every entry under a texture, pigment or normal
    // (each entry's own entries once).
    void count(const runtime::Texture& x) {
        count(x.pigment);
        if (x.normal) count(*x.normal);
        for (const auto& layer : x.below) count(layer);
        for (const auto& e : x.texture_map)
            if (++uses_[e.texture.get()] == 1) count(*e.texture);
    }
    void count(const runtime::Pigment& p) {
        for (const auto& e : p.pigment_map)
            if (++uses_[e.pigment.get()] == 1) count(*e.pigment);
    }
    void count(const runtime::Normal& n) {
        for (const auto& e : n.normal_map)
            if (++uses_[e.normal.get()] == 1) count(*e.normal);
    }
    template <class Print>
    std::string entry(const void* record, Print print) {
        if (uses_[record] < 2) return "[" + print() + "]";
        const auto [it, first] = labels_.try_emplace(record, static_cast<int>(labels_.size()) + 1);
        const std::string label = "#" + std::to_string(it->second);
        return first ? "[" + label + " " + print() + "]" : "[" + label + "]";
    }

  private:
    std::map<const void*, int> uses_, labels_;
};

// " uv_mapping" where it is on (nothing otherwise: dumps without it stay as they were).
std::string uv_word(runtime::UvMapping m) {
    return m == runtime::UvMapping::Off ? "" : " uv_mapping";
}

std::string pigment_body(const runtime::Pigment& p, double t, Shared& shared);
std::string pigment(const runtime::Pigment& p, double t, Shared& shared) {
    return pigment_body(p, t, shared) + uv_word(p.uv_mapping);
}

std::string pigment_body(const runtime::Pigment& p, double t, Shared& shared) {
    switch (p.pattern) {
        case runtime::Pigment::Pattern::Solid:
            return "solid" + colour(p.colours[0], t);
        case runtime::Pigment::Pattern::Patterned: {
            // The kind, its modifiers, then its map's entries at t (value and
            // colour, or value and pigment).
            std::string s = std::string(p.patterned->kind->name) + modifiers(p.patterned, t);
            for (const auto& e : p.colour_map.entries)
                s += " " + number(e.value(t)) + colour(e.colour, t);
            for (const auto& e : p.pigment_map)
                s += " " + number(e.value(t)) +
                     shared.entry(e.pigment.get(), [&] { return pigment(*e.pigment, t, shared); });
            return s;
        }
        case runtime::Pigment::Pattern::Image:
            return "image_map file=" + p.image_map->file +
                   " map_type=" + std::to_string(static_cast<int>(p.image_map->map_type)) +
                   " interpolate=" + std::to_string(static_cast<int>(p.image_map->interpolate)) +
                   " once=" + std::to_string(p.image_map->once ? 1 : 0) + modifiers(p.patterned, t);
        case runtime::Pigment::Pattern::Unsupported:
            return p.unsupported_name;
    }
    return "";
}

std::string normal(const runtime::Normal& n, double t, Shared& shared) {
    if (!n.unsupported_name.empty()) return n.unsupported_name;
    if (n.bump_map)
        return "bump_map file=" + n.bump_map->file + " amount=" + number(n.amount(t)) +
               modifiers(n.patterned, t);
    std::string s = std::string(n.patterned->kind->name) + " amount=" + number(n.amount(t)) +
                    modifiers(n.patterned, t);
    // A normal map's entries (value and normal), a slope map's (value,
    // height, slope).
    for (const auto& e : n.normal_map)
        s += " " + number(e.value(t)) +
             shared.entry(e.normal.get(), [&] { return normal(*e.normal, t, shared); });
    for (const auto& e : n.slope_map)
        s += " " + number(e.value(t)) + "<" + number(e.height(t)) + ", " + number(e.slope(t)) + ">";
    return s + uv_word(n.uv_mapping);
}

std::string layer(const runtime::Texture& texture, double t, Shared& shared);

// A texture at t: its one layer, or its layers top first, or its pattern
// and texture map.
std::string texture(const runtime::Texture& x, double t, Shared& shared) {
    if (x.is_patterned()) {
        // The pattern, then its map's entries (value and texture).
        std::string s =
            "texture_map=" + std::string(x.patterned->kind->name) + modifiers(x.patterned, t);
        for (const auto& e : x.texture_map)
            s += " " + number(e.value(t)) +
                 shared.entry(e.texture.get(), [&] { return texture(*e.texture, t, shared); });
        return s + uv_word(x.uv_mapping);
    }
    std::string s = layer(x, t, shared);
    // The layers under it, top first (Texture::below is bottom first).
    for (auto it = x.below.rbegin(); it != x.below.rend(); ++it)
        s += " under [" + layer(*it, t, shared) + "]";
    return s;
}

// A plain texture's pigment, normal and finish at t.
std::string layer(const runtime::Texture& texture, double t, Shared& shared) {
    std::string s = "pigment=" + pigment(texture.pigment, t, shared);
    if (texture.normal) s += " normal=" + normal(*texture.normal, t, shared);
    const runtime::Finish& f = texture.finish;
    // (ambient: a number when grey, else its colour)
    const double a[3] = {f.ambient[0](t), f.ambient[1](t), f.ambient[2](t)};
    const std::string ambient =
        a[0] == a[1] && a[1] == a[2]
            ? number(a[0])
            : "<" + number(a[0]) + ", " + number(a[1]) + ", " + number(a[2]) + ">";
    s += " finish=ambient:" + ambient + ",diffuse:" + number(f.diffuse(t)) +
         ",brilliance:" + number(f.brilliance(t)) + ",phong:" + number(f.phong(t)) +
         ",phong_size:" + number(f.phong_size(t)) + ",specular:" + number(f.specular(t)) +
         ",roughness:" + number(f.roughness(t)) + ",reflection:<" + number(f.reflection.c[0](t)) +
         ", " + number(f.reflection.c[1](t)) + ", " + number(f.reflection.c[2](t)) + ">";
    return s + uv_word(texture.uv_mapping);
}

// "sphere center=<...> radius=..." at t: the kind's keyword and its
// parameters (runtime/objects/shape_kind.hpp); a CSG's kind and child count.
struct ShapeWriter {
    double t;
    std::string out;

    void operator()(const char* name, const char*, const runtime::TimeFunction& f) {
        out += std::string(" ") + name + "=" + number(f(t));
    }
    void operator()(const char* name, const char*, const runtime::Vector3Function& v) {
        out += std::string(" ") + name + "=" + vector(v, t);
    }
    void operator()(const char* name, const char*, const runtime::Vector2Function& v) {
        out += std::string(" ") + name + "=" + vector2(v);
    }
    template <typename T>
    void operator()(const char* name, const char*, const std::vector<T>& items) {
        out += std::string(" ") + name + "=";
        for (std::size_t i = 0; i < items.size(); ++i) {
            ShapeWriter item{t, {}};
            item("", "", items[i]);
            out += (i ? ";" : "") + item.out.substr(2);  // without " ="
        }
    }
    // (A blob component's own transforms: its matrix, "[m00, .., m32]".)
    void operator()(const char* name, const char*, const runtime::Transform& x) {
        const std::string s = transform(x, t);
        out += std::string(" ") + name + "=" + s.substr(s.find('=') + 1);
    }
    void operator()(const char* name, const char*, bool on) {
        out += std::string(" ") + name + "=" + (on ? "1" : "0");
    }
    void operator()(const char* name, const char*, const std::string& text) {
        out += std::string(" ") + name + "=\"" + text + "\"";
    }
    void operator()(const char* name, const char*, const runtime::objects::DescribedParameter& p) {
        out += std::string(" ") + name + "=" + p.text;
    }

    std::string vector2(const runtime::Vector2Function& v) const {
        return "<" + number(v.c[0](t)) + ", " + number(v.c[1](t)) + ">";
    }

    static std::string write(const runtime::Shape& shape, double t) {
        if (const auto* c = std::get_if<runtime::Csg>(&shape))
            return std::string(runtime::shape_name(shape)) +
                   " children=" + std::to_string(c->children.size());
        ShapeWriter writer{t, runtime::shape_name(shape)};
        runtime::for_each_parameter(shape, writer);
        return writer.out;
    }
};

// An object and its CSG children, depth first, with a stack of its own:
// records nest up to runtime::kMaxObjectDepth deep, more than the thread's
// stack holds frames of this.
void dump_object(const runtime::ObjectRecord& top, const std::string& top_name, double t,
                 std::ostream& out) {
    std::vector<std::pair<const runtime::ObjectRecord*, std::string>> pending{{&top, top_name}};
    while (!pending.empty()) {
        const auto [object, name] = std::move(pending.back());
        pending.pop_back();
        // What exists at t only (runtime::Lifetime).
        if (!object->lifetime.contains(t)) continue;
        out << name << " " << ShapeWriter::write(object->shape, t) << " "
            << transform(object->transform, t);
        if (object->texture) {
            Shared shared;
            shared.count(*object->texture);
            out << " " << texture(*object->texture, t, shared);
        }
        if (object->interior) out << " ior=" << number(object->interior->ior(t));
        out << " no_shadow=" << object->no_shadow << " hollow=" << object->hollow
            << " inverse=" << object->inverse << "\n";
        if (const auto* csg = std::get_if<runtime::Csg>(&object->shape))
            for (std::size_t i = csg->children.size(); i-- > 0;)
                pending.emplace_back(csg->children[i].get(), name.substr(0, name.size() - 1) + "." +
                                                                 std::to_string(i) + "]");
    }
}

}  // namespace

void dump_scene(const runtime::SceneDescription& scene, double t, std::ostream& out) {
    const runtime::CameraFrame camera = scene.camera.evaluate(t);
    out << "camera location=" << vector(camera.location)
        << " direction=" << vector(camera.direction) << " right=" << vector(camera.right)
        << " up=" << vector(camera.up) << " sky=" << vector(camera.sky);
    // (Only what differs from a perspective pinhole, so that the usual
    // camera's line stays as it was.)
    switch (camera.type) {
        case runtime::CameraType::Perspective:
            break;
        case runtime::CameraType::Orthographic:
            out << " orthographic";
            break;
        case runtime::CameraType::Fisheye:
            out << " fisheye angle=" << number(camera.angle);
            break;
        case runtime::CameraType::Panoramic:
            out << " panoramic";
            break;
        case runtime::CameraType::Spherical:
            out << " spherical angle=" << number(camera.h_angle) << "," << number(camera.v_angle);
            break;
        case runtime::CameraType::UltraWideAngle:
            out << " ultra_wide_angle angle=" << number(camera.angle);
            break;
        case runtime::CameraType::Omnimax:
            out << " omnimax";
            break;
        case runtime::CameraType::Mesh:
            out << " mesh_camera rays=" << camera.mesh->rays_per_pixel()
                << " distribution=" << camera.mesh->distribution()
                << " meshes=" << camera.mesh->meshes().size();
            break;
        case runtime::CameraType::Cylinder1:
        case runtime::CameraType::Cylinder2:
        case runtime::CameraType::Cylinder3:
        case runtime::CameraType::Cylinder4:
            out << " cylinder " << 1 + int(camera.type) - int(runtime::CameraType::Cylinder1)
                << " angle=" << number(camera.angle);
            break;
    }
    if (camera.aperture != 0.0)
        out << " aperture=" << number(camera.aperture)
            << " focal_distance=" << number(camera.focal_distance);
    out << "\n";
    if (scene.camera.normal) {
        Shared shared;
        shared.count(*scene.camera.normal);
        out << "camera normal=" << normal(*scene.camera.normal, t, shared) << "\n";
    }
    out << "background colour=" << colour(scene.background, t) << "\n";
    if (scene.sky_sphere) {
        out << "sky_sphere emission=" << colour(scene.sky_sphere->emission, t);
        for (const auto& p : scene.sky_sphere->pigments) {
            Shared shared;
            shared.count(p);
            out << " pigment=" << pigment(p, t, shared);
        }
        out << "\n";
    }
    for (const auto& fog : scene.fogs)
        out << "fog type=" << fog.type << " distance=" << number(fog.distance(t))
            << " colour=" << colour(fog.colour, t) << "\n";
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const auto& light = scene.lights[i];
        if (!light.lifetime.contains(t)) continue;
        const glm::dvec4 p =
            light.transform.has_deformation()
                ? glm::dvec4(light.position(t), 1.0)
                : light.transform.matrix_at(t) * glm::dvec4(light.position(t), 1.0);
        out << "light[" << i << "] position=" << vector(glm::dvec3(p))
            << " colour=" << colour(light.colour, t) << " shadowless=" << light.shadowless;
        // (point_at a point, the area's axes directions, in the world: the
        // light's transform applied, as to its position.)
        const glm::dmat4 m =
            light.transform.has_deformation() ? glm::dmat4(1.0) : light.transform.matrix_at(t);
        const auto vec3 = [&](const runtime::Vector3Function& v, double w) {
            const glm::dvec4 q = m * glm::dvec4(v.c[0](t), v.c[1](t), v.c[2](t), w);
            return "<" + number(q.x) + ", " + number(q.y) + ", " + number(q.z) + ">";
        };
        if (light.kind != runtime::LightKind::Point)
            out << (light.kind == runtime::LightKind::Spotlight ? " spotlight" : " cylinder")
                << " radius=" << number(light.radius(t)) << " falloff=" << number(light.falloff(t))
                << " tightness=" << number(light.tightness(t));
        if (light.parallel) out << " parallel";
        if (light.parallel || light.kind != runtime::LightKind::Point)
            out << " point_at=" << vec3(light.point_at, 1.0);
        if (light.fade_power(t) > 0.0)
            out << " fade_distance=" << number(light.fade_distance(t))
                << " fade_power=" << number(light.fade_power(t));
        if (light.area)
            out << " area_light=" << vec3(light.area->axis1, 0.0) << ", "
                << vec3(light.area->axis2, 0.0) << ", " << light.area->size1 << ", "
                << light.area->size2 << (light.jitter ? " jitter" : "")
                << (light.circular ? " circular" : "") << (light.orient ? " orient" : "");
        out << "\n";
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        dump_object(*scene.objects[i], "object[" + std::to_string(i) + "]", t, out);
}

}  // namespace hexant::app
