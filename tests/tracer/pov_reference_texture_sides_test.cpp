// hexant against POV-Ray 3.7 on textures that pick whole textures by where
// or from which side a surface is seen: tiles { } and interior_texture { }
// (the images and the commands that made them: pov_reference/README.md).
#include <catch2/catch.hpp>

#include "pov_reference_compare.hpp"

using namespace hexant::test::pov_reference;

TEST_CASE("tiles agree with POV-Ray 3.7's", "[tracer][pov][pattern]") {
    // textures/tiles.pov: a first tile of two layers (one partly clear)
    // over a reflecting tile2, turning with clock; tiles with a bumpy
    // normal on a ball moving with clock; tiles in a texture_map's entry.
    // The still's tolerance (exact when written). Before, tiles was
    // refused.
    check_stills("textures", "tiles", {"0", "0.5"});
}

TEST_CASE("interior_texture agrees with POV-Ray 3.7's", "[tracer][pov][pattern]") {
    // textures/interior_texture.pov: a sphere opened by clipped_by showing
    // its two layered interior textures (one bumpy, turning with clock), a
    // sphere seen through its partly clear outer texture, and a clipped
    // union handing its interior texture to a member without one. The
    // still's tolerance (exact when written). Before, interior_texture was
    // refused.
    check_stills("textures", "interior_texture", {"0", "0.5"});
}
