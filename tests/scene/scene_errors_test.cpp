// Every way a .scene line can be wrong stops loading with "FILE:LINE: what is wrong"
// (engine/scene/scene_parser.cpp, scene_directives.cpp, directive_args.cpp).
#include <gtest/gtest.h>

#include "expect_file_error.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace prism {
namespace {

using test::expectFileError;
using test::TempDir;

constexpr const char *kFile = "dir/errors.scene";

// `text`'s line `line` must be reported with a message containing `fragment`.
void expectError(const std::string &text, int line, const std::string &fragment) {
    SCOPED_TRACE(text);
    expectFileError([&] { parseScene(text, kFile); }, kFile, line, fragment);
}

TEST(SceneErrors, UnknownDirectiveIsReportedAtItsLine) {
    expectError("# comment\n\nsphere 0 0 0 1\nspehre 0 0 0 1\n", 4, "unknown directive 'spehre'");
    expectError("Sphere 0 0 0 1\n", 1, "unknown directive 'Sphere'"); // keywords are lower case
    expectError("\"sphere\" 0 0 0 1\n", 1, "unknown directive");
}

TEST(SceneErrors, LineNumbersCountCrlfLines) {
    expectError("sphere 0 0 0 1\r\n\r\nsphere 0 0 0\r\n", 3, "missing argument");
}

TEST(SceneErrors, MissingAndExtraArguments) {
    expectError("sphere 0 0 0\n", 1, "missing argument (usage: sphere X Y Z RADIUS [NAME])");
    expectError("sphere 0 0 0 1 default extra\n", 1, "extra argument 'extra'");
    expectError("plane 0 0 0 0 1\n", 1, "missing argument");
    expectError("triangle 0 0 0 1 0 0 0 1\n", 1, "missing argument");
    expectError("background 1 1\n", 1, "missing argument");
    expectError("background 1 1 1 1\n", 1, "extra argument '1'");
    expectError("ambient 1 1 1 1\n", 1, "extra argument");
    expectError("light 1 1\n", 1, "missing argument");
    expectError("light 1 1 1 1\n", 1, "extra argument '1'");
    expectError("material\n", 1, "missing argument");
    expectError("use\n", 1, "missing argument");
    expectError("use a b\n", 1, "extra argument 'b'");
    expectError("v 1 2\n", 1, "missing argument");
    expectError("v 1 2 3 4\n", 1, "extra argument '4'");
    expectError("mesh\n", 1, "missing argument");
    expectError("camera\n", 1, "camera needs 'eye X Y Z'");
    expectError("camera eye 0 0 1\n", 1, "camera needs 'look X Y Z'");
}

TEST(SceneErrors, UnknownKeyDuplicateKeyAndShortKey) {
    expectError("light 0 0 0 colour 1 1 1\n", 1, "unknown key 'colour' for 'light'");
    expectError("camera eye 0 0 1 look 0 0 0 Fov 40\n", 1, "unknown key 'Fov'");
    expectError("material m color 1 1 1 shine 3\n", 1, "unknown key 'shine'");
    expectError("camera eye 0 0 1 look 0 0 0 fov 40 fov 50\n", 1, "'fov' is given twice");
    expectError("light 0 0 0 color 1 1 radius 1\n", 1, "'color' needs 3 values");
    expectError("material m ior\n", 1, "'ior' needs 1 value");
}

TEST(SceneErrors, BadNumbers) {
    expectError("sphere 0 0 zero 1\n", 1, "bad number 'zero': not a decimal number");
    expectError("sphere 0 0 0 1.0abc\n", 1, "bad number '1.0abc'");
    expectError("light nan 0 0\n", 1, "bad number 'nan': NaN and infinity are not allowed");
    expectError("light inf 0 0\n", 1, "bad number 'inf'");
    expectError("background 1e39 0 0\n", 1, "bad number '1e39': out of range for a 32-bit float");
    expectError("material m shininess 1e39\n", 1, "out of range");
    expectError("camera eye 0 0 1 look 0 0 0 fov 0x20\n", 1, "bad number '0x20'");
}

TEST(SceneErrors, CameraChecks) {
    expectError("camera eye 1 2 3 look 1 2 3\n", 1, "camera eye and look must differ");
    expectError("camera eye 0 0 0 look 0 5 0\n", 1, "must not be zero or parallel");
    expectError("camera eye 0 0 0 look 0 -5 0 up 0 2 0\n", 1, "parallel to the view direction");
    expectError("camera eye 0 0 5 look 0 0 0 up 0 0 0\n", 1, "must not be zero");
    expectError("camera eye 0 0 5 look 0 0 0 fov 0\n", 1, "fov must be between 0 and 180");
    expectError("camera eye 0 0 5 look 0 0 0 fov 180\n", 1, "fov must be between 0 and 180");
    expectError("camera eye 0 0 5 look 0 0 0 fov -30\n", 1, "got -30");
    expectError("camera eye 0 0 5 look 0 0 0 ortho 0\n", 1, "ortho height must be > 0, got 0");
    expectError("camera eye 0 0 5 look 0 0 0 ortho -2\n", 1, "ortho height must be > 0");
    expectError("camera eye 0 0 5 look 0 0 0\n\ncamera eye 0 0 6 look 0 0 0\n", 3,
                "only one camera is allowed (the first is at line 1)");
}

TEST(SceneErrors, PrimitiveChecks) {
    expectError("sphere 0 0 0 0\n", 1, "sphere radius must be > 0, got 0");
    expectError("sphere 0 0 0 -1\n", 1, "sphere radius must be > 0, got -1");
    expectError("plane 0 0 0 0 0 0\n", 1, "plane normal must not be zero");
}

TEST(SceneErrors, MaterialNamesAndValues) {
    expectError("material a\nmaterial a\n", 2, "material 'a' is already defined at line 1");
    expectError("material default color 1 0 0\n", 1, "'default' is already defined (built in)");
    expectError("use red\n", 1, "unknown material 'red'");
    expectError("sphere 0 0 0 1 red\n", 1, "unknown material 'red'");
    expectError("plane 0 0 0 0 1 0 red\n", 1, "unknown material 'red'");
    expectError("triangle 0 0 0 1 0 0 0 1 0 red\n", 1, "unknown material 'red'");
    expectError("material Red\nuse red\n", 2, "unknown material 'red'"); // names are exact
    expectError("material m ior 0\n", 1, "'ior' must be > 0, got 0");
    expectError("material m ior -1.5\n", 1, "'ior' must be > 0");
    for (const char *key : {"ambient", "diffuse", "specular", "shininess", "reflect", "transmit"})
        expectError(std::string("material m ") + key + " -0.5\n", 1,
                    std::string("'") + key + "' must not be negative, got -0.5");
    expectError("material m color 1 -1 0\n", 1, "'color' must not be negative, got 1 -1 0");
    expectError("\nmaterial m bm 0.5\n", 2,
                "'bm' scales a bump map: it needs 'bump PATH' on the same line");
    expectError("material m bm x bump h.png\n", 1, "bad number 'x'");
    expectError("material m bump\n", 1, "'bump' needs 1 value");
}

TEST(SceneErrors, NegativeColoursAndRadiusElsewhere) {
    expectError("background 0 0 -0.1\n", 1, "'background' must not be negative");
    expectError("ambient -1 0 0\n", 1, "'ambient' must not be negative");
    expectError("light 0 0 0 color 1 1 -1\n", 1, "'color' must not be negative");
    expectError("light 0 0 0 radius -1\n", 1, "'radius' must not be negative");
}

TEST(SceneErrors, FaceIndices) {
    const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expectError(verts + "f 1 2 4\n", 4, "face index 4 is out of range (3 vertices defined so far)");
    expectError(verts + "f 0 1 2\n", 4, "face index 0 is out of range");
    expectError(verts + "f -4 1 2\n", 4, "face index -4 is out of range");
    expectError("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", 1, "face index 1 is out of range");
    expectError(verts + "f 1 2\n", 4, "a face needs at least 3 vertices, got 2");
    expectError(verts + "f\n", 4, "a face needs at least 3 vertices, got 0");
    expectError(verts + "f 1 2 3.0\n", 4, "bad vertex index '3.0'");
    expectError(verts + "f 1 2 3/1\n", 4, "bad vertex index '3/1'");
}

TEST(SceneErrors, MeshTransformChecks) {
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::string scene = (dir.path() / "s.scene").string();
    auto expectMeshError = [&](const std::string &line, const std::string &fragment) {
        dir.write("s.scene", "# mesh\n" + line + "\n");
        expectFileError([&] { loadScene(scene); }, scene, 2, fragment);
    };
    expectMeshError("mesh tri.obj scale 0", "'scale' must be > 0, got 0");
    expectMeshError("mesh tri.obj scale -2", "'scale' must be > 0");
    expectMeshError("mesh tri.obj rotate w 90", "rotate axis must be x, y or z, got 'w'");
    expectMeshError("mesh tri.obj rotate X 90", "got 'X'");
    expectMeshError("mesh tri.obj rotate y", "'rotate' needs 2 values");
    expectMeshError("mesh tri.obj translate 1 2", "'translate' needs 3 values");
    expectMeshError("mesh tri.obj scale 2 scale 3", "'scale' is given twice");
    expectMeshError("mesh tri.obj nosuch", "unknown material 'nosuch'");
    expectMeshError("mesh tri.obj default extra", "unknown key 'extra' for 'mesh'");
    dir.write("tri.obj", "v 1e30 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expectMeshError("mesh tri.obj scale 1e30", "takes vertex 1 out of the range");
}

TEST(SceneErrors, UnreadableFilesAreErrorsOfTheLineThatNamesThem) {
    TempDir dir;
    std::string scene = (dir.path() / "s.scene").string();
    std::filesystem::create_directories(dir.path() / "adir");
    dir.write("s.scene", "sphere 0 0 0 1\nmesh missing.obj\n");
    expectFileError([&] { loadScene(scene); }, scene, 2, "cannot read OBJ file '");
    dir.write("s.scene", "mesh adir\n");
    expectFileError([&] { loadScene(scene); }, scene, 1, "it is a directory");
    dir.write("s.scene", "\nmaterial m texture missing.png\n");
    expectFileError([&] { loadScene(scene); }, scene, 2, "cannot read texture '");
    dir.write("s.scene", "sphere 0 0 0 1\nmaterial m norm missing.png\n");
    expectFileError([&] { loadScene(scene); }, scene, 2, "cannot read texture '");
    dir.write("s.scene", "\n\nmaterial m bump missing.png bm 2\n");
    expectFileError([&] { loadScene(scene); }, scene, 3, "missing.png");
    dir.write("not-an-image.png", "this is text");
    dir.write("s.scene", "material m texture not-an-image.png\n");
    expectFileError([&] { loadScene(scene); }, scene, 1, "not-an-image.png");
}

TEST(SceneErrors, ErrorsInsideAnObjAreReportedAtTheObjLine) {
    TempDir dir;
    dir.write("models/bad.obj", "# comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 0\n");
    std::filesystem::path scene = dir.write("scenes/s.scene", "mesh ../models/bad.obj\n");
    std::string objName = (dir.path() / "models/bad.obj").generic_string();
    expectFileError([&] { loadScene(scene); }, objName, 6, "face index 0 is out of range");
}

TEST(SceneErrors, QuotingErrors) {
    expectError("sphere 0 0 0 1\nmesh \"a b.obj\n", 2, "unterminated quoted string");
    expectError("mesh \"a\"b\n", 1, "quoted string must be followed by a space");
}

TEST(SceneErrors, AnUnreadableSceneFileIsAnError) {
    TempDir dir;
    try {
        loadScene(dir.path() / "nope.scene");
        ADD_FAILURE() << "no error";
    } catch (const FileError &e) {
        ADD_FAILURE() << "not a file:line error: " << e.what();
    } catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("cannot read scene file"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("nope.scene"), std::string::npos);
    }
}

} // namespace
} // namespace prism
