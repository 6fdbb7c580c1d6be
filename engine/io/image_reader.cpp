#include "io/image_reader.h"

#include "core/error.h"
#include "io/oiio_metadata.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <string>

namespace prism {
namespace {

[[noreturn]] void fail(const std::filesystem::path &path, const std::string &why) {
    throw Error("cannot read image '" + path.string() + "': " + why);
}

} // namespace

LoadedImage readImage(const std::filesystem::path &path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
    if (!in)
        fail(path, OIIO::geterror());

    const OIIO::ImageSpec &spec = in->spec();
    LoadedImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    // Relative to the display window's corner, which Prism's own images keep at 0, 0.
    image.x = spec.x - spec.full_x;
    image.y = spec.y - spec.full_y;
    image.fullWidth = spec.full_width;
    image.fullHeight = spec.full_height;
    image.channelNames = spec.channelnames;
    image.metadata = metadataOf(spec);
    image.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, image.pixels.data()))
        fail(path, in->geterror());
    in->close();
    return image;
}

} // namespace prism
