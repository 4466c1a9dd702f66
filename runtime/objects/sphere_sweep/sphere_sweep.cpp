#include "runtime/objects/sphere_sweep/sphere_sweep.hpp"

#include <string>

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Sphere_Sweep (parse.cpp): exactly one spline word
// (its absence is "Invalid type of interpolation."); the count is truncated
// to an integer and must be at least 2 (linear_spline) or 4 (b_spline,
// cubic_spline), else "Too few modeling spheres for interpolation type.";
// then the centres and radii in turn. Radii are not checked (POV-Ray
// squares them: a negative radius is the positive one).
SphereSweep SphereSweep::read(const objects::ShapeArguments& a) {
    using geometry::SweepSpline;
    SphereSweep sweep;
    const auto& words = a.options();
    if (words.empty())
        a.fail(
            "sphere_sweep needs its type of interpolation first (linear_spline, b_spline or "
            "cubic_spline): Invalid type of interpolation.");
    if (words.size() > 1)
        a.fail("sphere_sweep takes one type of interpolation, but '" + words[0] + "' and '" +
               words[1] + "' were given");
    const std::string& word = words.front();
    if (word == "linear_spline")
        sweep.spline = SweepSpline::linear;
    else if (word == "b_spline")
        sweep.spline = SweepSpline::b_spline;
    else if (word == "cubic_spline")
        sweep.spline = SweepSpline::cubic;
    else
        a.fail("sphere_sweep takes no '" + word + "'");

    if (a.size() < 1) a.need(1, 1, "a sphere count and the spheres");
    const long long n = a.count(0, "sphere_sweep's sphere count", -100'000'000, 100'000'000);
    const long long least = sweep.spline == SweepSpline::linear ? 2 : 4;
    if (n < least)
        a.fail("sphere_sweep with " + word + " needs at least " + std::to_string(least) +
               " spheres, but its count is " + std::to_string(n) +
               ": Too few modeling spheres for interpolation type.");
    if (a.size() != 2 * static_cast<std::size_t>(n) + 1)
        a.fail("sphere_sweep says it has " + std::to_string(n) + " spheres (" +
               std::to_string(2 * n) + " values: a centre and a radius each) but lists " +
               std::to_string(a.size() - 1) + " values");
    sweep.centres.reserve(static_cast<std::size_t>(n));
    sweep.radii.reserve(static_cast<std::size_t>(n));
    for (std::size_t i = 1; i < a.size(); i += 2) {
        sweep.centres.push_back(a.vector3(i, "a sphere_sweep sphere's centre"));
        sweep.radii.push_back(a.number(i + 1, "a sphere_sweep sphere's radius"));
    }
    return sweep;
}

void SphereSweep::set(std::string_view setting, const objects::ShapeArguments& value) {
    if (setting == "tolerance") {
        value.need(1, 1, "a tolerance");
        tolerance = value.number(0, "sphere_sweep's tolerance");
    }
}

}  // namespace hexant::runtime
