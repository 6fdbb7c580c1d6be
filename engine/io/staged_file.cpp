#include "io/staged_file.h"

#include "core/error.h"
#include "io/temp_file_cleanup.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <system_error>
#include <unistd.h>

namespace prism {
namespace {

std::filesystem::path tempPathFor(const std::filesystem::path &target) {
    // Appended piece by piece: GCC 12's -Wrestrict misfires on "." + std::string.
    std::string name(1, '.');
    name += target.stem().string();
    name += ".tmp-";
    name += std::to_string(::getpid());
    name += target.extension().string();
    return target.parent_path() / name;
}

// fsync before rename, so a crash cannot leave the target renamed but empty.
void flushToDisk(const std::filesystem::path &path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
        std::string reason = std::strerror(errno);
        if (fd >= 0)
            ::close(fd);
        throw Error("cannot flush '" + path.string() + "': " + reason);
    }
    ::close(fd);
}

} // namespace

void checkCanStage(const std::filesystem::path &target) {
    auto fail = [&](const std::string &why) {
        throw Error("cannot write image '" + target.string() + "': " + why);
    };
    std::filesystem::path dir = target.parent_path().empty() ? "." : target.parent_path();
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(dir, ec);
    if (!std::filesystem::exists(status))
        fail("the directory '" + dir.string() + "' does not exist");
    if (!std::filesystem::is_directory(status))
        fail("'" + dir.string() + "' is not a directory");
    if (std::filesystem::is_directory(target, ec))
        fail("it is a directory");
    std::filesystem::path probe = tempPathFor(target);
    int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST)
        fail(std::string("cannot create a file in '") + dir.string() +
             "': " + std::strerror(errno));
    if (fd >= 0) {
        ::close(fd);
        std::filesystem::remove(probe, ec);
    }
}

StagedFile::StagedFile(std::filesystem::path target)
    : target_(std::move(target)), temp_(tempPathFor(target_)), watch_(watchTempFile(temp_)) {}

StagedFile::~StagedFile() {
    unwatchTempFile(watch_);
    if (!committed_) {
        std::error_code ignored;
        std::filesystem::remove(temp_, ignored);
    }
}

void StagedFile::commit() {
    flushToDisk(temp_);
    std::error_code ec;
    std::filesystem::rename(temp_, target_, ec);
    if (ec)
        throw Error("cannot write image '" + target_.string() + "': rename from '" +
                    temp_.string() + "' failed: " + ec.message());
    committed_ = true;
}

} // namespace prism
