#include "runtime/objects/superellipsoid/superellipsoid.hpp"

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Superellipsoid (parse.cpp): one 2-vector <e, n>, no
// checks (its Power = <2/e, e/n, 2/n> is computed unguarded; e = 0 or n = 0
// gives an infinite power, which POV-Ray's evaluation turns into the box's
// faces). A value that is not a 2-vector is the language's error.
Superellipsoid Superellipsoid::read(const objects::ShapeArguments& a) {
    a.no_options();
    a.need(1, 1, "one vector <e, n>");
    const Vector2Function en = a.vector2(0, "superellipsoid's <e, n>");
    return {en.c[0], en.c[1]};
}

}  // namespace hexant::runtime
