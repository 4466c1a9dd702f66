// Where the bundled include files are: found from the running executable,
// so that an installed hexant reads its installed copy wherever the
// installation was put (a --prefix, a DESTDIR staging, a moved tree), and
// a hexant run from the build tree reads the source tree's.
#include <filesystem>
#include <system_error>

#include "language/interpreter.hpp"

// Both set on this file alone by language/CMakeLists.txt: the source
// tree's folder, and the installed folder relative to the installed
// executable's (bin/ to share/hexant/include: "../share/hexant/include").
#ifndef HEXANT_BUNDLED_INCLUDE_DIR
#error "HEXANT_BUNDLED_INCLUDE_DIR is set by language/CMakeLists.txt"
#endif
#ifndef HEXANT_INSTALLED_INCLUDE_DIR
#error "HEXANT_INSTALLED_INCLUDE_DIR is set by language/CMakeLists.txt"
#endif

namespace hexant::language {

std::filesystem::path bundled_include_dir() {
    namespace fs = std::filesystem;
    // Once per process: the executable does not move while it runs.
    static const fs::path folder = [] {
        std::error_code error;
        // The link's target is the executable's real path, symbolic links
        // resolved, so /usr/local/bin/hexant -> /opt/hexant/bin/hexant
        // finds /opt/hexant/share.
        const fs::path executable = fs::read_symlink("/proc/self/exe", error);
        if (!error) {
            const fs::path installed =
                (executable.parent_path() / HEXANT_INSTALLED_INCLUDE_DIR).lexically_normal();
            if (fs::is_directory(installed, error)) return installed;
        }
        return fs::path(HEXANT_BUNDLED_INCLUDE_DIR);
    }();
    return folder;
}

}  // namespace hexant::language
