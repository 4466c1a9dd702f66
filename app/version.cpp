// The version text; HEXANT_VERSION comes from project(VERSION) in the root
// CMakeLists.txt, the commit from build/generated/hexant_git_commit.hpp,
// which cmake/git_commit.cmake rewrites at each build only when it changes.
#include "app/version.hpp"

#include "hexant_git_commit.hpp"

#ifndef HEXANT_VERSION
#error "HEXANT_VERSION is set by app/CMakeLists.txt"
#endif

namespace hexant::app {

std::string version_text() {
    std::string text = "hexant " HEXANT_VERSION;
    const std::string commit = HEXANT_GIT_COMMIT;
    if (!commit.empty()) text += " (git " + commit + ")";
    return text;
}

std::string version_number() {
    return HEXANT_VERSION;
}

}  // namespace hexant::app
