#include "scene/mtl_loader.h"

#include "core/error.h"
#include "scene/diagnostics.h"
#include "scene/number_parser.h"
#include "scene/tokenizer.h"

#include <algorithm>
#include <cctype>
#include <sstream>

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
    // With options (`map_Kd -s 1 1 1 file.png`) the file is the last word; without, the whole
    // rest of the line, so names with spaces work.
    std::string texturePath() const {
        needValues();
        std::string path(words_[1].front() == '-' ? words_.back() : restAfterFirstWord(line_));
        std::replace(path.begin(), path.end(), '\\', '/');
        return path;
    }

    // `-bm MULT` among a bump map's options (1 without); the file must still follow it.
    float bumpMultiplier() const {
        for (size_t i = 1; i < words_.size(); ++i) {
            if (lowerCase(words_[i]) != "-bm")
                continue;
            if (i + 2 >= words_.size())
                throw LineError("'-bm' needs a number and then the bump map's file");
            return mtlNumber(words_[i + 1]);
        }
        return 1.0f;
    }

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
