// A model read back from the OBJ cache is the model the parser makes, array for array; the key
// follows the file's bytes and the name its warnings use; a damaged entry is parsed anew, never
// used; a file with errors, or one under the size worth caching, leaves no entry.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "cache/blob.h"
#include "cache/disk_cache.h"
#include "core/error.h"
#include "scene/obj_cache.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace prism {
namespace {

// Every statement the model keeps: positions, coordinates, normals, faces of 3 and 4 corners in
// each corner form, negative indices, smoothing groups, two usemtl slots, an mtllib, and a
// normal index past the file's normals (a warning).
constexpr const char *kObj = "mtllib parts.mtl\n"
                             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                             "vt 0 0\nvt 1 0\nvt 1 1\n"
                             "vn 0 0 1\nvn 0 1 0\n"
                             "usemtl red\ns 1\n"
                             "f 1/1/1 2/2/1 3/3/1 4/1/1\n"
                             "f -1//2 1//2 2//2\n"
                             "s off\nusemtl blue\n"
                             "f 2 3 5\n"
                             "f 3/3/7 4/1/1 5/2/1\n";

void expectSameModel(const ObjModel &a, const ObjModel &b) {
    ASSERT_EQ(a.positions, b.positions);
    ASSERT_EQ(a.uvs, b.uvs);
    ASSERT_EQ(a.normals, b.normals);
    // Byte for byte (both structs are without padding: obj_cache.cpp); an empty array's data()
    // may be null, which memcmp must not be given.
    ASSERT_EQ(a.corners.size(), b.corners.size());
    if (!a.corners.empty()) {
        EXPECT_EQ(0, std::memcmp(a.corners.data(), b.corners.data(),
                                 a.corners.size() * sizeof(ObjCorner)));
    }
    ASSERT_EQ(a.faces.size(), b.faces.size());
    if (!a.faces.empty()) {
        EXPECT_EQ(0, std::memcmp(a.faces.data(), b.faces.data(), a.faces.size() * sizeof(ObjFace)));
    }
    ASSERT_EQ(a.useMtl.size(), b.useMtl.size());
    for (size_t i = 0; i < a.useMtl.size(); ++i) {
        EXPECT_EQ(a.useMtl[i].name, b.useMtl[i].name);
        EXPECT_EQ(a.useMtl[i].line, b.useMtl[i].line);
    }
    ASSERT_EQ(a.mtlLibs.size(), b.mtlLibs.size());
    for (size_t i = 0; i < a.mtlLibs.size(); ++i) {
        EXPECT_EQ(a.mtlLibs[i].path, b.mtlLibs[i].path);
        EXPECT_EQ(a.mtlLibs[i].line, b.mtlLibs[i].line);
    }
    EXPECT_EQ(a.warnings, b.warnings);
}

void expectSameModel(const LoadedObjModel &a, const ObjModel &b) {
    expectSameModel(copyModel(a.view()), b);
}

struct CacheInTempDir {
    test::TempDir dir;
    std::vector<std::string> warnings;
    DiskCache cache{DiskCacheOptions{dir.path() / "cache", uint64_t(1) << 30,
                                     [this](const std::string &w) { warnings.push_back(w); }}};
    // Every file cached, however small.
    ObjCacheUse use() { return ObjCacheUse{&cache, 0}; }
    size_t entries() const {
        size_t n = 0;
        std::error_code ec;
        for ([[maybe_unused]] const auto &e :
             std::filesystem::directory_iterator(dir.path() / "cache", ec))
            ++n;
        return n;
    }
};

TEST(ObjCache, PackedModelUnpacksToTheSameModel) {
    ObjModel parsed = parseObj(kObj, "parts.obj");
    ASSERT_EQ(parsed.faces.size(), 4u);
    ASSERT_EQ(parsed.useMtl.size(), 2u);
    ASSERT_EQ(parsed.mtlLibs.size(), 1u);
    ASSERT_EQ(parsed.warnings.size(), 1u) << "the normal index past the file's normals";
    expectSameModel(unpackObjModel(packObjModel(parsed)), parsed);
    expectSameModel(unpackObjModel(packObjModel(ObjModel{})), ObjModel{});
}

// A cache hit reads the arrays where the entry's bytes hold them, without a copy (a 1M-triangle
// mesh's 60 MB); bytes that do not lie aligned for them are copied, to the same model.
TEST(ObjCache, AnEntrysArraysAreViewedWhereTheyLie) {
    ObjModel parsed = parseObj(kObj, "parts.obj");
    std::string packed = packObjModel(parsed);
    auto inside = [](const void *p, std::string_view bytes) {
        auto *c = static_cast<const char *>(p);
        return c >= bytes.data() && c < bytes.data() + bytes.size();
    };
    ObjModel rest;
    ObjModelView view = viewObjModel(packed, rest);
    expectSameModel(copyModel(view), parsed);
    EXPECT_TRUE(inside(view.positions.data(), packed));
    EXPECT_TRUE(inside(view.corners.data(), packed));
    EXPECT_TRUE(inside(view.faces.data(), packed));
    EXPECT_TRUE(rest.positions.empty() && rest.corners.empty() && rest.faces.empty());
    EXPECT_EQ(rest.useMtl.size(), 2u) << "names are strings: always copied";

    std::string shifted = "x" + packed; // every array one byte past a 4-byte boundary
    std::string_view odd = std::string_view(shifted).substr(1);
    ObjModel copies;
    ObjModelView copied = viewObjModel(odd, copies);
    expectSameModel(copyModel(copied), parsed);
    EXPECT_EQ(copies.corners.size(), parsed.corners.size());
    EXPECT_FALSE(inside(copied.corners.data(), shifted));
}

TEST(ObjCache, SecondLoadIsReadBackAndEqualsTheParse) {
    CacheInTempDir c;
    std::filesystem::path obj = c.dir.write("parts.obj", kObj);
    ObjModel parsed = parseObj(kObj, "parts.obj");
    ObjCacheUse use = c.use();
    expectSameModel(loadObjFile(obj, "parts.obj", &use), parsed);
    EXPECT_EQ(use.misses, 1);
    EXPECT_EQ(use.hits, 0);
    EXPECT_EQ(c.entries(), 1u);
    expectSameModel(loadObjFile(obj, "parts.obj", &use), parsed);
    EXPECT_EQ(use.misses, 1);
    EXPECT_EQ(use.hits, 1);
    EXPECT_TRUE(c.warnings.empty());

    // Under the size worth caching, and without a cache: parsed, nothing stored or counted.
    CacheInTempDir small;
    ObjCacheUse defaults{&small.cache};
    ASSERT_GT(defaults.minBytes, std::strlen(kObj));
    expectSameModel(loadObjFile(obj, "parts.obj", &defaults), parsed);
    expectSameModel(loadObjFile(obj, "parts.obj", nullptr), parsed);
    EXPECT_EQ(defaults.hits + defaults.misses, 0);
    EXPECT_EQ(small.entries(), 0u);
}

// The key is what the parse reads: the bytes, and the name its warnings carry.
TEST(ObjCache, KeyFollowsTheBytesAndTheName) {
    std::string key = objCacheKey(kObj, "parts.obj");
    EXPECT_EQ(objCacheKey(kObj, "parts.obj"), key);
    std::string changed = kObj;
    changed[changed.find("0.5")] = '1';
    EXPECT_NE(objCacheKey(changed, "parts.obj"), key);
    EXPECT_NE(objCacheKey(kObj, "other/parts.obj"), key);
}

// An entry whose bytes pass the checksum but do not make a model, or make one whose indices run
// past its arrays (which the importer would read past), is removed and the file parsed anew.
TEST(ObjCache, AnEntryThatIsNoModelIsParsedAgain) {
    ObjModel parsed = parseObj(kObj, "parts.obj");
    ObjModel pastPositions = parsed;
    pastPositions.corners[2].position = int32_t(parsed.positions.size());
    ObjModel pastNormals = parsed;
    pastNormals.corners[0].normal = int32_t(parsed.normals.size());
    ObjModel pastCorners = parsed;
    pastCorners.faces.back().cornerCount = 4;
    ObjModel pastSlots = parsed;
    pastSlots.faces[0].materialSlot = 2;
    std::string whole = packObjModel(parsed);
    for (const std::string &bad :
         {whole.substr(0, whole.size() / 2), whole + "x", packObjModel(pastPositions),
          packObjModel(pastNormals), packObjModel(pastCorners), packObjModel(pastSlots)}) {
        EXPECT_THROW(unpackObjModel(bad), BlobFormatError);
        CacheInTempDir c;
        std::filesystem::path obj = c.dir.write("parts.obj", kObj);
        c.cache.store("obj", objCacheKey(kObj, "parts.obj"), kObjCacheFormat, bad);
        ObjCacheUse use = c.use();
        ObjModel model = copyModel(loadObjFile(obj, "parts.obj", &use).view());
        ASSERT_EQ(c.warnings.size(), 1u);
        EXPECT_NE(c.warnings[0].find("damaged"), std::string::npos) << c.warnings[0];
        EXPECT_NE(c.warnings[0].find("parts.obj"), std::string::npos) << c.warnings[0];
        EXPECT_EQ(use.misses, 1);
        expectSameModel(model, parsed);
        // The parse was stored whole in its place.
        ObjCacheUse again = c.use();
        expectSameModel(loadObjFile(obj, "parts.obj", &again), parsed);
        EXPECT_EQ(again.hits, 1);
    }
}

// A file damaged on disk (a flipped byte: the cache's checksum) or written by another format
// version is parsed anew with one warning line.
TEST(ObjCache, ACorruptedOrStaleFileIsParsedAgain) {
    for (int damage = 0; damage < 2; ++damage) {
        CacheInTempDir c;
        std::filesystem::path obj = c.dir.write("parts.obj", kObj);
        std::string key = objCacheKey(kObj, "parts.obj");
        if (damage == 0) {
            c.cache.store("obj", key, kObjCacheFormat, packObjModel(parseObj(kObj, "parts.obj")));
            std::fstream file(c.cache.entryPath("obj", key),
                              std::ios::in | std::ios::out | std::ios::binary);
            file.seekp(-3, std::ios::end);
            file.put('\x7f');
        } else {
            c.cache.store("obj", key, kObjCacheFormat + 1,
                          packObjModel(parseObj(kObj, "parts.obj")));
        }
        ObjCacheUse use = c.use();
        expectSameModel(loadObjFile(obj, "parts.obj", &use), parseObj(kObj, "parts.obj"));
        EXPECT_EQ(use.misses, 1) << damage;
        EXPECT_EQ(c.warnings.size(), 1u) << damage;
    }
}

// A file the parser refuses stores nothing: the next load refuses it again, at its line.
TEST(ObjCache, AFileWithErrorsIsNotStored) {
    CacheInTempDir c;
    std::filesystem::path obj = c.dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
    for (int attempt = 0; attempt < 2; ++attempt) {
        ObjCacheUse use = c.use();
        try {
            loadObjFile(obj, "bad.obj", &use);
            ADD_FAILURE() << "a face past the vertices loaded";
        } catch (const FileError &e) {
            EXPECT_NE(std::string(e.what()).find("bad.obj:3:"), std::string::npos) << e.what();
        }
        EXPECT_EQ(use.hits + use.misses, 0);
    }
    EXPECT_EQ(c.entries(), 0u);
}

// Through the scene loader: the scene from the cache has the same triangles, bit for bit.
TEST(ObjCache, SceneFromTheCacheHasTheSameTriangles) {
    CacheInTempDir c;
    c.dir.write("parts.obj", kObj);
    std::filesystem::path scene =
        c.dir.write("a.scene", "mesh parts.obj translate 1 2 3 scale 2\nmesh parts.obj smooth\n");
    Scene parsed = loadScene(scene);
    ObjCacheUse use = c.use();
    Scene first = loadScene(scene, {}, &use);
    Scene second = loadScene(scene, {}, &use);
    EXPECT_EQ(use.misses, 1) << "one file, read twice by the first scene: stored once";
    EXPECT_EQ(use.hits, 3);
    for (const Scene *s : {&first, &second}) {
        ASSERT_EQ(s->triangles.size(), parsed.triangles.size());
        for (size_t i = 0; i < parsed.triangles.size(); ++i) {
            const Triangle &a = s->triangles[i], &b = parsed.triangles[i];
            const TriangleShading &as = s->shadingOf(i), &bs = parsed.shadingOf(i);
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(a.p[k], b.p[k]);
                EXPECT_EQ(as.n[k], bs.n[k]);
                EXPECT_EQ(as.uv[k], bs.uv[k]);
            }
            EXPECT_EQ(as.hasNormals, bs.hasNormals);
            EXPECT_EQ(as.hasUVs, bs.hasUVs);
            EXPECT_EQ(a.material, b.material);
        }
        EXPECT_EQ(s->warnings, parsed.warnings);
    }
}

} // namespace
} // namespace prism
