#include "io/oiio_metadata.h"

namespace prism {

void addMetadata(OIIO::ImageSpec &spec, const ImageMetadata &meta) {
    for (const auto &[name, value] : meta.strings)
        spec.attribute(name, value);
    for (const auto &[name, value] : meta.floats)
        spec.attribute(name, value);
    for (const auto &[name, value] : meta.ints)
        spec.attribute(name, value);
}

ImageMetadata metadataOf(const OIIO::ImageSpec &spec) {
    ImageMetadata meta;
    for (const OIIO::ParamValue &p : spec.extra_attribs) {
        const std::string name = p.name().string();
        if (p.type() == OIIO::TypeString)
            meta.strings.emplace_back(name, p.get_string());
        else if (p.type() == OIIO::TypeFloat)
            meta.floats.emplace_back(name, p.get_float());
        else if (p.type() == OIIO::TypeInt)
            meta.ints.emplace_back(name, p.get_int());
    }
    return meta;
}

} // namespace prism
