// readTexture, writeImage and readImage for front ends that load OpenImageIO only when they
// first need it (io/oiio_plugin.h): each call goes through the table of libprism_oiio.so, the
// library beside the binary this code is linked into, loaded at the first call.
#include <dlfcn.h>

#include "core/error.h"
#include "io/oiio_load_order.h"
#include "io/oiio_plugin.h"

namespace prism {
namespace {

// The directory of the binary (executable or shared library) that holds this function.
std::filesystem::path ownDirectory() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&ownDirectory), &info) == 0 || !info.dli_fname)
        return {};
    return std::filesystem::path(info.dli_fname).parent_path();
}

// Beside the binary (the build's bin/ and python/, and an installed Python module), else, for
// installed tools, where `cmake --install` puts it relative to them (tools/CMakeLists.txt).
std::filesystem::path pluginPath() {
    std::filesystem::path beside = ownDirectory() / kOiioPluginFile;
#ifdef PRISM_INSTALLED_PLUGIN_DIR
    std::filesystem::path installed = ownDirectory() / PRISM_INSTALLED_PLUGIN_DIR / kOiioPluginFile;
    if (!std::filesystem::exists(beside) && std::filesystem::exists(installed))
        return installed;
#endif
    return beside;
}

// OpenImageIO's ~260 libraries, one `dlopen` each, every one after those it needs. Loaded as
// the plugin's dependencies in one piece, each library's symbols are looked up along the whole
// closure in breadth-first order, and the large C++ ones (OpenVDB alone makes a third of the
// 150,000 lookups, almost all of its own symbols) sit deep in it: 160-200 ms here, most of it
// in the loader's lookup. Loaded leaves first, a library's own symbols come first in its own
// scope, and the same load takes 95-100 ms; the loader's lock is also let go between libraries,
// so a Vulkan driver on another thread waits for one library, not all of them. RTLD_NOW, as
// the plugin is loaded: a library that cannot bind alone (one using a symbol of a library it
// does not name) is not kept half-bound but loaded later as another's dependency, and one that
// is missing is named by the plugin's own `dlopen`. Only references to code defined twice bind
// otherwise (templates two libraries both instantiate; BLAS's `xerbla_` and NetCDF's
// `strlcat` their own): each library binds as it would linked alone (design.md).
void loadImageLibrariesLeavesFirst() {
    for (const char *const *name = kOiioLibrariesLeavesFirst; *name; ++name)
        dlopen(*name, RTLD_NOW | RTLD_LOCAL); // kept loaded, as the plugin keeps them
}

const OiioPluginTable &plugin() {
    static const OiioPluginTable *table = [] {
        std::filesystem::path path = pluginPath();
        if (std::filesystem::exists(path)) // else its `dlopen` says so, with nothing loaded
            loadImageLibrariesLeavesFirst();
        void *library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!library)
            throw Error(std::string("cannot load Prism's image-file library (OpenImageIO): ") +
                        dlerror());
        auto entry = reinterpret_cast<const OiioPluginTable *(*)()>(
            dlsym(library, "prism_oiio_plugin_table"));
        const OiioPluginTable *found = entry ? entry() : nullptr;
        if (!found || found->version != kOiioPluginVersion)
            throw Error(path.string() + " is not this build's image-file library (version " +
                        std::to_string(found ? found->version : 0) + ", expected " +
                        std::to_string(kOiioPluginVersion) + "): rebuild");
        return found; // the library stays loaded for the process's life
    }();
    return *table;
}

void check(const std::string &error) {
    if (!error.empty())
        throw Error(error);
}

} // namespace

Texture readTexture(const std::filesystem::path &path, TexelMeaning meaning) {
    Texture texture;
    check(plugin().readTexture(path, meaning, texture));
    return texture;
}

void writeImage(const std::filesystem::path &path, const OutputImage &image,
                const ImageMetadata &meta) {
    check(plugin().writeImage(path, image, meta));
}

void preloadImageFiles() {
    try {
        plugin();
    } catch (const Error &) {
        // The first real call tries again and reports it, where it has a file to name.
    }
}

LoadedImage readImage(const std::filesystem::path &path) {
    LoadedImage image;
    check(plugin().readImage(path, image));
    return image;
}

} // namespace prism
