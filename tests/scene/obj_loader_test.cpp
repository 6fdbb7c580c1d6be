// The OBJ reader (engine/scene/obj_loader.cpp): statements, index forms, errors at OBJ lines.
#include <gtest/gtest.h>

#include "expect_file_error.h"
#include "scene/obj_loader.h"

namespace prism {
namespace {

using test::expectFileError;

void expectObjError(const std::string &text, int line, const std::string &fragment) {
    SCOPED_TRACE(text);
    expectFileError([&] { parseObj(text, "model.obj"); }, "model.obj", line, fragment);
}

TEST(ObjLoader, ReadsVerticesTextureCoordinatesAndNormals) {
    ObjModel m = parseObj("v 1 2 3\nv 4 5 6 1.0\nv 7 8 9 0.1 0.2 0.3\n"
                          "vt 0.25 0.75\nvt 0.5 0.5 0\nvt 0.125\nvn 0 0 2\n",
                          "m.obj");
    ASSERT_EQ(m.positions.size(), 3u); // w and vertex colours ignored
    EXPECT_EQ(m.positions[2], glm::vec3(7, 8, 9));
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[0], glm::vec2(0.25f, 0.75f));
    EXPECT_EQ(m.uvs[2], glm::vec2(0.125f, 0.0f)); // v defaults to 0
    ASSERT_EQ(m.normals.size(), 1u);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 2)); // normalised later, after placing
}

TEST(ObjLoader, ReadsAllFourCornerFormsAndNegativeIndices) {
    ObjModel m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                          "f 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/3/1\n"
                          "f -3/-3/-1 -2/-2/-1 -1/-1/-1\n",
                          "m.obj");
    ASSERT_EQ(m.faces.size(), 5u);
    ASSERT_EQ(m.corners.size(), 15u);
    EXPECT_EQ(m.corners[0].uv, kObjNoIndex);
    EXPECT_EQ(m.corners[0].normal, kObjNoIndex);
    EXPECT_EQ(m.corners[4].uv, 1);
    EXPECT_EQ(m.corners[4].normal, kObjNoIndex);
    EXPECT_EQ(m.corners[7].uv, kObjNoIndex);
    EXPECT_EQ(m.corners[7].normal, 0);
    for (int face = 3; face < 5; ++face)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(m.corners[face * 3 + c].position, c);
            EXPECT_EQ(m.corners[face * 3 + c].uv, c);
            EXPECT_EQ(m.corners[face * 3 + c].normal, 0);
        }
}

TEST(ObjLoader, NegativeIndicesAreRelativeToTheVerticesSoFar) {
    ObjModel m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -3\nv 0 0 1\nf -1 -2 -3\n", "m.obj");
    EXPECT_EQ(m.corners[0].position, 2);
    EXPECT_EQ(m.corners[3].position, 3);
    EXPECT_EQ(m.corners[5].position, 1);
}

TEST(ObjLoader, PolygonsKeepAllCornersAndTheirLine) {
    ObjModel m = parseObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\nf 1 2 3 4\n", "m.obj");
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].cornerCount, 4u);
    EXPECT_EQ(m.faces[0].line, 6);
}

TEST(ObjLoader, UsemtlAndMtllibLines) {
    ObjModel m = parseObj("mtllib my lib.mtl\nmtllib ..\\mats\\x.mtl\nv 0 0 0\nv 1 0 0\n"
                          "v 0 1 0\nf 1 2 3\nusemtl red paint\nf 1 2 3\nusemtl\nf 1 2 3\n",
                          "m.obj");
    ASSERT_EQ(m.mtlLibs.size(), 2u);
    EXPECT_EQ(m.mtlLibs[0].path, "my lib.mtl");
    EXPECT_EQ(m.mtlLibs[1].path, "../mats/x.mtl");
    EXPECT_EQ(m.mtlLibs[1].line, 2);
    ASSERT_EQ(m.useMtl.size(), 2u);
    EXPECT_EQ(m.useMtl[0].name, "red paint");
    EXPECT_EQ(m.useMtl[0].line, 7);
    EXPECT_EQ(m.useMtl[1].name, "");
    EXPECT_EQ(m.faces[0].materialSlot, kObjNoIndex);
    EXPECT_EQ(m.faces[1].materialSlot, 0);
    EXPECT_EQ(m.faces[2].materialSlot, 1);
}

