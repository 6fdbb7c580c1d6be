#pragma once
// prism-merge's work: the tiles of one still (prism-render --tile I/N, or any regions written
// as EXRs whose data windows lie in one display window) put back together into the whole
// image. The tiles must cover the image exactly once: a pixel in two tiles or in none is an
// error naming the files, never a guess.
#include <filesystem>
#include <vector>

#include "io/image_metadata.h"
#include "io/image_writer.h"

namespace prism {

struct MergedImage {
    OutputImage image;
    // The first tile's metadata without what only a tile says (prism:region, prism:tile, its
    // command line and timings), the tiles' ray counts added up, prism:mergedTiles, and the
    // tiles' trace times added up as prism:renderTimeMs (the work, not the wall time).
    ImageMetadata metadata;
};

// Reads every tile (OpenImageIO) and assembles them. Throws prism::Error naming the file for an
// unreadable tile, one whose display window or channels differ from the first's, channels that
// are not Prism's (R, G, B, A, then Z and N.X, N.Y, N.Z, as prism-render writes them), pixels
// that two tiles both hold, and pixels that no tile holds.
MergedImage mergeTiles(const std::vector<std::filesystem::path> &tiles);

} // namespace prism
