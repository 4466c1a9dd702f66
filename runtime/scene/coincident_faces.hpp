// Coincident surfaces: two objects whose flat faces lie in one plane and
// overlap there (a glass box standing in the floor's plane, a board's
// squares flush with the board). Where a ray meets both at the same
// distance, which one it takes is decided by rounding, in POV-Ray as in
// hexant, so the two renderers differ there and neither image is right
// (POV-Ray's documentation: "coincident surfaces"). The language warns at
// each such pair (language/interpreter_sources.cpp, finish_reading).
//
// Only pairs a ray can tell apart are reported: faces that face the same
// way (or a two-sided disc or triangle), or facing each other where either
// object lets light through; and any pair whose nearest common CSG is an
// intersection or difference, where each face exists by an inside test of
// the other that the coincidence leaves to rounding. Two faces that take
// their texture from one CSG's texture look alike and are not reported.
// Objects whose shape or transform depends on time, deformed ones, clipped
// ones, no_image ones, members nested more than 256 deep and kinds
// without flat faces (runtime/objects/flat_face.hpp) take no part.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/objects/object.hpp"
#include "runtime/source_place.hpp"

namespace hexant::runtime {

struct CoincidentFaces {
    struct Side {
        SourcePlace place;  // the object's (a box's)
        const char* kind = "";
        SourcePlace top;  // the scene's object it is part of (itself, or a CSG)
        const char* top_kind = "";
    };
    Side first, second;
};

struct CoincidentFacesReport {
    // At most kMostReported pairs of places, each pair once (the copies of
    // one written object made in a loop count as one).
    std::vector<CoincidentFaces> pairs;
    // Further pairs of places found beyond those.
    std::size_t more = 0;
    static constexpr std::size_t kMostReported = 16;
};

// The scene's coincident faces. `default_texture`: the texture of objects
// that have none (#default). Cost: O(F log F) in the number of flat faces
// (at most 2^18 are collected), plus the overlapping pairs, of which at
// most 10^6 are examined.
CoincidentFacesReport find_coincident_faces(const std::vector<ObjectPtr>& objects,
                                            const Texture& default_texture);

}  // namespace hexant::runtime
