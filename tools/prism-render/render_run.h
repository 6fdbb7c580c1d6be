#pragma once
#include "render_options.h"

namespace prism {

// Loads, builds the grid, renders (warm-up + repeat frames), writes the image; throws
// prism::Error on any failure, leaving no output file behind.
void runRender(const RenderOptions &options);

} // namespace prism
