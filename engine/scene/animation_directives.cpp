#include "scene/animation_directives.h"

#include <string>

#include "scene/diagnostics.h"
#include "scene/directive_values.h"
#include "scene/number_parser.h"
#include "scene/placement.h"

namespace prism {

const DirectiveSpec kCameraKeySpec{
    "key",
    "key FRAME [eye X Y Z] [look X Y Z] [up X Y Z] [fov DEG] [ortho HEIGHT]",
    1,
    1,
    {{"eye", 3}, {"look", 3}, {"up", 3}, {"fov", 1}, {"ortho", 1}}};
const DirectiveSpec kPlaceKeySpec{"key",
                                  "key FRAME [scale S] [rotate AXIS DEG]... [translate X Y Z]",
                                  1,
                                  1,
                                  {{"scale", 1}, {"rotate", 2, true}, {"translate", 3}}};
const DirectiveSpec kTurntableSpec{"turntable",
                                   "turntable FRAMES [center X Y Z] [axis X Y Z] [degrees DEG]",
                                   1,
                                   1,
                                   {{"center", 3}, {"axis", 3}, {"degrees", 1}}};
const DirectiveSpec kInterpolateSpec{"interpolate", "interpolate linear|catmull-rom", 1, 1, {}};

namespace {

// A number no float-sized scene value can exceed: frames and degrees are read as doubles but
// must be finite (parseDouble refuses NaN and infinities).
double finiteNumber(const Token *token) {
    return coordinate(token);
}

// "the previous key's frame 4 (line 12)", or "frame 1 (the camera line's)" while the line that
// the keys animate has no key yet.
std::string previousKeyText(bool noKeyYet, double frame, int line, const char *frameOneLine) {
    if (noKeyYet)
        return std::string("frame 1 (") + frameOneLine + ")";
    return "the previous key's frame " + formatNumber(frame) + " (line " + std::to_string(line) +
           ")";
}

std::string axesText(const std::vector<MeshRotation> &rotations) {
    std::string text;
    for (const MeshRotation &r : rotations)
        text += std::string(text.empty() ? "" : ", ") + char('x' + r.axis);
    return text;
}

} // namespace

void cameraKey(SceneBuilder &builder, const DirectiveArgs &args) {
    if (builder.turntableLine != 0)
        throw LineError("the camera already turns by the turntable at line " +
                        std::to_string(builder.turntableLine) + "; keys and a turntable exclude "
                                                                "each other");
    std::vector<CameraKey> &keys = builder.scene.cameraAnimation.keys;
    CameraKey key;
    key.frame = finiteNumber(args.positional[0]);
    key.line = builder.line;
    double previous = keys.empty() ? 1.0 : keys.back().frame;
    if (!(key.frame > previous))
        throw LineError("key frame " + formatNumber(key.frame) + " must come after " +
                        previousKeyText(keys.empty(), previous, keys.empty() ? 0 : keys.back().line,
                                        "the camera line's") + ": keys go in time order");
    key.camera = keys.empty() ? builder.scene.camera : keys.back().camera;
    if (const KeyedValues *eye = args.find("eye"))
        key.camera.eye = pointAt(eye->values);
    if (const KeyedValues *look = args.find("look"))
        key.camera.look = pointAt(look->values);
    if (const KeyedValues *up = args.find("up"))
        key.camera.up = vec3At(up->values);
    if (const KeyedValues *fov = args.find("fov")) {
        if (key.camera.isOrtho())
            throw LineError("'fov' in a key of a parallel (ortho) camera: a key cannot change "
                            "the projection");
        key.camera.fovDegrees = number(fov->values[0]);
        if (!(key.camera.fovDegrees > 0.0f && key.camera.fovDegrees < 180.0f))
            throw LineError("key fov must be between 0 and 180 degrees (exclusive), got " +
                            formatNumber(key.camera.fovDegrees));
    }
    if (const KeyedValues *ortho = args.find("ortho")) {
        if (!key.camera.isOrtho())
            throw LineError("'ortho' in a key of a perspective camera: a key cannot change the "
                            "projection");
        key.camera.orthoHeight = number(ortho->values[0]);
        if (!(key.camera.orthoHeight > 0.0f))
            throw LineError("key ortho height must be > 0, got " +
                            formatNumber(key.camera.orthoHeight));
    }
    checkCameraView(key.camera, "key");
    keys.push_back(key);
}

void placeKey(SceneBuilder &builder, const DirectiveArgs &args) {
    OpenPlacement &open = *builder.lastPlace;
    std::vector<PlacementKey> &keys = open.track.keys; // keys[0]: the place line, frame 1
    PlacementKey key;
    key.frame = finiteNumber(args.positional[0]);
    key.line = builder.line;
    if (!(key.frame > keys.back().frame))
        throw LineError("key frame " + formatNumber(key.frame) + " must come after " +
                        previousKeyText(keys.size() == 1, keys.back().frame, keys.back().line,
                                        "the place line's") + ": keys go in time order");
    MeshTransform given;
    for (const KeyedValues &kv : args.keyed)
        placementValue(kv, given);
    key.transform = keys.back().transform;
    if (args.find("scale"))
        key.transform.scale = given.scale;
    if (args.find("translate"))
        key.transform.translation = given.translation;
    if (args.find("rotate")) {
        // Each angle is keyed on its own, so a key names every rotation of its place line.
        const std::vector<MeshRotation> &placed = keys.front().transform.rotations;
        bool sameAxes = given.rotations.size() == placed.size();
        for (size_t r = 0; sameAxes && r < placed.size(); ++r)
            sameAxes = given.rotations[r].axis == placed[r].axis;
        if (!sameAxes)
            throw LineError(
                placed.empty()
                    ? "the place line (line " + std::to_string(keys.front().line) +
                          ") has no rotate: a key turns only the rotations of its place line "
                          "(give it 'rotate AXIS 0' to start from)"
                    : "a key's rotations must be those of its place line (line " +
                          std::to_string(keys.front().line) + "), about " +
                          axesText(placed) + " in that order; this key gives " +
                          axesText(given.rotations));
        key.transform.rotations = given.rotations;
    }
    if (open.placed) {
        Instance instance = placedInstance(key.transform, open.track.centre);
        if (std::string problem = placementProblem(instance, open.track.boxMin,
                                                   open.track.boxMax, open.prototype);
            !problem.empty())
            throw LineError(problem);
    }
    keys.push_back(key);
    if (!open.placed)
        return;
    std::vector<PlacementTrack> &tracks = builder.scene.placementTracks;
    if (tracks.empty() || tracks.back().instance != open.track.instance)
        tracks.push_back(open.track);
    else
        tracks.back() = open.track;
}

void turntable(SceneBuilder &builder, const DirectiveArgs &args) {
    if (builder.turntableLine != 0)
        throw LineError("only one turntable is allowed (the first is at line " +
                        std::to_string(builder.turntableLine) + ")");
    if (builder.cameraLine == 0)
        throw LineError("'turntable' turns the camera line, which must come above it");
    if (!builder.scene.cameraAnimation.keys.empty())
        throw LineError("the camera already has keys (line " +
                        std::to_string(builder.scene.cameraAnimation.keys.front().line) +
                        "); keys and a turntable exclude each other");
    Turntable t;
    t.line = builder.line;
    t.frames = finiteNumber(args.positional[0]);
    if (!(t.frames > 0.0))
        throw LineError("turntable FRAMES must be > 0, got " + formatNumber(t.frames));
    const Camera &camera = builder.scene.camera;
    t.center = camera.look;
    t.axis = glm::dvec3(camera.up);
    if (const KeyedValues *center = args.find("center"))
        t.center = pointAt(center->values);
    if (const KeyedValues *axis = args.find("axis"))
        t.axis = pointAt(axis->values);
    if (!(glm::length(t.axis) > 0.0))
        throw LineError("turntable axis must not be zero");
    t.axis = glm::normalize(t.axis);
    if (const KeyedValues *degrees = args.find("degrees"))
        t.degrees = finiteNumber(degrees->values[0]);
    builder.scene.cameraAnimation.turntable = t;
    builder.turntableLine = builder.line;
}

void interpolate(SceneBuilder &builder, const DirectiveArgs &args) {
    if (builder.interpolateLine != 0)
        throw LineError("only one interpolate line is allowed (the first is at line " +
                        std::to_string(builder.interpolateLine) + ")");
    const std::string &mode = args.positional[0]->text;
    if (mode == "linear")
        builder.scene.keyInterpolation = KeyInterpolation::Linear;
    else if (mode == "catmull-rom")
        builder.scene.keyInterpolation = KeyInterpolation::CatmullRom;
    else
        throw LineError("interpolate takes 'linear' or 'catmull-rom', got '" + mode + "'");
    builder.interpolateLine = builder.line;
}

} // namespace prism
