// POV-Ray's bicubic_patch { type 0|1 [flatness F] [u_steps U] [v_steps V]
// [accuracy A] [uv_vectors <s0>, <s1>, <s2>, <s3>] P00, P01, ..., P33
// modifiers }: a Bezier patch of 4 x 4 control points, rendered as POV-Ray
// 3.7 renders it, as the triangles of the patch subdivided until flat
// (runtime/objects/bicubic_patch/bicubic_patch_geometry.hpp). The object
// kind (runtime/objects/shape_kind.hpp); its block has its own rule in the
// grammar (kOwnSyntax), read by language/actions/bicubic_patches.hpp.
//
// The control points and the uv_vectors may be time functions; type,
// flatness and the steps are numbers known while the scene is read.
// Types 0 and 1 give the same triangles (POV-Ray subdivides a type 0 patch
// for each ray, a type 1 patch once); hexant keeps the subdivision of a
// patch that never changes, whichever its type.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class BicubicPatchModel;
}  // namespace objects

struct BicubicPatch {
    static constexpr std::string_view keyword = "bicubic_patch";
    static constexpr bool kOwnSyntax = true;
    using Model = objects::BicubicPatchModel;

    // The most u_steps or v_steps hexant takes: 2^16 pieces along a side,
    // far finer than any scene needs (POV-Ray's own scenes use 3 to 8).
    static constexpr int kMaxSteps = 16;

    int type = 0;  // 0 or 1 (POV-Ray has no default: the language requires it)
    // POV-Ray's defaults (the BicubicPatch constructor): never flat, no
    // subdivision (two triangles of the corners).
    double flatness = 0.0;
    int u_steps = 0, v_steps = 0;
    // P[i][j] at 4 i + j, as written: i runs along u, j along v. (Sixteen,
    // on the heap: inline they made every object record's shape 480 bytes.)
    std::vector<Vector3Function> points = std::vector<Vector3Function>(16);
    // The texture coordinates of the corners (u, v) = (0, 0), (1, 0), (1, 1),
    // (0, 1) (POV-Ray's ST; its defaults).
    std::array<Vector2Function, 4> uv_corners{
        Vector2Function{{0.0, 0.0}}, Vector2Function{{1.0, 0.0}}, Vector2Function{{1.0, 1.0}},
        Vector2Function{{0.0, 1.0}}};

    template <class F>
    void parameters(F&& f) const {
        static constexpr const char* names[16] = {"p00", "p01", "p02", "p03", "p10", "p11",
                                                  "p12", "p13", "p20", "p21", "p22", "p23",
                                                  "p30", "p31", "p32", "p33"};
        static constexpr const char* uv_names[4] = {"uv0", "uv1", "uv2", "uv3"};
        f("subdivision", "subdivision",
          objects::DescribedParameter{
              "type " + std::to_string(type) + " flatness " + std::to_string(flatness) +
              " u_steps " + std::to_string(u_steps) + " v_steps " + std::to_string(v_steps)});
        for (int k = 0; k < 16; ++k) f(names[k], "control point", points[k]);
        for (int k = 0; k < 4; ++k) f(uv_names[k], "uv vector", uv_corners[k]);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/bicubic_patch/bicubic_patch_model.hpp"
