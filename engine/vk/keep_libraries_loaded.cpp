#include "vk/keep_libraries_loaded.h"

#ifdef PRISM_SANITIZE
#include <dlfcn.h>
#include <link.h>
#endif

namespace prism::vk {

void keepVulkanLibrariesLoaded() {
#ifdef PRISM_SANITIZE
    // Every shared object loaded now gets RTLD_NODELETE (RTLD_NOLOAD: none is loaded anew), so
    // a later dlclose leaves it in place; the extra reference is never dropped, on purpose.
    dl_iterate_phdr(
        [](dl_phdr_info *info, size_t, void *) {
            if (info->dlpi_name != nullptr && info->dlpi_name[0] != '\0')
                (void)dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
#endif
}

} // namespace prism::vk
