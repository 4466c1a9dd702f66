// Every pattern hexant has: its name, value function and POV-Ray 3.7's
// defaults for it (the default colour maps of pigment.cpp, the wave and
// parameters Parse_Pattern sets). One line a kind.
#include <algorithm>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

namespace {

using A = Kind::Argument;

// POV-Ray's default colour maps (pigment.cpp).
const std::vector<MapEntry> kGray = {{0.0, {0, 0, 0, 0, 0}}, {1.0, {1, 1, 1, 0, 0}}};
const std::vector<MapEntry> kBozo = {{0.4, {1, 1, 1, 0, 0}}, {0.4, {0, 1, 0, 0, 0}}, {0.6, {0, 1, 0, 0, 0}},
                                     {0.6, {0, 0, 1, 0, 0}}, {0.8, {0, 0, 1, 0, 0}}, {0.8, {1, 0, 0, 0, 0}}};
const std::vector<MapEntry> kWood = {{0.6, {0.666, 0.312, 0.2, 0, 0}}, {0.6, {0.4, 0.1333, 0.066, 0, 0}}};
const std::vector<MapEntry> kMandel = {{0.001, {0, 0, 0, 0, 0}}, {0.001, {0, 1, 1, 0, 0}}, {0.012, {1, 1, 0, 0, 0}},
                                       {0.015, {1, 0, 1, 0, 0}}, {0.1, {0, 1, 1, 0, 0}}};
const std::vector<MapEntry> kAgate = {{0.0, {1, 1, 1, 0, 0}},      {0.5, {0.95, 0.75, 0.5, 0, 0}},
                                      {0.5, {0.9, 0.7, 0.5, 0, 0}}, {0.6, {0.9, 0.7, 0.4, 0, 0}},
                                      {0.6, {1, 0.7, 0.4, 0, 0}},   {1.0, {0.6, 0.3, 0, 0, 0}}};
const std::vector<MapEntry> kRadial = {{0.0, {0, 1, 1, 0, 0}}, {0.333, {1, 1, 0, 0, 0}},
                                       {0.666, {1, 0, 1, 0, 0}}, {1.0, {0, 1, 1, 0, 0}}};
const std::vector<MapEntry> kMarble = {{0.0, {0.9, 0.8, 0.8, 0, 0}}, {0.9, {0.9, 0.08, 0.08, 0, 0}},
                                       {0.9, {0, 0, 0, 0, 0}}};
const std::vector<MapEntry> kBrick = {{0.0, {0.5, 0.5, 0.5, 0, 0}}, {1.0, {0.6, 0.15, 0.15, 0, 0}}};
const std::vector<MapEntry> kHexagon = {{0.0, {0, 0, 1, 0, 0}}, {1.0, {0, 1, 0, 0, 0}}, {2.0, {1, 0, 0, 0, 0}}};
// (POV-Ray's checker default reads the hexagon's first two entries.)
const std::vector<MapEntry> kChecker = {{0.0, {0, 0, 1, 0, 0}}, {1.0, {0, 1, 0, 0, 0}}};

// Brick's default mortar: 0.5 - 2 EPSILON.
constexpr double kMortar = 0.5 - 2.0e-10;

const std::vector<Kind>& kinds() {
    // Sorted by name (find_kind searches them).
    static const std::vector<Kind> all = {
        {"agate", agate_value, A::None, 0, Wave::Ramp, true, false, kAgate, {1.0, 0.0}},
        {"boxed", boxed_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"bozo", noise_value, A::None, 0, Wave::Ramp, true, false, kBozo},
        {"brick", brick_value, A::Colours, 2, Wave::Ramp, false, false, kBrick, {kMortar, 0.0}, {8.0, 3.0, 4.5}},
        {"bumps", noise_value, A::None, 0, Wave::Ramp, true, false, kGray, {}, {}, bumps_normal},
        {"cells", cells_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"checker", checker_value, A::Colours, 2, Wave::Ramp, false, false, kChecker},
        {"crackle", crackle_value, A::None, 0, Wave::Ramp, true, false, kGray, {2.0, 0.0}, {-1.0, 1.0, 0.0}, nullptr,
         false},
        {"cylindrical", cylindrical_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"dents", dents_value, A::None, 0, Wave::Ramp, true, false, kGray, {}, {}, dents_normal},
        {"gradient", gradient_value, A::Vector, 0, Wave::Ramp, true, false, kGray},
        {"granite", granite_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"hexagon", hexagon_value, A::Colours, 3, Wave::Ramp, false, false, kHexagon},
        {"leopard", leopard_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"mandel", mandel_value, A::Number, 0, Wave::Ramp, true, false, kMandel},
        {"marble", marble_value, A::None, 0, Wave::Triangle, true, true, kMarble},
        {"onion", onion_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"planar", planar_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"quilted", quilted_value, A::None, 0, Wave::Ramp, false, false, kGray, {1.0, 1.0}, {}, quilted_normal},
        {"radial", radial_value, A::None, 0, Wave::Ramp, true, false, kRadial},
        {"ripples", ripples_value, A::None, 0, Wave::Ramp, true, false, kGray, {}, {}, ripples_normal},
        {"spherical", spherical_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"spiral1", spiral1_value, A::Number, 0, Wave::Triangle, true, false, kGray},
        {"spiral2", spiral2_value, A::Number, 0, Wave::Triangle, true, false, kGray},
        {"spotted", noise_value, A::None, 0, Wave::Ramp, true, false, kGray},
        {"waves", waves_value, A::None, 0, Wave::Ramp, true, false, kGray, {}, {}, waves_normal},
        {"wood", wood_value, A::None, 0, Wave::Triangle, true, true, kWood},
        {"wrinkles", wrinkles_value, A::None, 0, Wave::Ramp, true, false, kGray, {}, {}, wrinkles_normal},
    };
    return all;
}

}  // namespace

const Kind* find_kind(std::string_view name) {
    const auto& all = kinds();
    const auto it = std::lower_bound(all.begin(), all.end(), name,
                                     [](const Kind& k, std::string_view n) { return k.name < n; });
    return it != all.end() && it->name == name ? &*it : nullptr;
}

const std::vector<const Kind*>& all_kinds() {
    static const std::vector<const Kind*> list = [] {
        std::vector<const Kind*> out;
        for (const Kind& k : kinds()) out.push_back(&k);
        return out;
    }();
    return list;
}

}  // namespace hexant::runtime::pattern
