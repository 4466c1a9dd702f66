// The object kinds hexant knows, registered here once: each is a record in
// its own folder (runtime/objects/shape_kind.hpp says what it provides).
// The language reads their keywords, options and settings from this list,
// the factory makes a Primitive of each one's Model, and the checks and the
// dump walk each one's parameters. Adding a kind: its folder, and a line in
// each of the two lists below.
#pragma once

#include "runtime/objects/bicubic_patch/bicubic_patch.hpp"
#include "runtime/objects/blob/blob.hpp"
#include "runtime/objects/box/box.hpp"
#include "runtime/objects/cylinder/cone.hpp"
#include "runtime/objects/cylinder/cylinder.hpp"
#include "runtime/objects/disc/disc.hpp"
#include "runtime/objects/height_field/height_field.hpp"
#include "runtime/objects/isosurface/isosurface.hpp"
#include "runtime/objects/julia_fractal/julia_fractal.hpp"
#include "runtime/objects/lathe/lathe.hpp"
#include "runtime/objects/mesh/mesh.hpp"
#include "runtime/objects/plane/plane.hpp"
#include "runtime/objects/poly/poly.hpp"
#include "runtime/objects/polygon/polygon.hpp"
#include "runtime/objects/prism/prism.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/objects/sor/sor.hpp"
#include "runtime/objects/sphere/sphere.hpp"
#include "runtime/objects/sphere_sweep/sphere_sweep.hpp"
#include "runtime/objects/superellipsoid/superellipsoid.hpp"
#include "runtime/objects/text/text.hpp"
#include "runtime/objects/torus/torus.hpp"
#include "runtime/objects/triangle/smooth_triangle.hpp"
#include "runtime/objects/triangle/triangle.hpp"

namespace hexant::runtime {

using ShapeKinds =
    objects::KindList<Sphere, Box, Plane, Polygon, Triangle, SmoothTriangle, Disc, Cylinder, Cone,
                      Torus, Prism, Text, Mesh, Lathe, Sor, Superellipsoid, HeightField, Blob,
                      SphereSweep, Isosurface, JuliaFractal, BicubicPatch, Quadric, Cubic, Quartic,
                      Poly, Polynomial>;

}  // namespace hexant::runtime
