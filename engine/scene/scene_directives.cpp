// One handler per .scene directive (format v1.2, docs/scene-format.md); the animation
// directives are in animation_directives.cpp.
#include "scene/scene_parser.h"

#include "core/error.h"
#include "scene/animation_directives.h"
#include "scene/diagnostics.h"
#include "scene/directive_args.h"
#include "scene/directive_values.h"
#include "scene/mesh_importer.h"
#include "scene/number_parser.h"
#include "scene/obj_cache.h"
#include "scene/obj_loader.h"
#include "scene/placement.h"
#include "scene/text_file.h"

#include <cmath>
#include <map>

namespace prism {
namespace {

float nonNegative(std::string_view what, float value) {
    if (value < 0.0f)
        throw LineError("'" + std::string(what) + "' must not be negative, got " +
                        formatNumber(value));
    return value;
}

glm::vec3 nonNegativeColour(std::string_view what, glm::vec3 colour) {
    if (colour.x < 0.0f || colour.y < 0.0f || colour.z < 0.0f)
        throw LineError("'" + std::string(what) + "' must not be negative, got " +
                        formatted(colour));
    return colour;
}

uint32_t materialNamed(const SceneBuilder &builder, const Token *name) {
    auto found = builder.materialByName.find(name->text);
    if (found == builder.materialByName.end())
        throw LineError("unknown material '" + name->text + "'");
    return found->second;
}

// The optional trailing NAME of a primitive, or the current material.
uint32_t primitiveMaterial(const SceneBuilder &builder, const DirectiveArgs &args,
                           size_t nameIndex) {
    return args.positional.size() > nameIndex ? materialNamed(builder, args.positional[nameIndex])
                                              : builder.currentMaterial;
}

void addTriangle(SceneBuilder &builder, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, uint32_t material,
                 int &dropped) {
    if (hasZeroArea(a, b, c)) {
        ++dropped;
        return;
    }
    Triangle t;
    t.p[0] = a;
    t.p[1] = b;
    t.p[2] = c;
    t.material = material;
    checkTriangleLimit(builder.heldTriangles() + 1, builder.limits.maxTriangles);
    builder.scene.triangles.push_back(t);
}

void warnDropped(SceneBuilder &builder, int dropped, const std::string &where) {
    if (dropped > 0)
        builder.warn(std::to_string(dropped) + " degenerate (zero-area) triangle" +
                     (dropped == 1 ? "" : "s") + where + " dropped");
}

void camera(SceneBuilder &builder, const DirectiveArgs &args) {
    if (builder.cameraLine != 0)
        throw LineError("only one camera is allowed (the first is at line " +
                        std::to_string(builder.cameraLine) + ")");
    const KeyedValues *eye = args.find("eye");
    const KeyedValues *look = args.find("look");
    if (!eye || !look)
        throw LineError(std::string("camera needs '") + (eye ? "look" : "eye") + " X Y Z'");
    Camera camera;
    camera.eye = pointAt(eye->values);
    camera.look = pointAt(look->values);
    if (const KeyedValues *up = args.find("up"))
        camera.up = vec3At(up->values);
    if (const KeyedValues *fov = args.find("fov")) {
        camera.fovDegrees = number(fov->values[0]);
        if (!(camera.fovDegrees > 0.0f && camera.fovDegrees < 180.0f))
            throw LineError("camera fov must be between 0 and 180 degrees (exclusive), got " +
                            formatNumber(camera.fovDegrees));
    }
    if (const KeyedValues *ortho = args.find("ortho")) {
        camera.orthoHeight = number(ortho->values[0]);
        if (!(camera.orthoHeight > 0.0f))
            throw LineError("camera ortho height must be > 0, got " +
                            formatNumber(camera.orthoHeight));
    }
    checkCameraView(camera, "camera");
    builder.scene.camera = camera;
    builder.cameraLine = builder.line;
}

void background(SceneBuilder &builder, const DirectiveArgs &args) {
    builder.scene.background = nonNegativeColour("background", vec3At(args.positional));
}

void environment(SceneBuilder &builder, const DirectiveArgs &args) {
    if (builder.environmentLine != 0)
        throw LineError("only one environment is allowed (the first is at line " +
                        std::to_string(builder.environmentLine) + ")");
    Environment e;
    if (const KeyedValues *intensity = args.find("intensity"))
        e.intensity = nonNegative("intensity", number(intensity->values[0]));
    if (const KeyedValues *rotate = args.find("rotate"))
        e.rotateDegrees = number(rotate->values[0]);
    e.texture = builder.textures.load(resolveInputPath(builder.baseDir, args.positional[0]->text),
                                      builder.scene);
    builder.scene.environment = e;
    builder.environmentLine = builder.line;
}

void ambient(SceneBuilder &builder, const DirectiveArgs &args) {
    builder.scene.ambient = nonNegativeColour("ambient", vec3At(args.positional));
}

void light(SceneBuilder &builder, const DirectiveArgs &args) {
    Light light;
    light.position = pointAt(args.positional);
    if (const KeyedValues *color = args.find("color"))
        light.color = nonNegativeColour("color", vec3At(color->values));
    if (const KeyedValues *radius = args.find("radius"))
        light.radius = nonNegative("radius", number(radius->values[0]));
    builder.scene.lights.push_back(light);
}

int32_t loadTexture(SceneBuilder &builder, const KeyedValues &kv, TexelMeaning meaning) {
    return builder.textures.load(resolveInputPath(builder.baseDir, kv.values[0]->text),
                                 builder.scene, meaning);
}

void material(SceneBuilder &builder, const DirectiveArgs &args) {
    const std::string &name = args.positional[0]->text;
    if (auto earlier = builder.materialLine.find(name); earlier != builder.materialLine.end())
        throw LineError("material '" + name + "' is already defined" +
                        (earlier->second == 0 ? std::string(" (built in)")
                                              : " at line " + std::to_string(earlier->second)));
    Material m;
    m.name = name;
    for (const KeyedValues &kv : args.keyed) {
        if (kv.key == "color")
            m.color = nonNegativeColour(kv.key, vec3At(kv.values));
        else if (kv.key == "ambient")
            m.ambient = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "diffuse")
            m.diffuse = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "specular")
            m.specular = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "shininess")
            m.shininess = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "reflect")
            m.reflect = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "transmit")
            m.transmit = nonNegative(kv.key, number(kv.values[0]));
        else if (kv.key == "ior") {
            m.ior = number(kv.values[0]);
            if (!(m.ior > 0.0f))
                throw LineError("'ior' must be > 0, got " + formatNumber(m.ior));
        } else if (kv.key == "texture")
            m.texture = loadTexture(builder, kv, TexelMeaning::Colour);
        else if (kv.key == "norm")
            m.normalMap = loadTexture(builder, kv, TexelMeaning::Data);
        else if (kv.key == "bump")
            m.bumpMap = loadTexture(builder, kv, TexelMeaning::Data);
        else if (kv.key == "bm")
            m.bumpScale = number(kv.values[0]);
    }
    if (args.find("bm") && m.bumpMap == kNoTexture)
        throw LineError("'bm' scales a bump map: it needs 'bump PATH' on the same line");
    builder.scene.materials.push_back(std::move(m));
    uint32_t index = uint32_t(builder.scene.materials.size() - 1);
    builder.materialByName[name] = index;
    builder.materialLine[name] = builder.line;
}

