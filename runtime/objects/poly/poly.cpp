#include "runtime/objects/poly/poly.hpp"

#include <stdexcept>

namespace hexant::runtime {

int poly_term_index(int order, int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i + j + k > order)
        throw std::out_of_range("poly_term_index: no such term");
    int index = 0;
    // Terms with a higher power of x come first, then of y, then of z.
    for (int a = order; a > i; --a) index += (order - a + 1) * (order - a + 2) / 2;
    for (int b = order - i; b > j; --b) index += order - i - b + 1;
    return index + (order - i - j - k);
}

Quadric Quadric::read(const objects::ShapeArguments& a) {
    a.no_options();
    a.need(4, 4, "<A, B, C>, <D, E, F>, <G, H, I> and J");
    const Vector3Function squares = a.vector3(0, "quadric's x^2, y^2, z^2 coefficients");
    const Vector3Function mixed = a.vector3(1, "quadric's xy, xz, yz coefficients");
    const Vector3Function linear = a.vector3(2, "quadric's x, y, z coefficients");
    const TimeFunction constant = a.number(3, "quadric's constant");
    Quadric q;
    q.order = 2;
    // x^2, xy, xz, x, y^2, yz, y, z^2, z, 1.
    q.coefficients = {squares.c[0], mixed.c[0],  mixed.c[1],   linear.c[0], squares.c[1],
                      mixed.c[2],   linear.c[1], squares.c[2], linear.c[2], constant};
    return q;
}

}  // namespace hexant::runtime
