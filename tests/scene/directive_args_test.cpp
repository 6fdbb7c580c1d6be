// Positional arguments and key groups (engine/scene/directive_args.cpp).
#include <gtest/gtest.h>

#include "scene/diagnostics.h"
#include "scene/directive_args.h"

#include <string>
#include <vector>

namespace prism {
namespace {

const DirectiveSpec kMesh{"mesh",
                          "mesh PATH [NAME] [scale S] [rotate AXIS DEG]...",
                          1,
                          2,
                          {{"scale", 1}, {"rotate", 2, true}, {"color", 3}}};

std::vector<Token> words(std::initializer_list<const char *> texts) {
    std::vector<Token> tokens;
    for (const char *text : texts)
        tokens.push_back(Token{text, false});
    return tokens;
}

std::string errorOf(const DirectiveSpec &spec, const std::vector<Token> &tokens) {
    try {
        splitDirectiveArgs(spec, tokens);
    } catch (const LineError &e) {
        return e.what();
    }
    return "";
}

TEST(DirectiveArgs, SplitsPositionalsAndKeysInAnyOrder) {
    std::vector<Token> tokens =
        words({"a.obj", "red", "rotate", "x", "90", "scale", "2", "rotate", "y", "45"});
    DirectiveArgs args = splitDirectiveArgs(kMesh, tokens);
    ASSERT_EQ(args.positional.size(), 2u);
    EXPECT_EQ(args.positional[1]->text, "red");
    ASSERT_EQ(args.keyed.size(), 3u);
    EXPECT_EQ(args.keyed[0].key, "rotate");
    EXPECT_EQ(args.keyed[1].key, "scale");
    EXPECT_EQ(args.keyed[2].values[0]->text, "y"); // repeatable, kept in order
    EXPECT_EQ(args.find("scale")->values[0]->text, "2");
    EXPECT_EQ(args.find("color"), nullptr);
}

TEST(DirectiveArgs, OptionalPositionalIsNotTakenFromAKeyUnlessQuoted) {
    std::vector<Token> tokens = words({"a.obj", "scale", "2"});
    EXPECT_EQ(splitDirectiveArgs(kMesh, tokens).positional.size(), 1u);
    tokens[1].quoted = true; // mesh a.obj "scale" 2: NAME is "scale", then a stray "2"
    EXPECT_NE(errorOf(kMesh, tokens).find("extra argument '2'"), std::string::npos);
    // A required positional is taken even when it spells a key: `material color ...`.
    std::vector<Token> named = words({"scale"});
    EXPECT_EQ(splitDirectiveArgs(kMesh, named).positional[0]->text, "scale");
}

TEST(DirectiveArgs, ReportsMissingExtraUnknownDuplicateAndShortKeys) {
    EXPECT_NE(errorOf(kMesh, {}).find("missing argument"), std::string::npos);
    EXPECT_NE(errorOf(kMesh, words({"a", "b", "7"})).find("extra argument '7'"), std::string::npos);
    EXPECT_NE(errorOf(kMesh, words({"a", "b", "colour", "1"})).find("unknown key 'colour'"),
              std::string::npos);
    EXPECT_NE(errorOf(kMesh, words({"a", "scale", "1", "scale", "2"})).find("given twice"),
              std::string::npos);
    EXPECT_NE(errorOf(kMesh, words({"a", "color", "1", "1", "scale", "2"}))
                  .find("'color' needs 3 values"),
              std::string::npos);
    EXPECT_NE(errorOf(kMesh, words({"a", "scale"})).find("'scale' needs 1 value"),
              std::string::npos);
}

} // namespace
} // namespace prism
