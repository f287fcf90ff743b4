#include "distributed/render_identity.h"

#include "sampling/sampler.h"

#include <fmt/format.h>

#include <iterator>
#include <sstream>
#include <vector>

namespace drt {

RenderIdentity renderIdentity(const RenderOptions& options, const std::string& sceneHash) {
    RenderIdentity identity;
    identity.version = DRT_VERSION;
    identity.sceneHash = sceneHash;
    const std::string sampler = options.sampler.empty() ? defaultSamplerName() : options.sampler;
    const std::string adaptive =
        options.adaptive ? fmt::format("error:{},min:{},max:{},floor:{}", options.adaptiveError,
                                       options.minSamplesPerPixel, options.maxSamplesPerPixel,
                                       options.adaptiveDarkFloor)
                         : "off";
    identity.settings = fmt::format("size={}x{} spp={} seed={} sampler={} adaptive={}", options.width,
                                    options.height, options.adaptive ? 0 : options.samplesPerPixel, options.seed,
                                    sampler, adaptive);
    // Left out at its default, so that the settings of a render that does not
    // split its light samples read as they did before the option.
    if (options.lightSamples != 1) identity.settings += fmt::format(" light_samples={}", options.lightSamples);
    return identity;
}

namespace {

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

} // namespace

std::string describeDifference(const RenderIdentity& here, const RenderIdentity& there, const std::string& thereName) {
    if (here.version != there.version)
        return fmt::format("'{}' was made by drt {}, this is drt {}", thereName, there.version, here.version);
    if (here.sceneHash != there.sceneHash)
        return fmt::format("'{}' is of another scene (scene hash {} there, {} here)", thereName,
                           there.sceneHash, here.sceneHash);
    if (here.settings == there.settings) return "";
    const std::vector<std::string> mine = words(here.settings), theirs = words(there.settings);
    std::string differences;
    for (size_t i = 0; i < std::max(mine.size(), theirs.size()); ++i) {
        const std::string a = i < mine.size() ? mine[i] : "", b = i < theirs.size() ? theirs[i] : "";
        if (a == b) continue;
        differences += fmt::format("{}{} there, {} here", differences.empty() ? "" : "; ", b, a);
    }
    return fmt::format("'{}' has other settings: {}", thereName, differences);
}

void addIdentity(Metadata& metadata, const RenderIdentity& identity, const std::optional<PixelWindow>& crop,
                 int width, int height) {
    metadata.emplace_back("drt:scene_sha1", identity.sceneHash);
    metadata.emplace_back("drt:settings", identity.settings);
    if (crop) {
        metadata.emplace_back("drt:crop", formatWindow(*crop));
        metadata.emplace_back("drt:full_size", fmt::format("{}x{}", width, height));
    }
}

std::optional<std::string> metadataValue(const Metadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key) return v;
    return std::nullopt;
}

std::optional<RenderIdentity> readIdentity(const Metadata& metadata) {
    const auto version = metadataValue(metadata, "drt:version");
    const auto hash = metadataValue(metadata, "drt:scene_sha1");
    const auto settings = metadataValue(metadata, "drt:settings");
    if (!version || !hash || hash->empty() || !settings) return std::nullopt;
    return RenderIdentity{*version, *hash, *settings};
}

std::string formatWindow(const PixelWindow& w) { return fmt::format("{},{},{},{}", w.x0, w.x1, w.y0, w.y1); }

std::optional<PixelWindow> parseWindow(const std::string& text) {
    PixelWindow w;
    char c1 = 0, c2 = 0, c3 = 0;
    std::istringstream in(text);
    if (!(in >> w.x0 >> c1 >> w.x1 >> c2 >> w.y0 >> c3 >> w.y1) || c1 != ',' || c2 != ',' || c3 != ',') return {};
    if (in.peek() != std::char_traits<char>::eof()) return {};
    return w;
}

} // namespace drt
