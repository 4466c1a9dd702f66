// The parameters of a scene's records that the renderer cannot use: NaN or
// infinite at some instant of the animation (a radius of sqrt(-1), a colour
// of 1/0, a translate by 1e300 * 1e300), a transform that is singular or
// overflows, a camera with a zero direction or whose look_at is its
// location. Each returns the message naming the first found, with the
// instant when it depends on `clock` ("the sphere's radius is NaN at
// clock = 0.75"), or nothing; the language puts it at the record's place.
// Time-dependent parameters are searched by interval evaluation over the
// animation's time (non_finite.hpp).
#pragma once

#include <optional>
#include <string>

#include "runtime/objects/object.hpp"
#include "runtime/scene/animation.hpp"
#include "runtime/scene/camera.hpp"
#include "runtime/scene/light.hpp"

namespace hexant::runtime {

// The object's own shape, transform, texture and interior (not its CSG
// children: each has its own place).
std::optional<std::string> bad_parameter(const ObjectRecord& object, const Animation& animation);
std::optional<std::string> bad_parameter(const LightRecord& light, const Animation& animation);
// A texture on its own (the #default one): `whose` begins the message
// ("the #default texture's").
std::optional<std::string> bad_parameter(const Texture& texture, const std::string& whose,
                                         const Animation& animation);
// Also its geometry at each frame's clock: the angle's range, a zero
// direction, look_at at the location (and, by interval search, at any
// instant where the two meet exactly).
std::optional<std::string> bad_parameter(const CameraRecord& camera, const Animation& animation);

}  // namespace hexant::runtime
