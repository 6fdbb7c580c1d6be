#include "scene/directive_values.h"

#include "scene/diagnostics.h"
#include "scene/number_parser.h"

namespace prism {
namespace {

// The value of a parsed number token, or the line's error saying what is wrong with it.
template <typename Parsed> auto valueOf(const Parsed &parsed, const Token *token) {
    if (!parsed.ok())
        throw LineError(describeBadNumber(token->text, parsed.problem));
    return parsed.value;
}

} // namespace

float number(const Token *token) {
    return valueOf(parseFloat(token->text), token);
}

double coordinate(const Token *token) {
    return valueOf(parseDouble(token->text), token);
}

glm::vec3 vec3At(const Values &values, size_t first) {
    return {number(values[first]), number(values[first + 1]), number(values[first + 2])};
}

glm::dvec3 pointAt(const Values &values, size_t first) {
    return {coordinate(values[first]), coordinate(values[first + 1]),
            coordinate(values[first + 2])};
}

std::string formatted(glm::dvec3 v) {
    return formatNumber(v.x) + " " + formatNumber(v.y) + " " + formatNumber(v.z);
}

void checkCameraView(const Camera &camera, const std::string &what) {
    if (camera.eye == camera.look)
        throw LineError(what + " eye and look must differ");
    glm::dvec3 forward = glm::normalize(camera.look - camera.eye);
    glm::dvec3 up(camera.up);
    // sin(angle between up and the view direction) below 1e-6 leaves no usable right vector.
    if (glm::length(glm::cross(forward, up)) <= 1e-6 * glm::length(up))
        throw LineError(what + " up " + formatted(camera.up) +
                        " must not be zero or parallel to the view direction");
}

namespace {

int rotationAxis(const Token *token) {
    if (token->text == "x" || token->text == "y" || token->text == "z")
        return token->text[0] - 'x';
    throw LineError("rotate axis must be x, y or z, got '" + token->text + "'");
}

} // namespace

bool placementValue(const KeyedValues &kv, MeshTransform &transform) {
    if (kv.key == "scale") {
        transform.scale = number(kv.values[0]);
        if (!(transform.scale > 0.0))
            throw LineError("'scale' must be > 0, got " + formatNumber(transform.scale));
    } else if (kv.key == "rotate") {
        transform.rotations.push_back(
            MeshRotation{rotationAxis(kv.values[0]), number(kv.values[1])});
    } else if (kv.key == "translate") {
        transform.translation = pointAt(kv.values);
    } else {
        return false;
    }
    return true;
}

} // namespace prism
