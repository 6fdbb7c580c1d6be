// The MTL reader and its mapping to scene materials (engine/scene/mtl_loader.cpp).
#include <gtest/gtest.h>

#include "expect_file_error.h"
#include "scene/mtl_loader.h"

namespace prism {
namespace {

MtlLibrary parse(const std::string &text, std::vector<std::string> *warningsOut = nullptr) {
    std::vector<std::string> warnings;
    MtlLibrary library = parseMtl(text, "lib.mtl", warnings);
    if (warningsOut)
        *warningsOut = warnings;
    else
        EXPECT_TRUE(warnings.empty()) << warnings.front();
    return library;
}

TEST(MtlLoader, MapsTheStatementsTheSpecNames) {
    MtlLibrary lib = parse("newmtl shiny glass\n  Kd 0.5 0.25 1\n  Ks 0.3 0.6 0.9\n  Ns 64\n"
                           "  Ni 1.33\n  Tr 0.75\n  d 0.1\n  map_Kd tex.png\n  Ka 1 1 1\n"
                           "  Ke 17 12 4\n  illum 2\n");
    ASSERT_EQ(lib.materials.size(), 1u);
    const MtlMaterial &mtl = lib.materials[0];
    EXPECT_EQ(mtl.name, "shiny glass");
    EXPECT_EQ(mtl.textureLine, 8);
    Material m = materialFromMtl(mtl, "obj:shiny glass");
    EXPECT_EQ(m.name, "obj:shiny glass");
    EXPECT_EQ(m.color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_FLOAT_EQ(m.specular, 0.6f);
    EXPECT_EQ(m.shininess, 64.0f);
    EXPECT_EQ(m.ior, 1.33f);
    EXPECT_EQ(m.transmit, 0.75f); // Tr wins over d
    EXPECT_EQ(m.ambient, 0.1f);   // scene-material defaults for the rest
    EXPECT_EQ(m.diffuse, 0.9f);
    EXPECT_EQ(m.reflect, 0.0f);
    EXPECT_EQ(mtl.texturePath, "tex.png");
}

TEST(MtlLoader, DissolveGivesTransmitWhenThereIsNoTr) {
    MtlLibrary lib = parse("newmtl a\nd 0.25\nnewmtl b\nd -halo 0.5\nnewmtl c\n");
    EXPECT_EQ(materialFromMtl(lib.materials[0], "a").transmit, 0.75f);
    EXPECT_EQ(materialFromMtl(lib.materials[1], "b").transmit, 0.5f);
    Material plain = materialFromMtl(lib.materials[2], "c"); // nothing said: all defaults
    EXPECT_EQ(plain.color, glm::vec3(0.8f));
    EXPECT_EQ(plain.specular, 0.0f);
    EXPECT_EQ(plain.shininess, 32.0f);
    EXPECT_EQ(plain.ior, 1.5f);
    EXPECT_EQ(plain.transmit, 0.0f);
}

TEST(MtlLoader, KeywordsAreCaseInsensitiveAndOneValueColoursAreGrey) {
    MtlLibrary lib = parse("NEWMTL a\nKD 0.5\nmap_kd x.png\n");
    EXPECT_EQ(lib.materials[0].kd, glm::vec3(0.5f));
    EXPECT_EQ(lib.materials[0].texturePath, "x.png");
}

TEST(MtlLoader, TexturePathsWindowsStyleWithOptionsAndWithSpaces) {
    MtlLibrary lib = parse("newmtl a\nmap_Kd .\\SpiderTex.jpg\nnewmtl b\n"
                           "map_Kd -s 1 1 1 -o 0 0 0 sub\\t.png\nnewmtl c\nmap_Kd my tex.png\n");
    EXPECT_EQ(lib.materials[0].texturePath, "./SpiderTex.jpg");
    EXPECT_EQ(lib.materials[1].texturePath, "sub/t.png");
    EXPECT_EQ(lib.materials[2].texturePath, "my tex.png");
}

// bump / map_Bump (height, -bm its multiplier) and norm (tangent-space normals), each with its
// line for a warning about the image; the multiplier carries over to the scene material.
TEST(MtlLoader, BumpAndNormalMaps) {
    MtlLibrary lib =
        parse("newmtl a\nbump h.png\nnorm n.png\nnewmtl b\n"
              "map_Bump -bm 0.5 sub\\h.png\nnewmtl c\nMAP_BUMP -clamp on -BM -2 h.png\n"
              "newmtl d\nmap_Kd d.png\n");
    ASSERT_EQ(lib.materials.size(), 4u);
    const MtlMaterial &a = lib.materials[0], &b = lib.materials[1], &c = lib.materials[2];
    EXPECT_EQ(a.bumpPath, "h.png");
    EXPECT_EQ(a.bumpLine, 2);
    EXPECT_EQ(a.bumpScale, 1.0f);
    EXPECT_EQ(a.normalPath, "n.png");
    EXPECT_EQ(a.normalLine, 3);
    EXPECT_EQ(b.bumpPath, "sub/h.png");
    EXPECT_EQ(b.bumpLine, 5);
    EXPECT_EQ(b.bumpScale, 0.5f);
    EXPECT_EQ(materialFromMtl(b, "b").bumpScale, 0.5f);
    EXPECT_EQ(c.bumpPath, "h.png");
    EXPECT_EQ(c.bumpScale, -2.0f); // a negative multiplier turns bumps into dents
    EXPECT_TRUE(c.normalPath.empty());
    EXPECT_TRUE(lib.materials[3].bumpPath.empty()); // map_Kd is no bump map
    Material plain = materialFromMtl(lib.materials[3], "d");
    EXPECT_EQ(plain.bumpScale, 1.0f);
    EXPECT_FALSE(plain.hasSurfaceMaps()); // the caller loads the images
}

// Options after the file name, as tinyobjloader reads them and as its own test files write
// them (issue 35: `map_bump -imfchan r bump.jpg -bm 1.5` was refused).
TEST(MtlLoader, TextureOptionsOnEitherSideOfTheFile) {
    MtlLibrary lib = parse("newmtl a\nmap_bump -imfchan r bump.jpg -bm 1.5\n"
                           "newmtl b\nmap_Kd tex.png -s 2 2\n"
                           "newmtl c\nmap_Kd -o 0.5 my tex.png -clamp on\n"
                           "newmtl d\nbump -mm 0 1 h.png -bm -0.5 -texres 512\n"
                           "newmtl e\nnorm -blendu off n.png -colorspace linear\n");
    ASSERT_EQ(lib.materials.size(), 5u);
    EXPECT_EQ(lib.materials[0].bumpPath, "bump.jpg");
    EXPECT_EQ(lib.materials[0].bumpScale, 1.5f);
    EXPECT_EQ(lib.materials[1].texturePath, "tex.png");
    EXPECT_EQ(lib.materials[2].texturePath, "my tex.png");
    EXPECT_EQ(lib.materials[3].bumpPath, "h.png");
    EXPECT_EQ(lib.materials[3].bumpScale, -0.5f);
    EXPECT_EQ(lib.materials[4].normalPath, "n.png");
}

TEST(MtlLoader, BadBumpMultipliersAndMissingFilesAreErrorsAtTheirLine) {
    std::vector<std::string> warnings;
    test::expectFileError([&] { parseMtl("newmtl a\nbump -bm x h.png\n", "lib.mtl", warnings); },
                          "lib.mtl", 2, "bad number 'x'");
    test::expectFileError([&] { parseMtl("newmtl a\n\nbump -bm 0.5\n", "lib.mtl", warnings); },
                          "lib.mtl", 3, "'bump' needs the image's file name");
    test::expectFileError([&] { parseMtl("newmtl a\nbump h.png -bm\n", "lib.mtl", warnings); },
                          "lib.mtl", 2, "'-bm' needs a number");
    test::expectFileError([&] { parseMtl("newmtl a\nnorm\n", "lib.mtl", warnings); }, "lib.mtl", 2,
                          "'norm' needs a value");
    test::expectFileError([&] { parseMtl("newmtl a\nmap_Bump\n", "lib.mtl", warnings); }, "lib.mtl",
                          2, "'map_Bump' needs a value");
}

TEST(MtlLoader, CrlfCommentsAndNoFinalNewline) {
    MtlLibrary lib = parse("# c\r\nnewmtl leftWall\r\n  Ka 0.63 0.065 0.05 # Red\r\n"
                           "  Kd 0.63 0.065 0.05\r\nnewmtl last\r\nKd 1 1 1");
    ASSERT_EQ(lib.materials.size(), 2u);
    EXPECT_EQ(lib.find("leftWall")->kd, glm::vec3(0.63f, 0.065f, 0.05f));
    EXPECT_EQ(lib.find("last")->kd, glm::vec3(1));
    EXPECT_EQ(lib.find("nope"), nullptr);
}

TEST(MtlLoader, UnusableValuesAreWarningsAndKeepDefaults) {
    std::vector<std::string> warnings;
    MtlLibrary lib = parse("newmtl a\nKd -1 0 0\nNi 0\nNs -3\nd 2\nKs spectral x.rfl\n", &warnings);
    ASSERT_EQ(warnings.size(), 5u);
    EXPECT_EQ(warnings[0].rfind("lib.mtl:2: warning: negative Kd", 0), 0u) << warnings[0];
    EXPECT_EQ(warnings[1].rfind("lib.mtl:3: warning: Ni must be > 0", 0), 0u) << warnings[1];
    EXPECT_EQ(warnings[2].rfind("lib.mtl:4: warning:", 0), 0u);
    EXPECT_EQ(warnings[3].rfind("lib.mtl:5: warning: d must be in [0, 1]", 0), 0u);
    EXPECT_EQ(warnings[4].rfind("lib.mtl:6: warning:", 0), 0u);
    Material m = materialFromMtl(lib.materials[0], "a");
    EXPECT_EQ(m.color, glm::vec3(0.8f));
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.shininess, 32.0f);
    EXPECT_EQ(m.transmit, 0.0f);
}

TEST(MtlLoader, ARedefinedNameWarnsAndTheLastDefinitionWins) {
    std::vector<std::string> warnings;
    MtlLibrary lib = parse("newmtl a\nKd 1 0 0\nnewmtl a\nKd 0 1 0\n", &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].rfind("lib.mtl:3: warning: material 'a' is defined again", 0), 0u);
    EXPECT_EQ(lib.find("a")->kd, glm::vec3(0, 1, 0));
}

TEST(MtlLoader, MalformedNumbersAreErrorsAtTheirLine) {
    std::vector<std::string> warnings;
    test::expectFileError([&] { parseMtl("newmtl a\nKd 1 nan 0\n", "lib.mtl", warnings); },
                          "lib.mtl", 2, "bad number 'nan'");
    test::expectFileError([&] { parseMtl("newmtl a\n\nNs 1x\n", "lib.mtl", warnings); }, "lib.mtl",
                          3, "bad number '1x'");
    test::expectFileError([&] { parseMtl("newmtl a\nKd 1 1\n", "lib.mtl", warnings); }, "lib.mtl",
                          2, "'Kd' needs 1 or 3 numbers");
    test::expectFileError([&] { parseMtl("newmtl\n", "lib.mtl", warnings); }, "lib.mtl", 1,
                          "newmtl needs a name");
}

} // namespace
} // namespace prism
