// Lines, comments, quoting and word splitting (engine/scene/tokenizer.cpp).
#include <gtest/gtest.h>

#include "scene/tokenizer.h"

#include <string>
#include <vector>

namespace prism {
namespace {

std::vector<std::string> linesOf(std::string_view text, std::vector<int> *numbers = nullptr) {
    LineCursor cursor(text);
    std::vector<std::string> lines;
    std::string_view line;
    while (cursor.next(line)) {
        lines.emplace_back(line);
        if (numbers)
            numbers->push_back(cursor.lineNumber());
    }
    return lines;
}

std::vector<Token> tokens(std::string_view line) {
    std::vector<Token> result;
    std::string error;
    EXPECT_TRUE(tokenizeSceneLine(line, result, error)) << error;
    return result;
}

TEST(LineCursor, HandlesCrlfAndNumbersLinesFromOne) {
    std::vector<int> numbers;
    EXPECT_EQ(linesOf("a\r\nb\r\n\r\nc\r\n", &numbers),
              (std::vector<std::string>{"a", "b", "", "c"}));
    EXPECT_EQ(numbers, (std::vector<int>{1, 2, 3, 4}));
}

TEST(LineCursor, KeepsALastLineWithoutNewline) {
    EXPECT_EQ(linesOf("a\nb"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(linesOf("a\r\nb\r"), (std::vector<std::string>{"a", "b"}));
}

TEST(LineCursor, EmptyTextHasNoLinesAndByteOrderMarkIsSkipped) {
    EXPECT_TRUE(linesOf("").empty());
    EXPECT_EQ(linesOf("\xEF\xBB\xBFsphere\n"), (std::vector<std::string>{"sphere"}));
}

TEST(SceneTokens, SplitsOnSpacesAndTabsAndDropsComments) {
    std::vector<Token> t = tokens("\tsphere  0\t1 2 # a comment \"with quote");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].text, "sphere");
    EXPECT_EQ(t[3].text, "2");
    EXPECT_FALSE(t[0].quoted);
    EXPECT_TRUE(tokens("   # only a comment").empty());
    EXPECT_TRUE(tokens("").empty());
    EXPECT_EQ(tokens("a#b").size(), 1u); // a comment may follow a token directly
}

TEST(SceneTokens, QuotedTokensKeepSpacesAndHashes) {
    std::vector<Token> t = tokens("mesh \"my models/a #1.obj\" red");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].text, "my models/a #1.obj");
    EXPECT_TRUE(t[1].quoted);
    EXPECT_EQ(t[2].text, "red");
    std::vector<Token> empty = tokens("use \"\"");
    ASSERT_EQ(empty.size(), 2u);
    EXPECT_EQ(empty[1].text, "");
    EXPECT_TRUE(empty[1].quoted);
}

TEST(SceneTokens, RejectsBadQuoting) {
    std::vector<Token> t;
    std::string error;
    EXPECT_FALSE(tokenizeSceneLine("mesh \"a.obj", t, error));
    EXPECT_NE(error.find("unterminated"), std::string::npos);
    EXPECT_FALSE(tokenizeSceneLine("mesh \"a\"b", t, error));
    EXPECT_FALSE(tokenizeSceneLine("mesh a\"b\"", t, error));
}

TEST(ObjWords, SplitsWordsAndStripsComments) {
    std::vector<std::string_view> words;
    splitWords("  Ka 0.63 0.065\t0.05 # Red\r", words);
    EXPECT_EQ(words, (std::vector<std::string_view>{"Ka", "0.63", "0.065", "0.05"}));
    EXPECT_EQ(restAfterFirstWord("mtllib  my file.mtl  # c"), "my file.mtl");
    EXPECT_EQ(restAfterFirstWord("usemtl"), "");
}

} // namespace
} // namespace prism
