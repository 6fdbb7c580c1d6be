// The command-line conventions every tool shares (tools/common/command_line.h, issue 35):
// --version and --help exit 0; a usage error, whether CLI11 finds it (an unknown option, a
// missing value) or the tool's own check of a value does, exits 2 with "TOOL: error: ..." and a
// pointer to --help, and writes nothing.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "temp_dir_fixture.h"

namespace {

using prism::test::CliResult;

struct Tool {
    const char *name, *exe;
    std::string badValue; // arguments whose value the tool's own check refuses
};

class CommandLine : public prism::test::TempDirTest {
protected:
    std::vector<Tool> tools() {
        std::string scene = write("ok.scene", "sphere 0 0 0 1\n").string();
        std::string png = (dir() / "out.png").string();
        return {{"prism-render", PRISM_RENDER_EXE, scene + " -o " + png + " --size 8by8"},
                {"prism-bench", PRISM_BENCH_EXE, scene + " --size 8by8"},
                {"prism-gridbench", PRISM_GRIDBENCH_EXE, scene + " --grids 0"},
                {"prism-merge", PRISM_MERGE_EXE, scene + " -o " + png + " --no-such-option"}};
    }
};

TEST_F(CommandLine, VersionAndHelpExitZero) {
    for (const Tool &t : tools()) {
        CliResult version = prism::test::runTool(t.exe, "--version");
        EXPECT_EQ(version.exitCode, 0) << t.name;
        EXPECT_NE(version.stdoutOnly.find(std::string(t.name) + " "), std::string::npos)
            << t.name << ": " << version.out;
        CliResult help = prism::test::runTool(t.exe, "--help");
        EXPECT_EQ(help.exitCode, 0) << t.name;
        EXPECT_NE(help.stdoutOnly.find("--help"), std::string::npos) << t.name;
    }
}

TEST_F(CommandLine, UsageErrorsExitTwoAndNameTheTool) {
    for (const Tool &t : tools()) {
        for (const std::string &args : {std::string("--no-such-option"), t.badValue}) {
            CliResult r = prism::test::runTool(t.exe, args);
            EXPECT_EQ(r.exitCode, 2) << t.name << " " << args << ": " << r.out;
            EXPECT_EQ(r.out.rfind(std::string(t.name) + ": error: ", 0), 0u)
                << t.name << " " << args << ": " << r.out;
            EXPECT_NE(r.out.find(std::string(t.name) + " --help"), std::string::npos) << r.out;
        }
    }
    EXPECT_EQ(entries().size(), 1u) << "only the scene: nothing written";
}

} // namespace
