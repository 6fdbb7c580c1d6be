#include "scene/mtl_loader.h"

#include "core/error.h"
#include "scene/diagnostics.h"
#include "scene/number_parser.h"
#include "scene/tokenizer.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>
#include <utility>

namespace prism {
namespace {

std::string lowerCase(std::string_view word) {
    std::string lower(word);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return lower;
}

float mtlNumber(std::string_view word) {
    ParsedFloat parsed = parseFloat(word);
    if (!parsed.ok())
        throw LineError(describeBadNumber(word, parsed.problem));
    return parsed.value;
}

std::string formatted(glm::vec3 v) {
    std::ostringstream text;
    text << v.x << ' ' << v.y << ' ' << v.z;
    return text.str();
}

// Parses one MTL statement into `material`; returns a warning, or "" when all is well.
class MtlStatementParser {
public:
    MtlStatementParser(std::string_view line, const std::vector<std::string_view> &words,
                       int lineNumber)
        : line_(line), words_(words), keyword_(lowerCase(words[0])), lineNumber_(lineNumber) {}

    std::string apply(MtlMaterial &material) const {
        if (keyword_ == "kd" || keyword_ == "ks") {
            std::optional<glm::vec3> colour = rgb();
            if (!colour)
                return std::string("'").append(words_[0]).append(" ").append(words_[1]) +
                       "' (spectral/xyz colours) is not supported; ignored";
            if (colour->x < 0 || colour->y < 0 || colour->z < 0)
                return "negative " + std::string(words_[0]) + " " + formatted(*colour) + " ignored";
            (keyword_ == "kd" ? material.kd : material.ks) = colour;
        } else if (keyword_ == "ns") {
            float ns = single();
            if (ns < 0)
                return "negative Ns ignored";
            material.ns = ns;
        } else if (keyword_ == "ni") {
            float ni = single();
            if (ni <= 0)
                return "Ni must be > 0; ignored (ior stays 1.5)";
            material.ni = ni;
        } else if (keyword_ == "d" || keyword_ == "tr") {
            float value = last(); // `d -halo 0.5` has its value last
            if (value < 0 || value > 1)
                return std::string(words_[0]) + " must be in [0, 1]; ignored";
            (keyword_ == "d" ? material.d : material.tr) = value;
        } else if (keyword_ == "map_kd") {
            material.texturePath = texturePath();
            material.textureLine = lineNumber_;
        } else if (keyword_ == "bump" || keyword_ == "map_bump") {
            material.bumpScale = bumpMultiplier();
            material.bumpPath = texturePath();
            material.bumpLine = lineNumber_;
        } else if (keyword_ == "norm") {
            material.normalPath = texturePath();
            material.normalLine = lineNumber_;
        }
        return "";
    }

private:
    void needValues() const {
        if (words_.size() < 2)
            throw LineError("'" + std::string(words_[0]) + "' needs a value");
    }
    float single() const {
        needValues();
        return mtlNumber(words_[1]);
    }
    float last() const {
        needValues();
        return mtlNumber(words_.back());
    }
    // `Kd r g b` or `Kd r` (g = b = r); nullopt for the spectral and xyz forms.
    std::optional<glm::vec3> rgb() const {
        needValues();
        if (words_[1] == "spectral" || words_[1] == "xyz")
            return std::nullopt;
        if (words_.size() == 2)
            return glm::vec3(mtlNumber(words_[1]));
        if (words_.size() != 4)
            throw LineError("'" + std::string(words_[0]) + "' needs 1 or 3 numbers");
        return glm::vec3(mtlNumber(words_[1]), mtlNumber(words_[2]), mtlNumber(words_[3]));
    }
    // A map statement's words split into its options and its file, as tinyobjloader reads
    // them: options may stand before or after the file (`map_bump -imfchan r bump.jpg -bm 1.5`,
    // as in tinyobjloader's own test files), each followed by its fixed number of values (-o,
    // -s and -t by one to three numbers). The file is the words that are neither, joined by
    // spaces; a line without options keeps its whole rest, so names with spaces work.
    struct MapStatement {
        std::string path;
        std::optional<float> bumpMultiplier;
    };
    MapStatement mapStatement() const {
        needValues();
        MapStatement map;
        bool anyOption = false;
        std::string path;
        for (size_t i = 1; i < words_.size(); ++i) {
            std::string option = lowerCase(words_[i]);
            int values = optionValues(option);
            if (values == 0) {
                if (!path.empty())
                    path += ' ';
                path += words_[i];
                continue;
            }
            anyOption = true;
            if (option == "-bm") {
                if (i + 1 >= words_.size())
                    throw LineError("'-bm' needs a number");
                map.bumpMultiplier = mtlNumber(words_[i + 1]);
            }
            size_t first = i + 1;
            if (values < 0) // -o, -s, -t: up to three numbers, at least one
                while (i + 1 < words_.size() && i + 1 < first + 3 && parseFloat(words_[i + 1]).ok())
                    ++i;
            else
                i = std::min(words_.size() - 1, i + size_t(values));
        }
        map.path = anyOption ? path : std::string(restAfterFirstWord(line_));
        if (map.path.empty())
            throw LineError("'" + std::string(words_[0]) + "' needs the image's file name");
        std::replace(map.path.begin(), map.path.end(), '\\', '/');
        return map;
    }
    // How many values follow a texture option (-1: one to three numbers); 0 for a word that is
    // no option (the MTL specification's options, and tinyobjloader's -colorspace).
    static int optionValues(const std::string &word) {
        static const std::pair<const char *, int> kOptions[] = {
            {"-blendu", 1},  {"-blendv", 1}, {"-boost", 1},  {"-mm", 2},        {"-o", -1},
            {"-s", -1},      {"-t", -1},     {"-texres", 1}, {"-clamp", 1},     {"-bm", 1},
            {"-imfchan", 1}, {"-type", 1},   {"-cc", 1},     {"-colorspace", 1}};
        for (const auto &[name, values] : kOptions)
            if (word == name)
                return values;
        return 0;
    }
    std::string texturePath() const { return mapStatement().path; }
    // `-bm MULT` among a bump map's options, anywhere on the line (1 without).
    float bumpMultiplier() const { return mapStatement().bumpMultiplier.value_or(1.0f); }

