#pragma once
// Splits a .scene directive's tokens into positional arguments and `key value...` groups and
// checks their counts, so each directive handler sees well-formed arguments only.
#include <span>
#include <string_view>
#include <vector>

#include "scene/tokenizer.h"

namespace prism {

struct KeySpec {
    std::string_view name;
    int valueCount;
    bool repeatable = false;
    int optionalValues = 0; // more values it takes when the next tokens are not keys
};

struct DirectiveSpec {
    std::string_view keyword;
    std::string_view usage; // e.g. "sphere X Y Z RADIUS [NAME]", quoted in messages
    int minPositional = 0;
    int maxPositional = 0; // kUnlimited for `f`
    std::vector<KeySpec> keys;
    static constexpr int kUnlimited = -1;
};

struct KeyedValues {
    std::string_view key;
    std::vector<const Token *> values;
};

struct DirectiveArgs {
    std::vector<const Token *> positional;
    std::vector<KeyedValues> keyed; // in the order written
    const KeyedValues *find(std::string_view key) const;
};

// `tokens` are the ones after the keyword. Required positional arguments are taken as they
// come; an optional one is taken unless it is an unquoted key of this directive. Throws
// LineError for a missing or extra argument, an unknown key, a key given twice or a key with
// too few values.
DirectiveArgs splitDirectiveArgs(const DirectiveSpec &spec, std::span<const Token> tokens);

} // namespace prism
