#include "scene_text.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"

namespace prism::scenegen {

int64_t toTicks(double value) {
    double scaled = value * double(kTicksPerUnit);
    if (!std::isfinite(scaled) || std::fabs(scaled) > 9.0e15)
        throw Error("number out of range: " + std::to_string(value));
    return std::llround(scaled);
}

std::string formatTicks(int64_t ticks) {
    if (ticks == 0)
        return "0";
    std::string sign = ticks < 0 ? "-" : "";
    uint64_t magnitude = ticks < 0 ? uint64_t(0) - uint64_t(ticks) : uint64_t(ticks);
    std::string text = sign + std::to_string(magnitude / kTicksPerUnit);
    uint64_t fraction = magnitude % kTicksPerUnit;
    if (fraction != 0) {
        std::string digits = std::to_string(fraction);
        digits.insert(0, 4 - digits.size(), '0'); // kTicksPerUnit has four zeros
        while (digits.back() == '0')
            digits.pop_back();
        text += "." + digits;
    }
    return text;
}

std::string formatNumber(double value) {
    return formatTicks(toTicks(value));
}

std::string formatVec(const glm::dvec3 &v) {
    return formatNumber(v.x) + " " + formatNumber(v.y) + " " + formatNumber(v.z);
}

void writeFileAtomically(const std::filesystem::path &path, const std::string &text) {
    std::filesystem::path target = path.empty() ? path : std::filesystem::absolute(path);
    if (target.empty() || !target.has_filename())
        throw Error("output path '" + path.string() + "' names no file");
    std::string pattern = target.string() + ".tmp-XXXXXX";
    int fd = ::mkstemp(pattern.data());
    if (fd < 0)
        throw Error("cannot create a file in '" + target.parent_path().string() +
                    "': " + std::strerror(errno));
    // mkstemp makes the file 0600; a scene is an ordinary file, so honour the umask instead.
    mode_t mask = ::umask(0);
    ::umask(mask);
    (void)::fchmod(fd, 0666 & ~mask);
    std::FILE *file = ::fdopen(fd, "wb");
    if (!file) {
        ::close(fd);
        std::remove(pattern.c_str());
        throw Error("cannot open '" + pattern + "' for writing");
    }
    bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    bool flushed = std::fflush(file) == 0 && ::fsync(fd) == 0;
    bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
        std::remove(pattern.c_str());
        throw Error("cannot write '" + path.string() + "' (disk full?)");
    }
    std::error_code error;
    std::filesystem::rename(pattern, target, error);
    if (error) {
        std::remove(pattern.c_str());
        throw Error("cannot rename the output onto '" + path.string() + "': " + error.message());
    }
}

} // namespace prism::scenegen
