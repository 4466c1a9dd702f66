// What each grammar rule does when it matches: PEGTL actions, kept apart from
// the grammar, working on the Interpreter's value stack and block stack. They
// live in language/actions/, one file a part beside its rules' part of the
// grammar, each including the one before it: action, literals, operators, directives,
// transformations, patterns, maps, materials, objects, meshes, lights, scene, arrays,
// functions, isosurfaces, julia_fractals, bicubic_patches, polys, file_directives.
#pragma once

#include "language/actions/file_directives.hpp"