    std::string_view line_;
    const std::vector<std::string_view> &words_;
    std::string keyword_;
    int lineNumber_;
};

} // namespace

const MtlMaterial *MtlLibrary::find(std::string_view name) const {
    for (auto it = materials.rbegin(); it != materials.rend(); ++it)
        if (it->name == name)
            return &*it;
    return nullptr;
}

MtlLibrary parseMtl(std::string_view text, const std::string &fileName,
                    std::vector<std::string> &warnings) {
    MtlLibrary library;
    LineCursor lines(text);
    std::string_view line;
    std::vector<std::string_view> words;
    auto warn = [&](const std::string &message) {
        warnings.push_back(warningAt(fileName, lines.lineNumber(), message));
    };
    while (lines.next(line)) {
        splitWords(line, words);
        if (words.empty())
            continue;
        try {
            if (lowerCase(words[0]) == "newmtl") {
                std::string name(restAfterFirstWord(line));
                if (name.empty())
                    throw LineError("newmtl needs a name");
                if (const MtlMaterial *earlier = library.find(name))
                    warn("material '" + name + "' is defined again (first at line " +
                         std::to_string(earlier->line) + "); the later one is used");
                library.materials.push_back(MtlMaterial{name, lines.lineNumber()});
                continue;
            }
            if (library.materials.empty())
                continue; // statements before the first newmtl belong to no material
            MtlMaterial &material = library.materials.back();
            std::string warning =
                MtlStatementParser(line, words, lines.lineNumber()).apply(material);
            if (!warning.empty())
                warn(warning);
        } catch (const LineError &e) {
            throw FileError(fileName, lines.lineNumber(), e.what());
        }
    }
    return library;
}

Material materialFromMtl(const MtlMaterial &mtl, std::string sceneName) {
    Material material;
    material.name = std::move(sceneName);
    if (mtl.kd)
        material.color = *mtl.kd;
    if (mtl.ks)
        material.specular = (mtl.ks->x + mtl.ks->y + mtl.ks->z) / 3.0f;
    if (mtl.ns)
        material.shininess = *mtl.ns;
    if (mtl.ni)
        material.ior = *mtl.ni;
    if (mtl.tr)
        material.transmit = *mtl.tr;
    else if (mtl.d)
        material.transmit = 1.0f - *mtl.d;
    material.bumpScale = mtl.bumpScale;
    return material;
}

} // namespace prism
