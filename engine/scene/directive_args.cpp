#include "scene/directive_args.h"

#include "scene/diagnostics.h"
#include "scene/number_parser.h"

#include <string>

namespace prism {
namespace {

const KeySpec *findKey(const DirectiveSpec &spec, const Token &token) {
    if (token.quoted)
        return nullptr;
    for (const KeySpec &key : spec.keys)
        if (key.name == token.text)
            return &key;
    return nullptr;
}

std::string usageOf(const DirectiveSpec &spec) {
    return "(usage: " + std::string(spec.usage) + ")";
}

[[noreturn]] void rejectStrayToken(const DirectiveSpec &spec, const Token &token) {
    // A word where a key could go is most likely a misspelt key; anything else is one
    // argument too many.
    bool looksLikeKey = !token.quoted && !spec.keys.empty() && !parseFloat(token.text).ok();
    if (looksLikeKey) {
        std::string known;
        for (const KeySpec &key : spec.keys)
            known += (known.empty() ? "" : ", ") + std::string(key.name);
        throw LineError("unknown key '" + token.text + "' for '" + std::string(spec.keyword) +
                        "' (keys: " + known + ")");
    }
    throw LineError("extra argument '" + token.text + "' " + usageOf(spec));
}

} // namespace

const KeyedValues *DirectiveArgs::find(std::string_view key) const {
    for (const KeyedValues &group : keyed)
        if (group.key == key)
            return &group;
    return nullptr;
}

DirectiveArgs splitDirectiveArgs(const DirectiveSpec &spec, std::span<const Token> tokens) {
    DirectiveArgs args;
    size_t i = 0;
    auto positionalRoom = [&] {
        return spec.maxPositional == DirectiveSpec::kUnlimited ||
               int(args.positional.size()) < spec.maxPositional;
    };
    while (i < tokens.size() && positionalRoom()) {
        bool required = int(args.positional.size()) < spec.minPositional;
        if (!required && findKey(spec, tokens[i]))
            break;
        args.positional.push_back(&tokens[i++]);
    }
    if (int(args.positional.size()) < spec.minPositional)
        throw LineError("missing argument " + usageOf(spec));

    while (i < tokens.size()) {
        const KeySpec *key = findKey(spec, tokens[i]);
        if (!key)
            rejectStrayToken(spec, tokens[i]);
        if (!key->repeatable && args.find(key->name))
            throw LineError("'" + std::string(key->name) + "' is given twice");
        ++i;
        KeyedValues group{key->name, {}};
        while (int(group.values.size()) < key->valueCount && i < tokens.size() &&
               !findKey(spec, tokens[i]))
            group.values.push_back(&tokens[i++]);
        if (int(group.values.size()) < key->valueCount)
            throw LineError("'" + std::string(key->name) + "' needs " +
                            std::to_string(key->valueCount) +
                            (key->valueCount == 1 ? " value" : " values") + " " + usageOf(spec));
        while (int(group.values.size()) < key->valueCount + key->optionalValues &&
               i < tokens.size() && !findKey(spec, tokens[i]))
            group.values.push_back(&tokens[i++]);
        args.keyed.push_back(std::move(group));
    }
    return args;
}

} // namespace prism
