#pragma once
// Running a command-line tool as a user does: its exit code, stdout, and stdout + stderr.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace prism::test {

struct CliResult {
    int exitCode;
    std::string out; // stdout and stderr together
    std::string stdoutOnly;
};

inline CliResult runTool(const std::string &exe, const std::string &args) {
    std::filesystem::path errFile =
        std::filesystem::temp_directory_path() / ("prism-cli-" + std::to_string(::getpid()));
    std::string command = exe + " " + args + " 2>" + errFile.string();
    CliResult result{};
    FILE *pipe = ::popen(command.c_str(), "r");
    std::array<char, 4096> buffer;
    size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        result.stdoutOnly.append(buffer.data(), n);
    int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(errFile);
    result.out = result.stdoutOnly + std::string(std::istreambuf_iterator<char>(err), {});
    std::filesystem::remove(errFile);
    return result;
}

} // namespace prism::test
