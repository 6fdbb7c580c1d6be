// The on-disk cache hands back exactly what was stored, refuses (and removes) an entry that is
// damaged, stale or someone else's, keeps within its size by dropping the least recently used,
// and stays whole when two processes fill the same entry at once.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "cache/blob.h"
#include "cache/disk_cache.h"
#include "temp_dir.h"

namespace prism {
namespace {

using test::TempDir;

const std::string kKey = "0123456789abcdef0123456789abcdef";

struct Fixture {
    TempDir dir;
    std::vector<std::string> warnings;
    DiskCache cache{DiskCacheOptions{dir.path() / "cache", uint64_t(1) << 30,
                                     [this](const std::string &w) { warnings.push_back(w); }}};
};

std::string payload(size_t n, char seed) {
    std::string bytes(n, '\0');
    for (size_t i = 0; i < n; ++i)
        bytes[i] = char(seed + char(i * 7));
    return bytes;
}

size_t filesIn(const std::filesystem::path &dir) {
    size_t n = 0;
    for ([[maybe_unused]] const auto &e : std::filesystem::directory_iterator(dir))
        ++n;
    return n;
}

TEST(DiskCache, GivesBackWhatWasStored) {
    Fixture f;
    EXPECT_FALSE(f.cache.load("grid", kKey, 1).has_value());
    std::string bytes = payload(100'000, 3);
    f.cache.store("grid", kKey, 1, bytes);
    std::optional<CacheEntry> back = f.cache.load("grid", kKey, 1);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->payload, bytes);
    EXPECT_FALSE(f.cache.load("mesh", kKey, 1).has_value()) << "kinds are apart";
    EXPECT_TRUE(f.warnings.empty());
    EXPECT_EQ(filesIn(f.cache.directory()), 1u) << "no temporary file left behind";
}

// An entry stored in pieces (cache/blob.h) is the entry of their bytes stored as one: the same
// file byte for byte (payload, size and checksum), read back whole.
TEST(DiskCache, PiecesAreStoredAsTheirBytesInOne) {
    Fixture f;
    std::string a = payload(10, 1), b = payload(300'000, 2), c = payload(7, 3);
    std::vector<std::string_view> pieces{a, b, "", c};
    f.cache.store("grid", kKey, 1, pieces);
    std::optional<CacheEntry> back = f.cache.load("grid", kKey, 1);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->payload, a + b + c);
    auto fileBytes = [](const std::filesystem::path &path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    std::string inPieces = fileBytes(f.cache.entryPath("grid", kKey));
    back.reset();
    f.cache.store("grid", kKey, 1, a + b + c);
    EXPECT_EQ(fileBytes(f.cache.entryPath("grid", kKey)), inPieces);
    EXPECT_TRUE(f.warnings.empty());
}

// A record's large arrays are borrowed where their vectors hold them, its small values copied;
// the pieces' bytes in order are the one string take() gives, which reads back as written.
TEST(BlobWriter, LargeArraysAreBorrowedAndThePiecesAreTheRecord) {
    std::vector<uint32_t> large(5000), small{7, 8, 9};
    for (uint32_t i = 0; i < large.size(); ++i)
        large[i] = i * 3u;
    BlobWriter out;
    out.value(uint32_t(42));
    out.values(small);
    out.values(large);
    out.text("after");
    out.values(std::vector<uint64_t>{});
    std::vector<std::string_view> pieces = out.pieces();
    ASSERT_EQ(pieces.size(), 3u) << "values, the large array, values";
    EXPECT_EQ(static_cast<const void *>(pieces[1].data()), static_cast<const void *>(large.data()));
    std::string whole = out.take(), joined;
    for (std::string_view piece : pieces)
        joined += piece;
    EXPECT_EQ(joined, whole);
    BlobReader in(whole);
    EXPECT_EQ(in.value<uint32_t>(), 42u);
    EXPECT_EQ(in.values<uint32_t>(), small);
    EXPECT_EQ(in.values<uint32_t>(), large);
    EXPECT_EQ(in.text(), "after");
    EXPECT_TRUE(in.values<uint64_t>().empty());
    EXPECT_TRUE(in.atEnd());
}

// Each way an entry can go bad: the next load warns once, removes it and reports nothing.
TEST(DiskCache, DamagedStaleOrForeignEntriesAreRemovedWithAWarning) {
    using Damage = std::function<void(const std::filesystem::path &)>;
    auto rewrite = [](const std::filesystem::path &p, const std::function<void(std::string &)> &f) {
        std::ifstream in(p, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        f(bytes);
        std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
    };
    const std::vector<std::pair<const char *, Damage>> damages = {
        {"a flipped payload byte",
         [&](auto &p) { rewrite(p, [](std::string &b) { b[b.size() / 2] ^= 0x10; }); }},
        {"truncated", [&](auto &p) { rewrite(p, [](std::string &b) { b.resize(b.size() - 1); }); }},
        {"cut inside the header",
         [&](auto &p) { rewrite(p, [](std::string &b) { b.resize(40); }); }},
        {"empty", [&](auto &p) { rewrite(p, [](std::string &b) { b.clear(); }); }},
        {"not an entry", [&](auto &p) { rewrite(p, [](std::string &b) { b[0] = 'X'; }); }},
        {"a byte appended", [&](auto &p) { rewrite(p, [](std::string &b) { b += 'x'; }); }},
    };
    for (const auto &[what, damage] : damages) {
        Fixture f;
        f.cache.store("grid", kKey, 1, payload(5000, 1));
        damage(f.cache.entryPath("grid", kKey));
        EXPECT_FALSE(f.cache.load("grid", kKey, 1).has_value()) << what;
        ASSERT_EQ(f.warnings.size(), 1u) << what;
        EXPECT_NE(f.warnings[0].find(f.cache.entryPath("grid", kKey).string()), std::string::npos);
        EXPECT_FALSE(std::filesystem::exists(f.cache.entryPath("grid", kKey))) << what;
        // And the next store makes it whole again.
        f.cache.store("grid", kKey, 1, payload(5000, 1));
        std::optional<CacheEntry> again = f.cache.load("grid", kKey, 1);
        ASSERT_TRUE(again.has_value()) << what;
        EXPECT_EQ(again->payload, payload(5000, 1)) << what;
    }
    {
        Fixture f; // written by another version of the format
        f.cache.store("grid", kKey, 1, payload(5000, 1));
        EXPECT_FALSE(f.cache.load("grid", kKey, 2).has_value());
        ASSERT_EQ(f.warnings.size(), 1u);
        EXPECT_NE(f.warnings[0].find("another version"), std::string::npos) << f.warnings[0];
    }
    {
        Fixture f; // an entry renamed to another key's file
        const std::string other = "ffffffffffffffffffffffffffffffff";
        f.cache.store("grid", kKey, 1, payload(5000, 1));
        std::filesystem::rename(f.cache.entryPath("grid", kKey), f.cache.entryPath("grid", other));
        EXPECT_FALSE(f.cache.load("grid", other, 1).has_value());
        ASSERT_EQ(f.warnings.size(), 1u);
        EXPECT_NE(f.warnings[0].find("another key"), std::string::npos) << f.warnings[0];
    }
}

TEST(DiskCache, KeepsWithinItsSizeDroppingTheLeastRecentlyUsed) {
    TempDir dir;
    std::vector<std::string> warnings;
    // Room for three entries of 10,000 bytes (plus headers), not four.
    DiskCache cache(
        DiskCacheOptions{dir.path(), 35'000, [&](const std::string &w) { warnings.push_back(w); }});
    auto key = [](int i) { return std::string(31, 'a') + char('0' + i); };
    auto age = [&](int i, int secondsAgo) {
        std::filesystem::last_write_time(cache.entryPath("grid", key(i)),
                                         std::filesystem::file_time_type::clock::now() -
                                             std::chrono::seconds(secondsAgo));
    };
    for (int i = 0; i < 3; ++i) {
        cache.store("grid", key(i), 1, payload(10'000, char(i)));
        age(i, 100 - i); // 0 oldest
    }
    ASSERT_TRUE(cache.load("grid", key(0), 1).has_value()); // 0 is now the most recent
    cache.store("grid", key(3), 1, payload(10'000, 3));
    EXPECT_TRUE(std::filesystem::exists(cache.entryPath("grid", key(0)))) << "used: kept";
    EXPECT_FALSE(std::filesystem::exists(cache.entryPath("grid", key(1)))) << "least recent";
    EXPECT_TRUE(std::filesystem::exists(cache.entryPath("grid", key(2))));
    EXPECT_TRUE(std::filesystem::exists(cache.entryPath("grid", key(3)))) << "just written";
    // An entry larger than the whole cache is not kept, and pushes nothing else out.
    cache.store("grid", key(4), 1, payload(50'000, 4));
    EXPECT_FALSE(std::filesystem::exists(cache.entryPath("grid", key(4))));
    for (int i : {0, 2, 3})
        EXPECT_TRUE(std::filesystem::exists(cache.entryPath("grid", key(i)))) << i;
    EXPECT_TRUE(warnings.empty());
}

// Two processes store the same entry at the same moment, many times over: every load in
// between and after sees either nothing or the whole entry, and no temporary file is left.
TEST(DiskCache, TwoProcessesFillingOneEntryLeaveOneWholeEntry) {
    TempDir dir;
    const std::string bytes = payload(4 << 20, 9);
    std::vector<pid_t> children;
    for (int child = 0; child < 2; ++child) {
        pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            DiskCache cache(DiskCacheOptions{dir.path(), uint64_t(1) << 30,
                                             [](const std::string &) { ::_exit(3); }});
            for (int round = 0; round < 20; ++round) {
                cache.store("grid", kKey, 1, bytes);
                std::optional<CacheEntry> back = cache.load("grid", kKey, 1);
                if (back && back->payload != bytes)
                    ::_exit(2);
            }
            ::_exit(0);
        }
        children.push_back(pid);
    }
    for (pid_t pid : children) {
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
            << "a process read a wrong entry (2) or was warned (3): " << WEXITSTATUS(status);
    }
    std::vector<std::string> warnings;
    DiskCache cache(DiskCacheOptions{dir.path(), uint64_t(1) << 30,
                                     [&](const std::string &w) { warnings.push_back(w); }});
    std::optional<CacheEntry> back = cache.load("grid", kKey, 1);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->payload, bytes);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(DiskCache, AnUnwritableDirectoryWarnsAndGoesOn) {
    TempDir dir;
    std::ofstream(dir.path() / "file") << "not a directory";
    std::vector<std::string> warnings;
    DiskCache cache(DiskCacheOptions{dir.path() / "file" / "cache", uint64_t(1) << 30,
                                     [&](const std::string &w) { warnings.push_back(w); }});
    cache.store("grid", kKey, 1, "bytes");
    EXPECT_FALSE(cache.load("grid", kKey, 1).has_value());
    EXPECT_EQ(warnings.size(), 1u);
    // A run stores more than once (its grid, its pipelines): the user is told once.
    cache.store("pipelines", kKey, 1, "more bytes");
    EXPECT_EQ(warnings.size(), 1u);
}

TEST(DiskCache, DefaultDirectoryFollowsTheEnvironment) {
    const char *saved[3] = {std::getenv("PRISM_CACHE_DIR"), std::getenv("XDG_CACHE_HOME"),
                            std::getenv("HOME")};
    std::string keep[3];
    for (int i = 0; i < 3; ++i)
        keep[i] = saved[i] ? saved[i] : "";
    ::setenv("HOME", "/home/u", 1);
    ::unsetenv("PRISM_CACHE_DIR");
    ::unsetenv("XDG_CACHE_HOME");
    EXPECT_EQ(DiskCache::defaultDirectory(), "/home/u/.cache/prism");
    ::setenv("XDG_CACHE_HOME", "/x", 1);
    EXPECT_EQ(DiskCache::defaultDirectory(), "/x/prism");
    ::setenv("PRISM_CACHE_DIR", "/p", 1);
    EXPECT_EQ(DiskCache::defaultDirectory(), "/p");
    const char *names[3] = {"PRISM_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
    for (int i = 0; i < 3; ++i) {
        if (saved[i])
            ::setenv(names[i], keep[i].c_str(), 1);
        else
            ::unsetenv(names[i]);
    }
}

} // namespace
} // namespace prism
