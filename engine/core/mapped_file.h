#pragma once
// A whole file's bytes, mapped read-only rather than copied: the page cache's own pages, so a
// large input (a 41 MB OBJ, a 73 MB grid cache entry) costs no fresh memory, which on the
// machines Prism is measured on costs more than reading it (core/huge_pages.h). A pipe or
// device, which cannot be mapped, is read into memory instead.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace prism {

class MappedFile {
public:
    // Throws prism::Error("cannot read WHAT 'PATH': reason") when the file cannot be read.
    MappedFile(const std::filesystem::path &path, const char *what);
    ~MappedFile();
    MappedFile(const MappedFile &) = delete;
    MappedFile &operator=(const MappedFile &) = delete;

    std::string_view bytes() const { return bytes_; }

private:
    void *mapping_ = nullptr;
    size_t mappedSize_ = 0;
    std::string copy_; // a file that could not be mapped
    std::string_view bytes_;
};

} // namespace prism
