// How open the shutter is over its open interval: a weight w(u) >= 0 for u
// in [0, 1] of the interval, piecewise linear through keyframes (as a
// physical shutter's opening and closing ramps, or Cycles' shutter curve).
// A sample's time is drawn with density proportional to w, by the inverse
// of w's integral applied to the sample's uniform time coordinate: the
// warp is monotone, so the time dimension's stratification (Sobol' with
// Owen scrambling, tracer/sample_pattern.hpp) carries over, and every sample
// keeps the weight 1. A box (w constant, the default) is the identity, so
// images without a curve are bit for bit what they were.
#pragma once

#include <string>
#include <vector>

namespace hexant::runtime {

class ShutterCurve {
  public:
    struct Key {
        double u;       // in [0, 1] of the open interval
        double weight;  // >= 0, finite
    };

    // The box: open fully from opening to closing.
    ShutterCurve() = default;
    // Keyframes at increasing u from 0 to 1 with weights >= 0, not all 0.
    // std::invalid_argument, saying which key is wrong, otherwise.
    explicit ShutterCurve(std::vector<Key> keys);
    // The curve a --shutter-curve text names: `box`, `triangle` (opening
    // to full at the middle and closing), `trapezoid` (a quarter opening,
    // a half fully open, a quarter closing), or keyframes `u:w,u:w,...`
    // (e.g. 0:0,0.1:1,0.9:1,1:0). std::invalid_argument naming the fault.
    static ShutterCurve parse(const std::string& text);

    bool is_box() const { return box_; }
    const std::vector<Key>& keys() const { return keys_; }
    // The instant in [0, 1] of the open interval for the uniform sample
    // coordinate x in [0, 1]: W^-1(x W(1)) with W(u) the integral of w
    // from 0. x itself for the box.
    double warp(double x) const { return box_ ? x : warp_keys(x); }

  private:
    double warp_keys(double x) const;
    std::vector<Key> keys_{{0.0, 1.0}, {1.0, 1.0}};
    std::vector<double> area_;  // W at each key
    bool box_ = true;
};

}  // namespace hexant::runtime