void use(SceneBuilder &builder, const DirectiveArgs &args) {
    builder.currentMaterial = materialNamed(builder, args.positional[0]);
}

void sphere(SceneBuilder &builder, const DirectiveArgs &args) {
    Sphere s;
    s.center = pointAt(args.positional);
    s.radius = number(args.positional[3]);
    if (!(s.radius > 0.0f))
        throw LineError("sphere radius must be > 0, got " + formatNumber(s.radius));
    s.material = primitiveMaterial(builder, args, 4);
    builder.scene.spheres.push_back(s);
}

void plane(SceneBuilder &builder, const DirectiveArgs &args) {
    Plane p;
    p.point = pointAt(args.positional);
    glm::dvec3 normal(vec3At(args.positional, 3));
    double length = glm::length(normal);
    if (length == 0.0)
        throw LineError("plane normal must not be zero");
    p.normal = glm::vec3(normal / length);
    p.material = primitiveMaterial(builder, args, 6);
    builder.scene.planes.push_back(p);
}

void triangle(SceneBuilder &builder, const DirectiveArgs &args) {
    uint32_t material = primitiveMaterial(builder, args, 9);
    int dropped = 0;
    addTriangle(builder, pointAt(args.positional, 0), pointAt(args.positional, 3),
                pointAt(args.positional, 6), material, dropped);
    warnDropped(builder, dropped, "");
}

