// Texture decoding and caching (engine/scene/texture_loader.cpp).
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene_loader.h"
#include "scene/texture_loader.h"
#include "temp_dir.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace prism {
namespace {

using test::TempDir;

template <typename T>
void writeImage(const std::filesystem::path &path, int width, int height, int channels,
                OIIO::TypeDesc type, const std::vector<T> &pixels) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, channels, type);
    if (channels == 2 || channels == 4) {
        spec.alpha_channel = channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1); // store straight colour as given
    }
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
    out->close();
}

float eotf(double encoded) { // the sRGB EOTF, written out independently
    return float(encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4));
}

TEST(TextureLoader, SrgbEotfIsExact) {
    EXPECT_EQ(srgbToLinear(0.0f), 0.0f);
    EXPECT_EQ(srgbToLinear(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(srgbToLinear(0.04045f), 0.04045f / 12.92f);
    EXPECT_NEAR(srgbToLinear(0.5f), 0.21404114, 1e-7);
}

TEST(TextureLoader, EightBitRgbIsDecodedToLinearWithTheTopRowFirst) {
    TempDir dir;
    // 2x2: top row red, 128-grey; bottom row black, (10, 200, 255).
    writeImage<uint8_t>(dir.path() / "t.png", 2, 2, 3, OIIO::TypeDesc::UINT8,
                        {255, 0, 0, 128, 128, 128, 0, 0, 0, 10, 200, 255});
    Texture t = readTexture(dir.path() / "t.png");
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 2);
    ASSERT_EQ(t.texels.size(), 4u);
    EXPECT_EQ(t.texels[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(t.texels[1], glm::vec4(glm::vec3(eotf(128 / 255.0)), 1));
    EXPECT_EQ(t.texels[2], glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(t.texels[3], glm::vec4(eotf(10 / 255.0), eotf(200 / 255.0), 1, 1));
    EXPECT_EQ(t.path, (dir.path() / "t.png").generic_string());
}

TEST(TextureLoader, GreyBecomesRgbWithOpaqueAlpha) {
    TempDir dir;
    writeImage<uint8_t>(dir.path() / "g.png", 2, 1, 1, OIIO::TypeDesc::UINT8, {0, 100});
    Texture t = readTexture(dir.path() / "g.png");
    ASSERT_EQ(t.texels.size(), 2u);
    EXPECT_EQ(t.texels[1], glm::vec4(eotf(100 / 255.0), eotf(100 / 255.0), eotf(100 / 255.0), 1));
}

TEST(TextureLoader, AlphaIsLinearAndColourIsNotPremultiplied) {
    TempDir dir;
    writeImage<uint8_t>(dir.path() / "ga.png", 1, 1, 2, OIIO::TypeDesc::UINT8, {200, 51});
    writeImage<uint8_t>(dir.path() / "rgba.png", 2, 1, 4, OIIO::TypeDesc::UINT8,
                        {255, 255, 255, 0, 128, 64, 32, 102});
    Texture ga = readTexture(dir.path() / "ga.png");
    EXPECT_EQ(ga.texels[0], glm::vec4(glm::vec3(eotf(200 / 255.0)), 51 / 255.0f));
    Texture rgba = readTexture(dir.path() / "rgba.png");
    EXPECT_EQ(rgba.texels[0], glm::vec4(1, 1, 1, 0)); // colour kept where alpha is 0
    EXPECT_EQ(rgba.texels[1],
              glm::vec4(eotf(128 / 255.0), eotf(64 / 255.0), eotf(32 / 255.0), 102 / 255.0f));
}

TEST(TextureLoader, SixteenBitIsSrgbDecodedToo) {
    TempDir dir;
    writeImage<uint16_t>(dir.path() / "w.png", 1, 1, 3, OIIO::TypeDesc::UINT16, {65535, 32768, 0});
    Texture t = readTexture(dir.path() / "w.png");
    EXPECT_EQ(t.texels[0], glm::vec4(1, eotf(32768 / 65535.0), 0, 1));
}

TEST(TextureLoader, FloatImagesAreTakenAsTheyAre) {
    TempDir dir;
    writeImage<float>(dir.path() / "f.exr", 1, 2, 3, OIIO::TypeDesc::FLOAT,
                      {0.5f, 2.0f, 0.01f, 0.25f, 0.0f, 7.5f});
    Texture t = readTexture(dir.path() / "f.exr");
    ASSERT_EQ(t.texels.size(), 2u);
    EXPECT_EQ(t.texels[0], glm::vec4(0.5f, 2.0f, 0.01f, 1.0f));
    EXPECT_EQ(t.texels[1], glm::vec4(0.25f, 0.0f, 7.5f, 1.0f));
}

// An image header can claim any size (here a PPM header alone, 10000 x 10000): it is refused
// by the limit before any texel is allocated.
TEST(TextureLoader, HugeImagesAreRefusedByTheLimit) {
    TempDir dir;
    dir.write("huge.ppm", "P6\n10000 10000\n255\n");
    try {
        readTexture(dir.path() / "huge.ppm");
        ADD_FAILURE() << "a 10000 x 10000 texture was accepted";
    } catch (const Error &e) {
        std::string message = e.what();
        EXPECT_NE(message.find("huge.ppm"), std::string::npos) << message;
        EXPECT_NE(message.find("10000 x 10000 pixels"), std::string::npos) << message;
        EXPECT_NE(message.find("8192 x 8192"), std::string::npos) << message;
    }
}

TEST(TextureLoader, UnreadableImagesThrowWithThePath) {
    TempDir dir;
    dir.write("text.png", "not an image");
    for (const char *name : {"missing.png", "text.png"}) {
        try {
            readTexture(dir.path() / name);
            ADD_FAILURE() << name;
        } catch (const Error &e) {
            EXPECT_EQ(std::string(e.what()).rfind("cannot read texture '", 0), 0u) << e.what();
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(TextureCache, LoadsEachFileOnceWhateverItsSpelling) {
    TempDir dir;
    writeImage<uint8_t>(dir.path() / "a.png", 1, 1, 3, OIIO::TypeDesc::UINT8, {1, 2, 3});
    writeImage<uint8_t>(dir.path() / "b.png", 1, 1, 3, OIIO::TypeDesc::UINT8, {4, 5, 6});
    std::filesystem::create_directories(dir.path() / "sub");
    Scene scene;
    TextureCache cache;
    EXPECT_EQ(cache.load(dir.path() / "a.png", scene), 0);
    EXPECT_EQ(cache.load(dir.path() / "sub/../a.png", scene), 0);
    EXPECT_EQ(cache.load(dir.path() / "b.png", scene), 1);
    EXPECT_EQ(cache.load(dir.path() / "./a.png", scene), 0);
    EXPECT_EQ(scene.textures.size(), 2u);
    EXPECT_THROW(cache.load(dir.path() / "c.png", scene), Error);
    EXPECT_EQ(scene.textures.size(), 2u);
}

TEST(TextureCache, MaterialLinesShareTexturesAndAcceptQuotedPaths) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "my textures");
    writeImage<uint8_t>(dir.path() / "my textures/checker board.png", 2, 1, 3,
                        OIIO::TypeDesc::UINT8, {255, 255, 255, 0, 0, 0});
    Scene scene = loadScene(dir.write(
        "s.scene", "material a texture \"my textures/checker board.png\"\n"
                   "material b color 1 0 0 texture \"./my textures/checker board.png\"\n"));
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials[1].texture, 0);
    EXPECT_EQ(scene.materials[2].texture, 0);
    EXPECT_EQ(scene.materials[2].color, glm::vec3(1, 0, 0)); // the texture multiplies colour
    EXPECT_EQ(scene.textures[0].texels[1], glm::vec4(0, 0, 0, 1));
}

// Normal and bump maps are data: 8-bit values are only scaled to [0, 1] (a normal map's 128
// must stay 128/255, not become 0.216), so a file used for colour and for data is two textures.
TEST(TextureCache, NormalAndBumpMapsAreDataNotColour) {
    TempDir dir;
    writeImage<uint8_t>(dir.path() / "n.png", 1, 1, 3, OIIO::TypeDesc::UINT8, {128, 64, 255});
    writeImage<uint16_t>(dir.path() / "h.png", 1, 1, 1, OIIO::TypeDesc::UINT16, {32768});
    Scene scene = loadScene(dir.write("s.scene", "material a texture n.png norm n.png\n"
                                                 "material b bump h.png bm -0.5 norm ./n.png\n"
                                                 "material c bump h.png\n"));
    ASSERT_EQ(scene.textures.size(), 3u);
    const Material &a = scene.materials[1], &b = scene.materials[2], &c = scene.materials[3];
    EXPECT_NE(a.texture, a.normalMap);
    EXPECT_EQ(b.normalMap, a.normalMap);
    EXPECT_EQ(c.bumpMap, b.bumpMap);
    EXPECT_EQ(a.bumpMap, kNoTexture);
    EXPECT_EQ(b.bumpScale, -0.5f);
    EXPECT_EQ(c.bumpScale, 1.0f);
    EXPECT_EQ(scene.textures[size_t(a.normalMap)].texels[0],
              glm::vec4(128 / 255.0f, 64 / 255.0f, 1.0f, 1.0f));
    EXPECT_EQ(scene.textures[size_t(a.texture)].texels[0].y, eotf(64 / 255.0));
    EXPECT_EQ(scene.textures[size_t(b.bumpMap)].texels[0],
              glm::vec4(glm::vec3(32768 / 65535.0f), 1.0f));
}

// `environment PATH [intensity K] [rotate DEG]`: the image is a texture like any other (an EXR
// kept linear), shared with materials naming the same file; one environment a scene.
TEST(Environment, LineLoadsItsImageWithIntensityAndRotation) {
    TempDir dir;
    writeImage<float>(dir.path() / "sky.exr", 2, 1, 3, OIIO::TypeDesc::FLOAT,
                      {2.0f, 1.0f, 0.5f, 0.0f, 0.0f, 4.0f});
    Scene plain = loadScene(dir.write("a.scene", "sphere 0 0 0 1\n"));
    EXPECT_EQ(plain.environment.texture, kNoTexture);
    Scene scene = loadScene(dir.write(
        "s.scene", "environment sky.exr rotate -30 intensity 0.5\nmaterial m texture sky.exr\n"));
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.environment.texture, 0);
    EXPECT_EQ(scene.materials[1].texture, 0);
    EXPECT_EQ(scene.environment.intensity, 0.5f);
    EXPECT_EQ(scene.environment.rotateDegrees, -30.0f);
    EXPECT_EQ(scene.textures[0].texels[0], glm::vec4(2.0f, 1.0f, 0.5f, 1.0f)); // HDR kept
    Scene defaults = loadScene(dir.write("d.scene", "environment sky.exr\n"));
    EXPECT_EQ(defaults.environment.intensity, 1.0f);
    EXPECT_EQ(defaults.environment.rotateDegrees, 0.0f);
}

TEST(Environment, ErrorsNameTheLine) {
    TempDir dir;
    writeImage<float>(dir.path() / "sky.exr", 1, 1, 3, OIIO::TypeDesc::FLOAT, {1.0f, 1.0f, 1.0f});
    struct Case {
        const char *text;
        int line;
        const char *fragment;
    };
    for (const Case &c :
         {Case{"\nenvironment missing.exr\n", 2, "missing.exr"},
          Case{"environment sky.exr\nenvironment sky.exr\n", 2, "only one environment"},
          Case{"environment sky.exr intensity -1\n", 1, "must not be negative"},
          Case{"environment\n", 1, "environment PATH"},
          Case{"environment sky.exr rotate\n", 1, "'rotate' needs 1 value"}}) {
        std::filesystem::path scene = dir.write("bad.scene", c.text);
        try {
            loadScene(scene);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const Error &e) {
            std::string message = e.what();
            EXPECT_NE(message.find(scene.string() + ":" + std::to_string(c.line) + ":"),
                      std::string::npos)
                << message;
            EXPECT_NE(message.find(c.fragment), std::string::npos) << message;
        }
    }
}

} // namespace
} // namespace prism
