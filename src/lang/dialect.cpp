#include "lang/dialect.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace drt {

const Dialect& drtDialect() {
    static const Dialect d{};
    return d;
}

const Dialect& povDialect() {
    static const Dialect d = [] {
        Dialect p;
        p.kind = DialectKind::Pov;
        p.name = "pov";
        p.strictLexing = false;
        p.requireCommas = false;
        p.recoverAfterErrors = false;
        p.strictValues = false;
        p.unsupportedIsError = false;
        p.rightFromImageAspect = false;
        p.fullAreaLights = false;
        p.mediaAttenuationDefault = false;
        p.drtPatternDefaults = false;
        p.modifyBlocks = true;
        p.versionGammaRules = true;
        p.povCameraRules = true;
        p.keepUnions = true;
        p.legacySyntax = true;
        return p;
    }();
    return d;
}

std::optional<DialectKind> dialectNamed(const std::string& name) {
    if (name == "drt") return DialectKind::Drt;
    if (name == "pov") return DialectKind::Pov;
    return std::nullopt;
}

const Dialect& dialectOf(DialectKind kind) { return kind == DialectKind::Pov ? povDialect() : drtDialect(); }

DialectKind dialectForPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".pov" || ext == ".inc" || ext == ".mac" ? DialectKind::Pov : DialectKind::Drt;
}

} // namespace drt
