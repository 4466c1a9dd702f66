// A scene that includes POV-Ray's own files (textures.inc, math.inc) reads
// without -L, as `povray` finds them through its povray.ini's
// Library_Path (../shared/cases: three real animations were refused for
// it). The files come from Debian's povray-includes, which `make deps`
// installs.
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"

TEST_CASE("POV-Ray's include folder is searched without -L", "[language][include]") {
    hexant::language::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    const auto scene = hexant::language::parse_scene_text(R"(
#include "math.inc"
#include "textures.inc"
#declare V = vnormalize(<3, 0, 4>);
sphere { V, 1 texture { Jade } }
)",
                                                          "test.pov", options);
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.inputs.size() >= 2);  // both files read from the folder
}
