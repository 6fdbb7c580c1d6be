#include "core/mapped_file.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"

namespace prism {

MappedFile::MappedFile(const std::filesystem::path &path, const char *what) {
    auto fail = [&](const std::string &why) {
        throw Error(std::string("cannot read ") + what + " '" +
                    path.lexically_normal().generic_string() + "': " + why);
    };
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        fail(std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        int error = errno;
        ::close(fd);
        fail(std::strerror(error));
    }
    if (S_ISDIR(st.st_mode)) {
        ::close(fd);
        fail("it is a directory");
    }
    if (S_ISREG(st.st_mode) && st.st_size > 0) {
        // MAP_POPULATE: the pages are mapped in one call instead of one fault each.
        void *p = ::mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (p != MAP_FAILED) {
            mapping_ = p;
            mappedSize_ = size_t(st.st_size);
            bytes_ = std::string_view(static_cast<const char *>(p), mappedSize_);
            ::close(fd);
            return;
        }
    }
    // A pipe, a device, an empty file or a file system without mmap: read it.
    char buffer[1 << 16];
    for (;;) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            int error = errno;
            ::close(fd);
            fail(std::strerror(error));
        }
        if (n == 0)
            break;
        copy_.append(buffer, size_t(n));
    }
    ::close(fd);
    bytes_ = copy_;
}

MappedFile::~MappedFile() {
    if (mapping_)
        ::munmap(mapping_, mappedSize_);
}

} // namespace prism