void vertex(SceneBuilder &builder, const DirectiveArgs &args) {
    builder.faceVertices.push_back(pointAt(args.positional));
}

// 1-based, or negative = relative to the last `v` so far (as in OBJ).
glm::dvec3 faceVertex(const SceneBuilder &builder, const Token *token) {
    ParsedInteger parsed = parseInteger(token->text);
    if (!parsed.ok())
        throw LineError("bad vertex index '" + token->text + "'");
    int64_t count = int64_t(builder.faceVertices.size());
    int64_t index = parsed.value > 0 ? parsed.value - 1 : count + parsed.value;
    if (parsed.value == 0 || index < 0 || index >= count)
        throw LineError("face index " + std::to_string(parsed.value) + " is out of range (" +
                        std::to_string(count) + " vertices defined so far)");
    return builder.faceVertices[size_t(index)];
}

void face(SceneBuilder &builder, const DirectiveArgs &args) {
    if (args.positional.size() < 3)
        throw LineError("a face needs at least 3 vertices, got " +
                        std::to_string(args.positional.size()));
    std::vector<glm::dvec3> corners;
    for (const Token *token : args.positional)
        corners.push_back(faceVertex(builder, token));
    int dropped = 0;
    for (size_t k = 1; k + 1 < corners.size(); ++k) // fan around the first corner
        addTriangle(builder, corners[0], corners[k], corners[k + 1], builder.currentMaterial,
                    dropped);
    warnDropped(builder, dropped, "");
}

// `smooth` without an angle: facets meeting at more than 60 degrees stay sharp. A cube's edges
// (90) and a tetrahedron's (109) keep them; a sphere or teapot tessellated at 15-30 degrees a
// step, and the bunny's (mostly under 40), come out smooth.
constexpr double kDefaultCreaseDegrees = 60.0;

void checkNewPrototypeName(const SceneBuilder &builder, const std::string &name) {
    if (auto earlier = builder.prototypeByName.find(name); earlier != builder.prototypeByName.end())
        throw LineError("prototype '" + name + "' is already defined at line " +
                        std::to_string(earlier->second.line));
}

// `mesh ... as ID`: the placed mesh's triangles, centred on their bounding box, become a
// prototype that only `place` lines draw. One without triangles is remembered (so that its
// `place` lines can say so) but not added to Scene::prototypes.
void definePrototype(SceneBuilder &builder, const std::string &name,
                     std::vector<Triangle> triangles, std::vector<TriangleShading> shading) {
    PrototypeEntry entry;
    entry.line = builder.line;
    if (!triangles.empty()) {
        glm::dvec3 lo = triangles[0].p[0], hi = lo;
        for (const Triangle &t : triangles)
            for (const glm::dvec3 &p : t.p) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        entry.centre = 0.5 * lo + 0.5 * hi;
        for (Triangle &t : triangles)
            for (glm::dvec3 &p : t.p)
                p -= entry.centre;
        entry.boxMin = lo - entry.centre; // rounded as the vertex it came from: still the box
        entry.boxMax = hi - entry.centre;
        entry.index = uint32_t(builder.scene.prototypes.size());
        builder.prototypeTriangles += triangles.size();
        builder.scene.prototypes.push_back(
            MeshPrototype{name, std::move(triangles), std::move(shading)});
    }
    builder.prototypeByName.emplace(name, entry);
}

