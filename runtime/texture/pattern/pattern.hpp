// POV-Ray's patterns: a function from a point in pattern space to a number
// (mostly in [0, 1]) that a colour map turns into a colour. Each kind is
// one file under kinds/ (pattern_kind.hpp says what it declares), listed
// once in kinds.hpp; kinds of one family share their helpers' files
// (noise_patterns.cpp, shape_patterns.cpp, block_patterns.cpp,
// fractal_patterns.cpp, crackle.cpp, normal_patterns.cpp). The pipeline around the kind's function
// is POV-Ray 3.7's (Compute_Pigment, Warp_EPoint, Evaluate_TPat in its sources):
//
//   world point -> the pattern's transforms and warps, inverted, last
//   written first -> classic turbulence (unless the kind reads it itself)
//   -> the kind's value -> frequency and phase (fmod by 1.00001) -> wave
//   shape -> the colour map.
//
// Every parameter may be a function of time; a Pattern holds them as the
// scene wrote them, Values holds them at one instant.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/motion/transform.hpp"
#include "runtime/texture/pattern/noise.hpp"
#include "runtime/texture/pattern/warps/point_warp.hpp"
#include "runtime/time/user_function.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {
struct Pigment;
}

namespace hexant::runtime::pattern {

class DensityFile;  // density_file.hpp
struct ImageMap;    // image_map.hpp

enum class Wave { Ramp, Sine, Triangle, Scallop, Cubic, Poly };

// turbulence <x, y, z> with its octaves, omega and lambda.
struct Turbulence {
    Vector3Function amount{{0.0, 0.0, 0.0}};
    TimeFunction octaves = 6.0;
    TimeFunction omega = 0.5;
    TimeFunction lambda = 2.0;
    bool depends_on_time() const;
};

// One step of a pattern's warp list, in the order written: a transform
// (consecutive ones composed), a `warp { turbulence ... }` or one of the
// other warps (repeat, black_hole, the mapping warps: warps/point_warp.hpp).
struct Warp {
    std::optional<Transform> transform;  // else turbulence, or `point`
    Turbulence turbulence;
    std::optional<PointWarp> point;
};

// What a pattern may read besides its point (POV-Ray's Intersection): the
// surface event being shaded. `normal` is POV-Ray's PNormal: the shading
// normal facing the viewer, as the latest normal { } of the texture being
// evaluated left it (unit, in the space around that normal); `point` the
// world point, `uv` the surface's (u, v), `t` the time. No surface (a sky's
// pigment): POV-Ray's null Intersection.
struct Hit {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};
    glm::dvec2 uv{0.0};
    double t = 0.0;
    bool surface = false;
};

// A pigment a pattern reads (pigment_pattern): its colour (r, g, b,
// filter, transmit) at a point in the pattern's space, at `hit`.
class PigmentSource {
  public:
    virtual std::array<double, 5> colour_at(const glm::dvec3& point, const Hit& hit) const = 0;

  protected:
    ~PigmentSource() = default;
};

// The parameters of one instant, as a kind's function reads them.
// waves' and ripples' wave sources: POV-Ray's default number_of_waves, and
// the most hexant computes (POV-Ray sets none).
inline constexpr int kDefaultNumberOfWaves = 10;
inline constexpr int kMaxNumberOfWaves = 1000;

struct Values {
    glm::dvec3 vector{0.0};          // gradient's direction, brick_size
    std::array<double, 2> number{};  // mortar, arms, iterations, control0/1, agate_turb
    // A kind with a block of its own (slope): a second vector, more numbers.
    glm::dvec3 vector2{0.0};
    std::array<double, 4> more{};
    // The surface (slope) and the pigment (pigment_pattern) a kind may
    // read: set for each evaluation, null where there is none.
    const Hit* hit = nullptr;
    const PigmentSource* pigment = nullptr;
    // The function pattern's function of (x, y, z) and time.
    const SpaceFunction* function = nullptr;
    // The density_file pattern's voxels (density_file.hpp).
    const DensityFile* density_file = nullptr;
    // The material_map's image (image_map.hpp).
    const ImageMap* image = nullptr;
    bool has_turbulence = false;  // classic turbulence given
    glm::dvec3 turbulence{0.0};
    Octaves octaves;
    double frequency = 1.0;
    double phase = 0.0;
    int noise_generator = kDefaultNoiseGenerator;
    int number_of_waves = kDefaultNumberOfWaves;
};

