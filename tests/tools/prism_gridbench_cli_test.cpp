// prism-gridbench as a user meets it: help, a bad grid named, and a tiny study's table and JSON.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "temp_dir_fixture.h"

namespace fs = std::filesystem;
using prism::test::CliResult;

namespace {

CliResult gridbench(const std::string &args) {
    return prism::test::runTool(PRISM_GRIDBENCH_EXE, args);
}

class PrismGridbenchCli : public prism::test::TempDirTest {
protected:
    fs::path scene_ = write("tiny.scene", "light 2 2 5\nsphere 0 0 0 1\nsphere 1 1 -1 0.5\n"
                                          "plane 0 -1 0 0 1 0\n");
};

TEST_F(PrismGridbenchCli, HelpNamesTheOptions) {
    CliResult r = gridbench("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char *word : {"--grids", "--runs", "--no-embree", "--json"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// --version answers without a scene, as the other tools do (issue 35).
TEST_F(PrismGridbenchCli, VersionNeedsNoScene) {
    CliResult r = gridbench("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("prism-gridbench 0.1.0"), std::string::npos) << r.out;
}

TEST_F(PrismGridbenchCli, BadGridIsNamed) {
    CliResult r = gridbench(scene_.string() + " --grids regular,fine");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("fine"), std::string::npos) << r.out;
}

TEST_F(PrismGridbenchCli, TableAndJsonForEveryGrid) {
    fs::path json = dir() / "builds.json";
    CliResult r =
        gridbench(scene_.string() + " --grids regular,adaptive,4 --runs 3 --json " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char *row :
         {"| tiny | 2 | regular |", "| tiny | 2 | adaptive |", "| tiny | 2 | 4 |"})
        EXPECT_NE(r.stdoutOnly.find(row), std::string::npos) << row << "\n" << r.stdoutOnly;
    nlohmann::json all = nlohmann::json::parse(std::ifstream(json));
    size_t grids = 0;
    for (const nlohmann::json &row : all) {
        EXPECT_EQ(row["build_ms"].size(), 3u) << "every build timed";
        if (row["grid"] == "embree")
            continue;
        ++grids;
        EXPECT_GT(row["cells"].get<uint64_t>(), 0u);
        EXPECT_GT(row["bytes"].get<uint64_t>(), 0u);
    }
    EXPECT_EQ(grids, 3u);
    EXPECT_EQ(all[all.size() - 1]["layout"], "4x4x4");
}

} // namespace