void mesh(SceneBuilder &builder, const DirectiveArgs &args) {
    const KeyedValues *as = args.find("as");
    if (as)
        checkNewPrototypeName(builder, as->values[0]->text);
    MeshRequest request;
    request.objPath = resolveInputPath(builder.baseDir, args.positional[0]->text);
    request.objName = displayPath(resolveInputPath("", args.positional[0]->text));
    if (args.positional.size() > 1)
        request.namedMaterial = materialNamed(builder, args.positional[1]);
    request.fallbackMaterial = builder.currentMaterial;
    for (const KeyedValues &kv : args.keyed) {
        if (placementValue(kv, request.transform))
            continue;
        if (kv.key == "smooth") {
            double crease = kv.values.empty() ? kDefaultCreaseDegrees : number(kv.values[0]);
            if (!(crease >= 0.0 && crease <= 180.0))
                throw LineError("'smooth' crease angle must be between 0 and 180 degrees, got " +
                                formatNumber(crease));
            request.smoothCreaseDegrees = crease;
        }
    }
    LoadedObjModel loaded =
        loadObjFile(request.objPath, displayPath(request.objPath), builder.objCache);
    const ObjModelView &model = loaded.view();
    builder.scene.warnings.insert(builder.scene.warnings.end(), model.warnings.begin(),
                                  model.warnings.end());
    std::vector<Triangle> prototype;
    std::vector<TriangleShading> prototypeShading;
    TriangleSink sink{as ? prototype : builder.scene.triangles,
                      as ? prototypeShading : builder.scene.triangleShading,
                      builder.heldTriangles(), builder.limits.maxTriangles};
    MeshImportResult result =
        builder.meshes.import(model, request, builder.scene, builder.textures, sink);
    warnDropped(builder, int(result.degenerateDropped),
                " in '" + displayPath(request.objPath) + "'");
    if (as)
        definePrototype(builder, as->values[0]->text, std::move(prototype),
                        std::move(prototypeShading));
}

// `place ID [NAME] ...`: one instance of the prototype (scene/placement.h: placedInstance). The
// place line stays open for `key` lines under it, which move the instance.
void place(SceneBuilder &builder, const DirectiveArgs &args) {
    const std::string &name = args.positional[0]->text;
    auto found = builder.prototypeByName.find(name);
    if (found == builder.prototypeByName.end())
        throw LineError("unknown prototype '" + name + "' (a 'mesh PATH ... as " + name +
                        "' line above it defines one)");
    const PrototypeEntry &entry = found->second;
    int32_t material = kOwnMaterials;
    if (args.positional.size() > 1)
        material = int32_t(materialNamed(builder, args.positional[1]));
    MeshTransform transform;
    for (const KeyedValues &kv : args.keyed)
        placementValue(kv, transform);
    OpenPlacement open;
    open.prototype = name;
    open.track.centre = entry.centre;
    open.track.boxMin = entry.boxMin;
    open.track.boxMax = entry.boxMax;
    open.track.keys.push_back(PlacementKey{1.0, transform, builder.line});
    builder.lastPlace = open;
    if (!entry.index) {
        builder.warn("prototype '" + name + "' (line " + std::to_string(entry.line) +
                     ") has no triangles; nothing is placed");
        return;
    }
    Instance instance = placedInstance(transform, entry.centre);
    instance.prototype = *entry.index;
    instance.material = material;
    if (std::string problem = placementProblem(instance, entry.boxMin, entry.boxMax, name);
        !problem.empty())
        throw LineError(problem);
    checkInstanceLimit(builder.scene.instances.size() + 1, builder.limits.maxInstances);
    builder.lastPlace->track.instance = uint32_t(builder.scene.instances.size());
    builder.lastPlace->track.first = instance;
    builder.lastPlace->placed = true;
    builder.scene.instances.push_back(instance);
}

struct Directive {
    DirectiveSpec spec;
    void (*apply)(SceneBuilder &, const DirectiveArgs &);
};

