#include "io/format_writers.h"
#include "io/oiio_metadata.h"
#include "io/oiio_output.h"

#include <cstddef>
#include <string>
#include <vector>

namespace prism {

// Float32 in one part: R,G,B,A, then Z and N.X,N.Y,N.Z when present ("N.X" is the layer
// naming EXR readers such as Nuke and OIIO group into one "N" layer).
void writeExr(const std::filesystem::path &file, const OutputImage &image,
              const ImageMetadata &meta, const std::filesystem::path &reportedPath) {
    std::vector<std::string> names = {"R", "G", "B", "A"};
    if (!image.depth.empty())
        names.push_back("Z");
    if (!image.normal.empty())
        names.insert(names.end(), {"N.X", "N.Y", "N.Z"});

    const int channels = static_cast<int>(names.size());
    OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeFloat);
    spec.channelnames = names;
    spec.alpha_channel = 3;
    spec.z_channel = image.depth.empty() ? -1 : 4;
    if (image.fullWidth > 0) { // a part: the data window inside the whole image's
        spec.x = image.x;
        spec.y = image.y;
        spec.full_x = spec.full_y = 0;
        spec.full_width = image.fullWidth;
        spec.full_height = image.fullHeight;
    }
    // Lossless, whichever (OutputImage::exrCompression): floats come back bit for bit. The
    // default zlib at level 1 rather than its own 6: a 1024x768 frame compresses in a third of
    // the time for files 3% larger, and in a range the write shares the cores with the next
    // frame's trace (docs/benchmarks.md, "Frames").
    spec.attribute("compression", image.exrCompression);
    addMetadata(spec, meta);

    const std::size_t pixelCount = static_cast<std::size_t>(image.width) * image.height;
    std::vector<float> interleaved(pixelCount * channels);
    for (std::size_t i = 0; i < pixelCount; ++i) {
        float *px = &interleaved[i * channels];
        int c = 0;
        for (int k = 0; k < 4; ++k)
            px[c++] = image.rgba[i * 4 + k];
        if (!image.depth.empty())
            px[c++] = image.depth[i];
        if (!image.normal.empty())
            for (int k = 0; k < 3; ++k)
                px[c++] = image.normal[i * 3 + k];
    }
    writeWithOiio(file, "openexr", spec, interleaved.data(), reportedPath);
}

} // namespace prism
