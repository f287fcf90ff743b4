// Provenance metadata of rendered images (render/provenance.h).
#include "render/provenance.h"

#include "core/sha1.h"
#include "sampling/sampler.h"

#include <algorithm>
#include <fmt/format.h>
#include <thread>

namespace drt {

namespace {

void put(Metadata& entries, const std::string& key, const std::string& value) {
    auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.first == key; });
    if (it != entries.end())
        it->second = value;
    else
        entries.emplace_back(key, value);
}

std::string localTime(std::time_t t, const char* format) {
    std::tm local{};
    localtime_r(&t, &local);
    char text[64];
    return std::strftime(text, sizeof text, format, &local) ? text : "";
}

} // namespace

void Provenance::identify(const std::string& key, const std::string& value) { put(identity_, key, value); }

void Provenance::record(const std::string& key, const std::string& value) { put(run_, key, value); }

Metadata Provenance::metadata(bool reproducible) const {
    Metadata out = identity_;
    std::string dateTime;
    if (!reproducible) {
        out.insert(out.end(), run_.begin(), run_.end());
        for (const auto& [key, value] : run_)
            if (key == "drt:started" && value.size() >= 19) {
                // EXIF/TIFF DateTime: "YYYY:MM:DD HH:MM:SS" from "YYYY-MM-DDTHH:MM:SS...".
                dateTime = value.substr(0, 19);
                std::replace(dateTime.begin(), dateTime.begin() + 10, '-', ':');
                dateTime[10] = ' ';
            }
    }
    out.emplace_back("Software", fmt::format("drt {}", DRT_VERSION));
    out.emplace_back("DateTime", dateTime);
    return out;
}

Provenance renderProvenance(const std::string& scenePath, const std::string& sceneSha1,
                            const RenderOptions& options, const std::string& filter) {
    Provenance p;
    p.identify("drt:version", DRT_VERSION);
    const size_t slash = scenePath.find_last_of('/');
    p.identify("drt:scene", slash == std::string::npos ? scenePath : scenePath.substr(slash + 1));
    if (!sceneSha1.empty())
        p.identify("drt:scene_sha1", sceneSha1);
    p.identify("drt:size", fmt::format("{}x{}", options.width, options.height));
    p.identify("drt:seed", std::to_string(options.seed));
    p.identify("drt:spp", options.adaptive ? fmt::format("adaptive (error {} min {} max {})", options.adaptiveError,
                                                         options.minSamplesPerPixel, options.maxSamplesPerPixel)
                                           : std::to_string(options.samplesPerPixel));
    p.identify("drt:sampler", options.sampler.empty() ? defaultSamplerName() : options.sampler);
    p.identify("drt:filter", filter);
    return p;
}

void recordRun(Provenance& provenance, const RenderOptions& options, const RenderStats& stats,
               const std::string& commandLine, std::time_t started) {
    if (!commandLine.empty())
        provenance.record("drt:command_line", commandLine);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    provenance.record("drt:threads", options.threads > 0 ? std::to_string(options.threads)
                                                         : fmt::format("all cores ({})", cores));
    provenance.record("drt:started", localTime(started, "%Y-%m-%dT%H:%M:%S%z"));
    provenance.record("drt:render_seconds", fmt::format("{:.3f}", stats.buildSeconds + stats.renderSeconds));
}

std::string sha1Hex(std::string_view bytes) {
    Sha1 sha;
    sha.append(bytes);
    return sha.hexDigest();
}

std::string sceneTextSha1(const SourceFiles& files) {
    Sha1 sha;
    for (int id = 0; id < files.count(); ++id) {
        // Each file framed by its length, so that moving text from one file to
        // the next ("a" + "bc" against "ab" + "c") changes the hash.
        const std::string_view text = files.text(id);
        sha.append(std::to_string(text.size()) + "\n");
        sha.append(text);
    }
    return sha.hexDigest();
}

std::string shellCommandLine(int argc, const char* const* argv) {
    std::string line;
    for (int i = 0; i < argc; ++i) {
        const std::string word = argv[i];
        const bool plain = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                                   "0123456789-_./=:,+@%") == std::string::npos;
        std::string quoted = plain ? word : "'";
        if (!plain) {
            for (char c : word)
                quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
            quoted += "'";
        }
        line += (i ? " " : "") + quoted;
    }
    return line;
}

} // namespace drt
