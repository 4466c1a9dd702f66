#include "runtime/scene/shutter_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace hexant::runtime {

namespace {

std::string number(double v) {
    std::string s = std::to_string(v);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

double parse_number(const std::string& text, const std::string& what) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() || !std::isfinite(v))
        throw std::invalid_argument(what + " '" + text + "' is not a finite number");
    return v;
}

}  // namespace

ShutterCurve::ShutterCurve(std::vector<Key> keys) : keys_(std::move(keys)) {
    if (keys_.size() < 2)
        throw std::invalid_argument("a shutter curve needs at least two keys, at 0 and at 1");
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const Key& k = keys_[i];
        const std::string which =
            "key " + std::to_string(i + 1) + " (" + number(k.u) + ":" + number(k.weight) + ")";
        if (!(k.weight >= 0.0) || !std::isfinite(k.weight))
            throw std::invalid_argument(which + ": a weight must be a finite number of at least 0");
        if (!(k.u >= 0.0 && k.u <= 1.0))
            throw std::invalid_argument(which + ": its time must lie in [0, 1]");
        if (i > 0 && !(k.u > keys_[i - 1].u))
            throw std::invalid_argument(which + ": times must increase from key to key");
    }
    if (keys_.front().u != 0.0 || keys_.back().u != 1.0)
        throw std::invalid_argument(
            "a shutter curve's keys must begin at time 0 and end at time 1");
    area_.assign(keys_.size(), 0.0);
    for (std::size_t i = 1; i < keys_.size(); ++i)
        area_[i] = area_[i - 1] +
                   0.5 * (keys_[i - 1].weight + keys_[i].weight) * (keys_[i].u - keys_[i - 1].u);
    if (!(area_.back() > 0.0))
        throw std::invalid_argument("a shutter curve must be open somewhere (a weight above 0)");
    box_ = std::all_of(keys_.begin(), keys_.end(),
                       [&](const Key& k) { return k.weight == keys_.front().weight; });
}

ShutterCurve ShutterCurve::parse(const std::string& text) {
    if (text == "box") return ShutterCurve();
    if (text == "triangle") return ShutterCurve({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}});
    if (text == "trapezoid")
        return ShutterCurve({{0.0, 0.0}, {0.25, 1.0}, {0.75, 1.0}, {1.0, 0.0}});
    std::vector<Key> keys;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string item = text.substr(at, comma - at);
        const std::size_t colon = item.find(':');
        if (colon == std::string::npos)
            throw std::invalid_argument(
                "'" + item + "' is not a key u:w (or a shape: box, triangle, trapezoid)");
        keys.push_back({parse_number(item.substr(0, colon), "the time"),
                        parse_number(item.substr(colon + 1), "the weight")});
        at = comma + 1;
    }
    return ShutterCurve(std::move(keys));
}

double ShutterCurve::warp_keys(double x) const {
    const double target = std::clamp(x, 0.0, 1.0) * area_.back();
    // The segment whose integral holds the target (the first, among
    // segments of no area, whose end reaches it).
    const std::size_t i = std::min<std::size_t>(
        std::lower_bound(area_.begin() + 1, area_.end(), target) - area_.begin(), keys_.size() - 1);
    const Key& a = keys_[i - 1];
    const Key& b = keys_[i];
    const double length = b.u - a.u, rest = target - area_[i - 1];
    // Within the segment w(s) = w0 + (w1 - w0) s / L, whose integral
    // w0 s + (w1 - w0) s^2 / (2L) equals `rest` at
    // s = 2 rest / (w0 + sqrt(w0^2 + 2 (w1 - w0) rest / L)), the root
    // written without cancellation (w0 = 0 and w1 = w0 included).
    const double slope = (b.weight - a.weight) / length;
    const double root = std::sqrt(std::max(0.0, a.weight * a.weight + 2.0 * slope * rest));
    const double denominator = a.weight + root;
    const double s = denominator > 0.0 ? 2.0 * rest / denominator : 0.0;
    // (Below 1, as the uniform coordinate: the closing instant is not in
    // the interval.)
    return std::clamp(a.u + std::min(s, length), 0.0, std::nextafter(1.0, 0.0));
}

}  // namespace hexant::runtime