const std::map<std::string_view, Directive> &directives() {
    constexpr int kAny = DirectiveSpec::kUnlimited;
    static const std::map<std::string_view, Directive> table = {
        {"camera",
         {{"camera",
           "camera eye X Y Z look X Y Z [up X Y Z] [fov DEG] [ortho HEIGHT]",
           0,
           0,
           {{"eye", 3}, {"look", 3}, {"up", 3}, {"fov", 1}, {"ortho", 1}}},
          camera}},
        {"background", {{"background", "background R G B", 3, 3, {}}, background}},
        {"ambient", {{"ambient", "ambient R G B", 3, 3, {}}, ambient}},
        {"environment",
         {{"environment",
           "environment PATH [intensity K] [rotate DEG]",
           1,
           1,
           {{"intensity", 1}, {"rotate", 1}}},
          environment}},
        {"light",
         {{"light", "light X Y Z [color R G B] [radius R]", 3, 3, {{"color", 3}, {"radius", 1}}},
          light}},
        {"material",
         {{"material",
           "material NAME [color R G B] [ambient K] [diffuse K] [specular K] [shininess N] "
           "[reflect K] [transmit K] [ior N] [texture PATH] [norm PATH] [bump PATH] [bm K]",
           1,
           1,
           {{"color", 3},
            {"ambient", 1},
            {"diffuse", 1},
            {"specular", 1},
            {"shininess", 1},
            {"reflect", 1},
            {"transmit", 1},
            {"ior", 1},
            {"texture", 1},
            {"norm", 1},
            {"bump", 1},
            {"bm", 1}}},
          material}},
        {"use", {{"use", "use NAME", 1, 1, {}}, use}},
        {"sphere", {{"sphere", "sphere X Y Z RADIUS [NAME]", 4, 5, {}}, sphere}},
        {"plane", {{"plane", "plane X Y Z NX NY NZ [NAME]", 6, 7, {}}, plane}},
        {"triangle",
         {{"triangle", "triangle X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3 [NAME]", 9, 10, {}}, triangle}},
        {"v", {{"v", "v X Y Z", 3, 3, {}}, vertex}},
        {"f", {{"f", "f A B C [D ...]", 0, kAny, {}}, face}},
        {"mesh",
         {{"mesh",
           "mesh PATH [NAME] [scale S] [rotate AXIS DEG]... [translate X Y Z] [smooth [ANGLE]] "
           "[as ID]",
           1,
           2,
           {{"scale", 1},
            {"rotate", 2, true},
            {"translate", 3},
            {"smooth", 0, false, 1},
            {"as", 1}}},
          mesh}},
        {"place",
         {{"place",
           "place ID [NAME] [scale S] [rotate AXIS DEG]... [translate X Y Z]",
           1,
           2,
           {{"scale", 1}, {"rotate", 2, true}, {"translate", 3}}},
          place}},
        {"key", {kCameraKeySpec, cameraKey}},
        {"turntable", {kTurntableSpec, turntable}},
        {"interpolate", {kInterpolateSpec, interpolate}},
    };
    return table;
}

} // namespace

void applyDirective(SceneBuilder &builder, std::span<const Token> tokens) {
    const Token &keyword = tokens[0];
    auto found = keyword.quoted ? directives().end() : directives().find(keyword.text);
    if (found == directives().end())
        throw LineError("unknown directive '" + keyword.text + "'");
    const Directive &directive = found->second;
    if (directive.spec.keyword == "key") {
        // A key animates the camera or place line above it (other keys between): its keys are
        // that line's.
        if (builder.keyTarget.empty())
            throw LineError("'key' must follow the camera line, a place line or another key (it "
                            "animates the line above it)");
        if (builder.keyTarget == "place")
            placeKey(builder, splitDirectiveArgs(kPlaceKeySpec, tokens.subspan(1)));
        else
            cameraKey(builder, splitDirectiveArgs(kCameraKeySpec, tokens.subspan(1)));
        return;
    }
    directive.apply(builder, splitDirectiveArgs(directive.spec, tokens.subspan(1)));
    bool animatable = directive.spec.keyword == "camera" || directive.spec.keyword == "place";
    builder.keyTarget = animatable ? directive.spec.keyword : std::string_view();
}

} // namespace prism
