// CSG nested beyond what the tracer's recursion can take is refused where
// it is written (issue 17: 8,000 nested intersections crashed the render);
// the depth real scenes use builds, and unions, split apart, are not
// counted.
#include <string>

#include <catch2/catch.hpp>

#include "object_test_support.hpp"
#include "runtime/objects/object_error.hpp"

using namespace object_test;

namespace {

std::string nested(const char* kind, int n) {
    std::string text;
    for (int i = 0; i < n; ++i) text += std::string(kind) + " { ";
    text += "sphere { 0, 1 } sphere { <0.5, 0, 0>, 1 }";
    for (int i = 0; i < n; ++i) text += " }";
    return text + "\n";
}

}  // namespace

TEST_CASE("CSG nesting: refused past 1000 levels, at its place", "[object][nesting]") {
    for (const char* kind : {"intersection", "difference", "merge"}) {
        INFO(kind);
        CHECK_NOTHROW(parse(nested(kind, 1000)));
        try {
            parse(nested(kind, 1001));
            FAIL("expected an error");
        } catch (const rt::ObjectError& e) {
            CHECK(std::string(e.what()).find("CSG nested more than 1000 levels") !=
                  std::string::npos);
        }
    }
}
