#pragma once
// Errors Prism reports to users. Every message is complete on its own: a scene error reads
// "FILE:LINE: what is wrong", a device error says what to install.
#include <stdexcept>
#include <string>

namespace prism {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An error located in an input file; what() is "FILE:LINE: message".
class FileError : public Error {
public:
    FileError(std::string file, int line, const std::string &message)
        : Error(file + ":" + std::to_string(line) + ": " + message), file_(std::move(file)),
          line_(line) {}
    const std::string &file() const { return file_; }
    int line() const { return line_; }

private:
    std::string file_;
    int line_;
};

} // namespace prism