TEST(ObjLoader, IgnoresStatementsARayTracerDoesNotUse) {
    ObjModel m = parseObj("o thing\ng a b\ns 1\ns off\nv 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 1\n"
                          "vp 0.5\ncstype bspline\ndeg 3\ncurv 0 1 1 2\nend\nvw 1 2\n"
                          "weird stuff here\nf 1 2 3\n",
                          "m.obj");
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.faces.size(), 1u);
}

TEST(ObjLoader, CrlfCommentsAndNoFinalNewline) {
    ObjModel m =
        parseObj("# c\r\nv 0 0 0 # trailing\r\nv\t1 0 0\r\nv 0 1 0\r\nf -3 -2 -1", "m.obj");
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.faces.size(), 1u);
}

TEST(ObjLoader, BadVerticesAreErrorsAtTheirLine) {
    expectObjError("v 0 0 0\nv 1 nan 0\n", 2, "bad number 'nan'");
    expectObjError("v 1 2 inf\n", 1, "bad number 'inf'");
    expectObjError("v 1 2 1e39\n", 1, "out of range");
    expectObjError("v 1 2\n", 1, "a vertex needs 3 numbers, got 2");
    expectObjError("v 1 2 3abc\n", 1, "bad number '3abc'");
    expectObjError("vt\n", 1, "a texture coordinate needs 1 number, got 0");
    expectObjError("vt 0.5 nan\n", 1, "bad number 'nan'");
    expectObjError("vn 0 1\n", 1, "a normal needs 3 numbers");
}

TEST(ObjLoader, BadFacesAreErrorsAtTheirLine) {
    const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expectObjError(three + "f 1 2 0\n", 4, "face index 0 is out of range (3 vertices defined");
    expectObjError(three + "f 1 2 4\n", 4, "face index 4 is out of range");
    expectObjError(three + "f -4 1 2\n", 4, "face index -4 is out of range");
    expectObjError("f 1 2 3\n" + three, 1, "face index 1 is out of range (0 vertices");
    expectObjError(three + "f 1 2\n", 4, "a face needs at least 3 vertices, got 2");
    expectObjError(three + "vt 0 0\nf 1/0 2/1 3/1\n", 5, "face texture coordinate index 0");
    expectObjError(three + "vn 0 0 1\nf 1//1 2//0 3//1\n", 5, "face normal index 0");
    expectObjError(three + "f 1 2 3.5\n", 4, "bad face index '3.5'");
    expectObjError(three + "f 1 2 3/\n", 4, "bad face corner '3/'");
    expectObjError(three + "f 1 2 3/1/1/1\n", 4, "bad face corner");
    expectObjError(three + "f 1 2 /1\n", 4, "bad face corner");
}

// Faces naming texture coordinates or normals that are not there (their vt or vn lines taken
// out) load as tinyobjloader and Blender load them: those corners go without, and the first such
// index of each kind is a warning at its line. Positions stay errors (above).
TEST(ObjLoader, MissingNormalsAndTextureCoordinatesAreWarnedOnce) {
    ObjModel m =
        parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\n"
                 "f 1//1 2//2 3//3\nf 1//4 2//5 3//6\nf 1/1 2/2 3/1\nf 3/1/7 2/9/1 1/1/1\n",
                 "model.obj");
    ASSERT_EQ(m.faces.size(), 4u);
    for (const ObjCorner &c : m.corners)
        EXPECT_EQ(c.normal, kObjNoIndex);
    EXPECT_EQ(m.corners[6].uv, 0);
    EXPECT_EQ(m.corners[7].uv, kObjNoIndex);
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_EQ(m.warnings[0], "model.obj:5: warning: face normal index 1 is out of range (0 "
                             "normals defined so far); such corners go without (warned once)");
    EXPECT_NE(m.warnings[1].find("model.obj:7: warning: face texture coordinate index 2 is out "
                                 "of range (1 texture coordinates"),
              std::string::npos)
        << m.warnings[1];
}

} // namespace
} // namespace prism
