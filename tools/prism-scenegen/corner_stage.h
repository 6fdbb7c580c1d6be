#pragma once
// The stage the random and lattice scenes share: their header comments, a camera looking into
// the corner of a box of side `side` (centred on x = z = 0, standing on y = 0), the background,
// one light and the floor's material.
#include <string>

#include "scene_text.h"

namespace prism::scenegen {

void writeCornerStage(SceneText &out, double side, const std::string &description,
                      const std::string &recreates, const std::string &command);

} // namespace prism::scenegen