using Function = double (*)(const glm::dvec3& point, const Values& values);
// A normal-only pattern's perturbation (bumps, dents, ripples, waves,
// wrinkles, quilted in a normal { }): `normal` (pattern space) plus its
// bump of size `amount` at `point` (POV-Ray's normal.cpp).
using NormalFunction = glm::dvec3 (*)(const glm::dvec3& point, const Values& values, double amount,
                                      const glm::dvec3& normal);

// A colour map's entry: at `value`, this colour (r, g, b, filter, transmit).
struct MapEntry {
    double value;
    std::array<double, 5> colour;
};

// A kind's own modifier (POV-Ray's Parse_Pattern: brick's mortar,
// crackle's metric, a fractal's exterior): its word, what it takes, where
// its value goes and its default. A Number or a Pair's first number goes to
// Values::number[slot], or from kMoreSlot on to Values::more[slot -
// kMoreSlot]; a Pair (`exterior TYPE, FACTOR`) fills slot and slot + 1; a
// Vector goes to Values::vector. Its value may move with clock unless it is
// `constant`. An `integer` one is truncated as POV-Ray's (int) casts and
// must lie in [low, high]: outside, an error, or (`warns`) POV-Ray's
// warning and the default.
struct Setting {
    enum class Type { Number, Vector, Pair, Flag };
    static constexpr int kMoreSlot = 2;
    std::string_view name;
    Type type = Type::Number;
    int slot = 0;
    double number = 0.0;
    std::array<double, 3> vector{};
    bool constant = false;
    double second = 0.0;  // a Pair's second number's default
    bool integer = false;
    int low = 0, high = 0;
    bool warns = false;

    static constexpr Setting of_number(std::string_view name, int slot, double default_value) {
        return {name, Type::Number, slot, default_value, {}, false};
    }
    static constexpr Setting of_vector(std::string_view name, std::array<double, 3> default_value) {
        return {name, Type::Vector, 0, 0.0, default_value, false};
    }
    // A word alone (crackle's solid): its slot 1 when written, else 0.
    static constexpr Setting of_flag(std::string_view name, int slot) {
        return {name, Type::Flag, slot, 0.0, {}, true};
    }
    // A constant whole number in [low, high] (a fractal's exponent).
    static constexpr Setting of_integer(std::string_view name, int slot, double default_value,
                                        int low, int high, bool warns) {
        return {name, Type::Number, slot, default_value, {}, true, 0.0, true, low, high, warns};
    }
    // A constant whole number in [low, high] and a number (moving with
    // clock if written so) after it.
    static constexpr Setting of_pair(std::string_view name, int slot, double first, double second,
                                     int low, int high) {
        return {name, Type::Pair, slot, first, {}, true, second, true, low, high, false};
    }
};

// A pattern kind as the texture evaluator reads it: made from its file
// under kinds/ (pattern_kind.hpp, make_kind).
struct Kind {
    std::string_view name;
    Function value;
    // What follows the name: nothing, a vector (gradient), a number
    // (spiral1's arms, mandel's iterations), a point and a number (julia's
    // <cr, ci>, iterations), a list of colours (the
    // block patterns: checker and brick 2, hexagon 3; their values are the
    // index of a colour, POV-Ray's blend list), or a syntax of its own that
    // the grammar reads by its own rule (slope, pigment_pattern, magnet).
    enum class Argument {
        None,
        Vector,
        Number,
        PointNumber,
        Colours,
        Own
    } argument = Argument::None;
    int colours = 0;
    Wave wave = Wave::Ramp;
    bool frequency = true;        // false: frequency 0 (block patterns, quilted)
    bool own_turbulence = false;  // marble, wood: read classic turbulence themselves
    std::vector<MapEntry> default_map;
    // Its own modifiers, and its numbers' defaults (Values::number) and
    // vector's (brick_size), the settings' defaults among them.
    std::vector<Setting> settings;
    std::array<double, 2> number{};
    std::array<double, 4> more{};
    glm::dvec3 vector{0.0};
    // In a normal { }: its own perturbation, else the slope of its value.
    NormalFunction normal = nullptr;
    // POV-Ray keeps the kinds' numbers in single precision, but crackle's
    // metric and offset in double.
    bool single_numbers = true;
    // average: no value of its own; its map's entries are averaged by
    // their weights (POV-Ray's AVERAGE_PATTERN).
    bool average = false;
};

