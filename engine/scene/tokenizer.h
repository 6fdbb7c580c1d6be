#pragma once
// Lexing shared by the .scene, OBJ and MTL readers: lines (LF or CRLF, last newline optional,
// UTF-8 byte-order mark skipped), '#' comments, words separated by spaces or tabs.
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// Walks the lines of a text, numbering them from 1, without the line-end characters.
class LineCursor {
public:
    explicit LineCursor(std::string_view text);
    bool next(std::string_view &line); // false after the last line
    int lineNumber() const { return lineNumber_; }

private:
    std::string_view rest_;
    bool done_ = false;
    int lineNumber_ = 0;
};

inline bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// A .scene token. Quoted tokens ("a b") keep their spaces and are never keys or keywords.
struct Token {
    std::string text;
    bool quoted = false;
};

// Splits one .scene line into tokens, dropping any comment. Returns false with `error` set for
// an unterminated quote or a quote glued to other characters.
bool tokenizeSceneLine(std::string_view line, std::vector<Token> &tokens, std::string &error);

// OBJ/MTL lexing (no quoting there): the line without its comment, and its words.
std::string_view stripComment(std::string_view line);
std::string_view trimBlanks(std::string_view text);
void splitWords(std::string_view line, std::vector<std::string_view> &words);
// Everything after the first word, trimmed: names and paths that may contain spaces.
std::string_view restAfterFirstWord(std::string_view line);

} // namespace prism
