#include "size_option.h"

#include <regex>

#include "core/error.h"

namespace prism {

ImageSize parseSizeOption(const std::string &text, const std::string &option) {
    std::smatch m;
    static const std::regex pattern("([0-9]{1,9})x([0-9]{1,9})");
    if (!std::regex_match(text, m, pattern))
        throw Error(option + " must look like 1024x768, got \"" + text + "\"");
    ImageSize size{uint32_t(std::stoul(m[1])), uint32_t(std::stoul(m[2]))};
    if (size.width < 1 || size.height < 1 || size.width > 16384 || size.height > 16384)
        throw Error(option + " must be between 1x1 and 16384x16384, got \"" + text + "\"");
    return size;
}

} // namespace prism