// The kind named `name`, or null.
const Kind* find_kind(std::string_view name);
// The setting `name` of `kind`, or null.
const Setting* find_setting(const Kind& kind, std::string_view name);
// Every kind, by name.
const std::vector<const Kind*>& all_kinds();

// A pattern as the scene wrote it.
struct Pattern {
    const Kind* kind = nullptr;
    Vector3Function vector;
    std::array<TimeFunction, 2> number{};
    std::optional<Turbulence> turbulence;  // classic
    TimeFunction frequency = 1.0;
    TimeFunction phase = 0.0;
    Wave wave = Wave::Ramp;
    TimeFunction exponent = 1.0;  // poly_wave
    int noise_generator = 0;      // 0: the scene's
    int number_of_waves = 0;      // waves' and ripples' sources (0: POV-Ray's 10)
    std::vector<Warp> warps;      // before the last transforms (Pigment::transform)
    // A kind with a block of its own: slope's altitude and its numbers.
    Vector3Function vector2;
    std::array<TimeFunction, 4> more{};
    // pigment_pattern's pigment (its value is the pigment's grey).
    std::shared_ptr<const Pigment> pigment;
    // The function pattern's function.
    std::shared_ptr<const SpaceFunction> function;
    // The density_file pattern's voxels.
    std::shared_ptr<const DensityFile> density_file;
    // The material_map's image.
    std::shared_ptr<const ImageMap> image;

    // A pattern of `kind` with its defaults.
    static Pattern of(const Kind& kind);
    bool depends_on_time() const;
};

// The colour map of a pattern written without one (its kind's, as
// POV-Ray's Post_Pigment picks it).
const std::vector<MapEntry>& default_map(const Pattern& pattern);

// The value at a point already in pattern space (after warps and classic
// turbulence), through frequency, phase and the wave (Evaluate_TPat).
double evaluate(const Kind& kind, const glm::dvec3& point, const Values& values, Wave wave,
                double exponent);

// A normal perturbed by the slope of the pattern's value (POV-Ray's
// Perturb_Normal for patterns without a normal function of their own): the
// value at four points `delta` from `point` along a tetrahedron's
// directions, weighted by amount * -5 * 0.02 / delta. `normal` and the
// result are in pattern space.
// With a slope map, each value goes through it first.
struct SlopeEntry;
glm::dvec3 slope_normal(const Kind& kind, const glm::dvec3& point, const Values& values, Wave wave,
                        double exponent, double amount, double delta, const glm::dvec3& normal,
                        const std::vector<SlopeEntry>* slope_map = nullptr);

// A slope_map's entry: at `value` (single precision, as POV-Ray keeps a
// map's values), a height and a slope.
struct SlopeEntry {
    double value, height, slope;
};
// A value through a slope map (POV-Ray's Do_Slope_Map: the Hermite cubic
// between the neighbouring entries' heights and slopes; the entry's height
// at or beyond the ends).
double slope_map_value(const std::vector<SlopeEntry>& map, double value);

// Classic turbulence applied to a point, as Warp_EPoint does it.
glm::dvec3 apply_turbulence(const glm::dvec3& point, const glm::dvec3& amount, const Octaves& o);

// POV-Ray's Search_Blend_Map over `count` entries whose values, in order,
// value_at(i) gives: below the first entry, above the last or on an
// entry's value, prev == cur; else cur is the first entry above `value`,
// prev the one before, and f (in (0, 1)) how far value lies from prev to
// cur. Values are read as the search goes (a time-varying map is not
// copied).
struct BlendPick {
    std::size_t prev = 0, cur = 0;
    double f = 1.0;
};
template <class ValueAt>
BlendPick search_blend_map(double value, std::size_t count, ValueAt value_at) {
    BlendPick pick;
    if (count == 0) return pick;
    double at_cur;
    if (value >= (at_cur = value_at(count - 1))) {
        pick.prev = pick.cur = count - 1;
    } else {
        double at_prev = at_cur = value_at(0);
        while (value > at_cur) {
            pick.prev = pick.cur++;
            at_prev = at_cur;
            at_cur = value_at(pick.cur);
        }
        if (value != at_cur && pick.prev != pick.cur)
            pick.f = (value - at_prev) / (at_cur - at_prev);
    }
    if (value == at_cur) pick.prev = pick.cur;
    return pick;
}

// The colour a map gives a value (Search_Blend_Map and the linear blend
// between its neighbouring entries; below the first, the first; above the
// last, the last).
std::array<double, 5> map_colour(const std::vector<MapEntry>& map, double value);

}  // namespace hexant::runtime::pattern
