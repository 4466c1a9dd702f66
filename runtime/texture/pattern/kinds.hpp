// The pattern kinds hexant knows, registered here once: each is a struct in
// its own file under kinds/ (pattern_kind.hpp says what it provides). The
// grammar reads their keywords and setting words from this list
// (PatternWords), and registry.cpp makes the texture evaluator's Kind of
// each. Adding a pattern: its file, and its line in the list below.
#pragma once

#include "runtime/texture/pattern/kinds/agate.hpp"
#include "runtime/texture/pattern/kinds/average.hpp"
#include "runtime/texture/pattern/kinds/boxed.hpp"
#include "runtime/texture/pattern/kinds/bozo.hpp"
#include "runtime/texture/pattern/kinds/brick.hpp"
#include "runtime/texture/pattern/kinds/bumps.hpp"
#include "runtime/texture/pattern/kinds/cells.hpp"
#include "runtime/texture/pattern/kinds/checker.hpp"
#include "runtime/texture/pattern/kinds/crackle.hpp"
#include "runtime/texture/pattern/kinds/cylindrical.hpp"
#include "runtime/texture/pattern/kinds/density_file.hpp"
#include "runtime/texture/pattern/kinds/dents.hpp"
#include "runtime/texture/pattern/kinds/function.hpp"
#include "runtime/texture/pattern/kinds/gradient.hpp"
#include "runtime/texture/pattern/kinds/granite.hpp"
#include "runtime/texture/pattern/kinds/hexagon.hpp"
#include "runtime/texture/pattern/kinds/julia.hpp"
#include "runtime/texture/pattern/kinds/leopard.hpp"
#include "runtime/texture/pattern/kinds/magnet.hpp"
#include "runtime/texture/pattern/kinds/mandel.hpp"
#include "runtime/texture/pattern/kinds/marble.hpp"
#include "runtime/texture/pattern/kinds/material_map.hpp"
#include "runtime/texture/pattern/kinds/object.hpp"
#include "runtime/texture/pattern/kinds/onion.hpp"
#include "runtime/texture/pattern/kinds/pigment_pattern.hpp"
#include "runtime/texture/pattern/kinds/planar.hpp"
#include "runtime/texture/pattern/kinds/quilted.hpp"
#include "runtime/texture/pattern/kinds/radial.hpp"
#include "runtime/texture/pattern/kinds/ripples.hpp"
#include "runtime/texture/pattern/kinds/slope.hpp"
#include "runtime/texture/pattern/kinds/spherical.hpp"
#include "runtime/texture/pattern/kinds/spiral1.hpp"
#include "runtime/texture/pattern/kinds/spiral2.hpp"
#include "runtime/texture/pattern/kinds/spotted.hpp"
#include "runtime/texture/pattern/kinds/square.hpp"
#include "runtime/texture/pattern/kinds/triangular.hpp"
#include "runtime/texture/pattern/kinds/waves.hpp"
#include "runtime/texture/pattern/kinds/wood.hpp"
#include "runtime/texture/pattern/kinds/wrinkles.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern {

// One kind a line (kept so by hand, not by clang-format): adding one is a
// line here and its #include above.
// clang-format off
using PatternKinds = PatternKindList<
    kinds::Agate,
    kinds::Average,
    kinds::Boxed,
    kinds::Bozo,
    kinds::Brick,
    kinds::Bumps,
    kinds::Cells,
    kinds::Checker,
    kinds::Crackle,
    kinds::Cylindrical,
    kinds::DensityFilePattern,
    kinds::Dents,
    kinds::FunctionPattern,
    kinds::Gradient,
    kinds::Granite,
    kinds::Hexagon,
    kinds::Julia,
    kinds::Leopard,
    kinds::Magnet,
    kinds::Mandel,
    kinds::Marble,
    kinds::MaterialMap,
    kinds::ObjectPattern,
    kinds::Onion,
    kinds::PigmentPattern,
    kinds::Planar,
    kinds::Quilted,
    kinds::Radial,
    kinds::Ripples,
    kinds::Slope,
    kinds::Spherical,
    kinds::Spiral1,
    kinds::Spiral2,
    kinds::Spotted,
    kinds::Square,
    kinds::Triangular,
    kinds::Waves,
    kinds::Wood,
    kinds::Wrinkles>;
// clang-format on

}  // namespace hexant::runtime::pattern
