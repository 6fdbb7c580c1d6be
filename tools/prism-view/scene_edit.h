#pragma once
// The changing scene of a soak run: the scene file's text with zero, one or two small spheres
// added. Each reload then changes the primitive count, so the grid is rebuilt and the scene
// buffers are re-uploaded at another size, as after a user's edit.
#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace prism {

// The variants cycle: edit k writes variant k % kSceneVariants (0: the text unchanged), so a
// soak run keeps returning to states it has been in.
constexpr uint32_t kSceneVariants = 3;

// `text` with variant `variant`'s spheres appended: `default` material, radius 4% of the
// eye-to-look distance, beside `camera`'s look point, where the camera sees them.
std::string sceneVariant(const std::string &text, const Camera &camera, uint32_t variant);

} // namespace prism
