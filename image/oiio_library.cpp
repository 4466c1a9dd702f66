#include "image/oiio_library.hpp"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <system_error>

#include <dlfcn.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> loaded{false};

}  // namespace

std::vector<fs::path> oiio_module_folders() {
    std::vector<fs::path> folders;
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path own = exe.parent_path();
        folders.push_back(own);
        folders.push_back((own / HEXANT_MODULE_RELATIVE_DIR).lexically_normal());
    }
    folders.push_back(HEXANT_MODULE_BUILD_DIR);
    return folders;
}

const HexantOiioApi& oiio_module(const std::string& needed_for) {
    static std::mutex mutex;
    static const HexantOiioApi* api = nullptr;
    const std::lock_guard lock(mutex);
    if (api) return *api;
    std::string tried, why;
    for (const fs::path& folder : oiio_module_folders()) {
        const fs::path file = folder / kOiioModuleName;
        std::error_code error;
        tried += (tried.empty() ? "" : ", ") + folder.string();
        if (!fs::is_regular_file(file, error)) continue;
        // RTLD_LOCAL: OpenImageIO's symbols stay the module's own.
        void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* text = ::dlerror();
            // (The module is there; a library it needs is not.)
            throw std::runtime_error(
                needed_for + " needs OpenImageIO, and " + file.string() +
                " does not load: " + (text ? text : "?") +
                " (install Debian's package libopenimageio2.4, or libopenimageio-dev to build)");
        }
        using Entry = const HexantOiioApi* (*)(int);
        const auto entry = reinterpret_cast<Entry>(::dlsym(handle, HEXANT_OIIO_ENTRY));
        const HexantOiioApi* table = entry ? entry(HEXANT_OIIO_API_VERSION) : nullptr;
        if (!table) {
            ::dlclose(handle);
            why = file.string() + " is another version of the module than this hexant's";
            continue;
        }
        // (Never closed: OpenImageIO keeps threads and caches.)
        api = table;
        loaded = true;
        return *api;
    }
    throw std::runtime_error(needed_for + " needs hexant's OpenImageIO module " +
                             std::string(kOiioModuleName) + ", " +
                             (why.empty() ? "not found in " + tried : why) +
                             " (build the target hexant_oiio, or install hexant with it; it needs "
                             "Debian's package libopenimageio2.4)");
}

bool oiio_module_loaded() {
    return loaded;
}

}  // namespace hexant::image
