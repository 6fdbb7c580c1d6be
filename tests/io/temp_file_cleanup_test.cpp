// A process stopped by SIGTERM (scancel), SIGINT or SIGHUP while it writes an image leaves
// neither the image nor its temporary file (io/temp_file_cleanup.h), and ends by that signal.
#include <csignal>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/staged_file.h"
#include "temp_dir_fixture.h"

namespace prism {
namespace {

using TempFileCleanup = test::TempDirTest;

TEST_F(TempFileCleanup, ASignalDuringAWriteRemovesTheTemporaryFile) {
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) {
        SCOPED_TRACE(signal);
        std::filesystem::path target = dir() / "frame.exr";
        pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) { // the writer, stopped in mid-write
            StagedFile staged(target);
            std::ofstream(staged.tempPath()) << "half an image";
            // The parent checks that the file was there: it names it in a marker.
            std::ofstream(dir() / "marker") << staged.tempPath().string();
            ::raise(signal);
            ::_exit(0); // not reached: the signal ends the process
        }
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        EXPECT_TRUE(WIFSIGNALED(status));
        EXPECT_EQ(WTERMSIG(status), signal) << "ended by the signal, as without the handler";
        std::string temp;
        std::ifstream(dir() / "marker") >> temp;
        EXPECT_FALSE(temp.empty()) << "the child wrote its temporary file";
        EXPECT_FALSE(std::filesystem::exists(temp)) << temp;
        EXPECT_FALSE(std::filesystem::exists(target));
        std::filesystem::remove(dir() / "marker");
    }
}

// After a commit, the file is the target's and a later signal removes nothing.
TEST_F(TempFileCleanup, ACommittedFileStays) {
    std::filesystem::path target = dir() / "frame.exr";
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        {
            StagedFile staged(target);
            std::ofstream(staged.tempPath()) << "a whole image";
            staged.commit();
        }
        ::raise(SIGTERM);
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_TRUE(std::filesystem::exists(target));
}

} // namespace
} // namespace prism
