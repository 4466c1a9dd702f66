#include "app/scene_summary.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace hexant::app {

namespace {

std::string number(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

std::string vector(const glm::dvec3& v) {
    return "<" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ">";
}

// "center, transform depend on time" or "static".
std::string timing(const runtime::ObjectRecord& object) {
    std::vector<std::string> parts = object.timed_parameters();
    if (object.transform.depends_on_time()) parts.push_back("transform");
    if (object.texture_depends_on_time()) parts.push_back("texture");
    if (object.interior && object.interior->ior.depends_on_time()) parts.push_back("ior");
    if (object.limits) {
        const auto moves = [](const auto& list) {
            for (const auto& limit : list)
                if (limit->depends_on_time()) return true;
            return false;
        };
        if (moves(object.limits->clipped_by)) parts.push_back("clipped_by");
        if (moves(object.limits->bounded_by)) parts.push_back("bounded_by");
    }
    std::string s;
    for (const auto& p : parts) s += (s.empty() ? "" : ", ") + p;
    s = parts.empty() ? "static" : s + (parts.size() == 1 ? " depends" : " depend") + " on time";
    if (object.transform.has_deformation()) s += "; deformed";
    if (!object.lifetime.is_always()) s += "; exists " + object.lifetime.to_string();
    return s;
}

}  // namespace

void summarize_scene(const runtime::SceneDescription& scene, std::ostream& out) {
    const auto& a = scene.animation;
    out << "frames " << a.initial_frame << ".." << a.final_frame << ", clock "
        << number(a.time_begin()) << ".." << number(a.time_end()) << (a.cyclic ? " (cyclic)" : "")
        << ", shutter " << number(a.shutter) << (a.shutter_curve.is_box() ? "" : " (shutter curve)")
        << (a.rolling_shutter > 0.0 ? ", rolling shutter " + number(a.rolling_shutter)
                                    : std::string())
        << (a.shutter_position == runtime::ShutterPosition::Centre ? ", centred on each frame"
            : a.shutter_position == runtime::ShutterPosition::End  ? ", ending at each frame"
                                                                   : "")
        << ", " << a.width << "x" << a.height << "\n";
    const auto camera = scene.camera.evaluate(a.time_begin());
    out << "camera at " << vector(camera.location) << " looking along " << vector(camera.direction)
        << (scene.camera.depends_on_time() ? ", moves with time" : ", static") << "\n";
    out << scene.lights.size() << " light" << (scene.lights.size() == 1 ? "" : "s") << "\n";
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        out << "  light " << i << ": " << (scene.lights[i].moves() ? "moves with time" : "static")
            << (scene.lights[i].shadowless ? ", shadowless" : "")
            << (scene.lights[i].lifetime.is_always()
                    ? ""
                    : ", shines " + scene.lights[i].lifetime.to_string())
            << "\n";
    out << scene.objects.size() << " object" << (scene.objects.size() == 1 ? "" : "s") << "\n";
    std::size_t moving = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& object = *scene.objects[i];
        if (object.depends_on_time()) ++moving;
        out << "  object " << i << ": " << runtime::shape_name(object.shape) << " at "
            << object.place.to_string() << ", " << timing(object) << "\n";
    }
    for (const auto& split : scene.time_splits) {
        out << "branch at " << split.where.to_string() << " on clock: ";
        {
            out << "switches at";
            // (Every digit: an instant sits between two neighbouring doubles.)
            char buffer[32];
            for (const double t : split.instants) {
                std::snprintf(buffer, sizeof buffer, "%.17g", t);
                out << " " << buffer;
            }
            out << "\n";
        }
    }
    out << moving << " of " << scene.objects.size() << " objects depend on time";
    if (!scene.warnings.empty()) out << "; " << scene.warnings.size() << " warning(s)";
    out << "\n";
}

}  // namespace hexant::app
