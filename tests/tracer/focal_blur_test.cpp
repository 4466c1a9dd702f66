// POV-Ray's focal blur (tracer/focal_blur.hpp): lens points fill the disc
// of radius 0.5 evenly, and every ray through a screen point meets the
// others on the plane in focus.
#include "tracer/focal_blur.hpp"

#include <cmath>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

namespace tr = hexant::tracer;

TEST_CASE("lens points fill the disc of radius 0.5 evenly", "[tracer][camera]") {
    int inner = 0, total = 0;
    double farthest = 0.0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const glm::dvec2 p = tr::lens_point({(i + 0.5) / 64, (j + 0.5) / 64});
            farthest = std::max(farthest, glm::length(p));
            ++total;
            if (glm::length(p) < 0.25) ++inner;  // a quarter of the area
        }
    CHECK(farthest <= 0.5);
    CHECK(farthest > 0.49);
    CHECK(double(inner) / total == Approx(0.25).margin(0.01));
}

TEST_CASE("focal blur's rays through one screen point meet on the plane in focus",
          "[tracer][camera]") {
    hexant::runtime::CameraFrame camera;
    camera.location = {1, 2, -5};
    camera.direction = {0, 0, 2};
    camera.right = {1.33, 0, 0};
    camera.up = {0, 1, 0};
    camera.aperture = 0.8;
    camera.focal_distance = 6.0;
    const glm::dvec3 screen = camera.direction + 0.3 * camera.right - 0.2 * camera.up;
    // Where the pinhole ray through this screen point meets the plane 6
    // along the view: every lens ray passes there.
    const glm::dvec3 focus = camera.location + screen * (6.0 / 2.0);
    for (const glm::dvec2 lens :
         {glm::dvec2(0.5, 0.0), glm::dvec2(-0.3, 0.4), glm::dvec2(0.0, -0.5)}) {
        const tr::CameraRay ray = tr::focal_blur_ray(camera, screen, lens);
        // The eye moved across the view by up to aperture / 4.
        CHECK(std::fabs(ray.origin.z - camera.location.z) < 1e-12);
        CHECK(glm::length(ray.origin - camera.location) == Approx(0.4 * glm::length(lens)));
        const double s = (focus.z - ray.origin.z) / ray.direction.z;
        const glm::dvec3 there = ray.origin + s * ray.direction;
        CHECK(glm::length(there - focus) < 1e-12);
    }
    // No aperture: the pinhole ray.
    camera.aperture = 0.0;
    const tr::CameraRay pinhole = tr::focal_blur_ray(camera, screen, {0.5, 0.5});
    CHECK(pinhole.origin == camera.location);
    CHECK(pinhole.direction == glm::normalize(screen));
}
