// A rendered frame: linear RGB, rows top to bottom.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

namespace hexant::tracer {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // 3 per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}
    glm::dvec3 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, const glm::dvec3& c) {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
        rgb[i] = static_cast<float>(c.x);
        rgb[i + 1] = static_cast<float>(c.y);
        rgb[i + 2] = static_cast<float>(c.z);
    }
};

}  // namespace hexant::tracer
