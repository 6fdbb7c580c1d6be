#include "scene/tokenizer.h"

namespace prism {

LineCursor::LineCursor(std::string_view text) : rest_(text) {
    constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    if (rest_.substr(0, kUtf8Bom.size()) == kUtf8Bom)
        rest_.remove_prefix(kUtf8Bom.size());
}

bool LineCursor::next(std::string_view &line) {
    if (done_)
        return false;
    size_t end = rest_.find('\n');
    if (end == std::string_view::npos) {
        line = rest_;
        rest_ = {};
        done_ = true;
        if (line.empty()) // nothing after the last newline (or an empty text): no extra line
            return false;
    } else {
        line = rest_.substr(0, end);
        rest_.remove_prefix(end + 1);
    }
    if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
    ++lineNumber_;
    return true;
}

bool tokenizeSceneLine(std::string_view line, std::vector<Token> &tokens, std::string &error) {
    tokens.clear();
    size_t i = 0;
    while (i < line.size()) {
        char c = line[i];
        if (isBlank(c)) {
            ++i;
        } else if (c == '#') {
            break;
        } else if (c == '"') {
            size_t close = line.find('"', i + 1);
            if (close == std::string_view::npos) {
                error = "unterminated quoted string";
                return false;
            }
            size_t after = close + 1;
            if (after < line.size() && !isBlank(line[after]) && line[after] != '#') {
                error = "a quoted string must be followed by a space";
                return false;
            }
            tokens.push_back(Token{std::string(line.substr(i + 1, close - i - 1)), true});
            i = after;
        } else {
            size_t start = i;
            while (i < line.size() && !isBlank(line[i]) && line[i] != '#') {
                if (line[i] == '"') {
                    error = "a quote may only start a token";
                    return false;
                }
                ++i;
            }
            tokens.push_back(Token{std::string(line.substr(start, i - start)), false});
        }
    }
    return true;
}

std::string_view stripComment(std::string_view line) {
    size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

std::string_view trimBlanks(std::string_view text) {
    while (!text.empty() && isBlank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back()))
        text.remove_suffix(1);
    return text;
}

void splitWords(std::string_view line, std::vector<std::string_view> &words) {
    words.clear();
    line = stripComment(line);
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i]))
            ++i;
        size_t start = i;
        while (i < line.size() && !isBlank(line[i]))
            ++i;
        if (i > start)
            words.push_back(line.substr(start, i - start));
    }
}

std::string_view restAfterFirstWord(std::string_view line) {
    line = trimBlanks(stripComment(line));
    size_t i = 0;
    while (i < line.size() && !isBlank(line[i]))
        ++i;
    return trimBlanks(line.substr(i));
}

} // namespace prism
