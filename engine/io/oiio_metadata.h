#pragma once
// ImageMetadata <-> OpenImageIO ImageSpec attributes.
#include "io/image_metadata.h"

#include <OpenImageIO/imageio.h>

namespace prism {

void addMetadata(OIIO::ImageSpec &spec, const ImageMetadata &meta);

// Every string, float and int attribute of the spec; other types are left out.
ImageMetadata metadataOf(const OIIO::ImageSpec &spec);

} // namespace prism
