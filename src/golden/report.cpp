// The HTML report of `drt test --report DIR`: one section per failed test with
// candidate, golden, error heatmap and (statistical tests) z-score map side by
// side and the comparison's figures, then the passed tests with their golden
// previews. The pictures are embedded in index.html (data: URIs), so the page
// is one file a CI system can show as an artefact; the candidate's EXR is
// written beside it.
#include "golden/golden.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace fs = std::filesystem;

namespace drt::golden {

namespace {

std::string base64(const std::string& bytes) {
    static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t group = uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
        if (i + 1 < bytes.size())
            group |= uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size())
            group |= uint32_t(static_cast<unsigned char>(bytes[i + 2]));
        out += digits[(group >> 18) & 63];
        out += digits[(group >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(group >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[group & 63] : '=';
    }
    return out;
}

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The image as an 8-bit sRGB PNG (clamped) in a data: URI, so the page holds
// every picture itself and can be viewed as a single CI artefact. The PNG is
// written through the one image I/O path into the report folder, read back
// and removed.
std::string pngDataUri(const fs::path& dir, const std::string& name, const Image& image, std::string& problem) {
    const fs::path file = dir / (name + ".png");
    if (problem = writeImage(file.string(), image); !problem.empty())
        return "";
    const std::string bytes = fileBytes(file);
    std::error_code ec;
    fs::remove(file, ec);
    return "data:image/png;base64," + base64(bytes);
}

std::string figure(const std::string& source, const std::string& caption) {
    return fmt::format("<figure><img src=\"{0}\" alt=\"{1}\"><figcaption>{1}</figcaption></figure>\n",
                       escapeMarkup(source), escapeMarkup(caption));
}

// The comparison's figures, only those that mean something under the policy:
// an exact test counts differing pixels, a statistical one has z-scores instead
// (every pixel of a noisy render differs).
std::string figuresTable(const CaseResult& result) {
    const CompareResult& r = *result.comparison;
    std::string rows;
    auto row = [&rows](const std::string& name, const std::string& value) {
        rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, escapeMarkup(value));
    };
    std::string channels;
    for (int c = 0; c < r.channels; ++c) {
        if (c) channels += '/';
        channels += channelName(c);
    }
    row("size", fmt::format("{}x{}, channels {}", r.width, r.height, channels));
    row("NaN/Inf pixels", std::to_string(r.nonFinitePixels));
    row("RMSE", fmt::format("{:.6g}", r.rmse));
    row("relMSE", fmt::format("{:.6g}", r.relMse));
    row("mean signed error (bias)", fmt::format("{:+.6g} (positive: the candidate is brighter)", r.meanSignedError));
    row("max error", fmt::format("{:.6g} at ({}, {}) in {}", r.maxError, r.maxErrorX, r.maxErrorY,
                                 channelName(r.maxErrorChannel)));
    row("PSNR", std::isinf(r.psnr) ? "identical" : fmt::format("{:.2f} dB", r.psnr));
    if (r.statistical) {
        std::string z;
        for (size_t c = 0; c < r.globalZ.size(); ++c)
            z += fmt::format("{}{} {:+.2f}", z.empty() ? "" : ", ", channelName(int(c)), r.globalZ[c]);
        row("global z per channel", fmt::format("{} (reject beyond ±{:.2f})", z, r.globalZThreshold));
        row("failing tiles", fmt::format("{} of {} (|z| > {:.2f}, alpha {:g})", r.failingTiles, r.tileTests,
                                         r.tileZThreshold, result.settings.alpha));
        row("worst tile", fmt::format("at ({}, {}) in {}: z {:+.2f}, mean error {:+.4g}", r.worstTile.x0,
                                      r.worstTile.y0, channelName(r.worstTile.channel), r.worstTile.z,
                                      r.worstTile.meanError));
    } else if (result.settings.failThreshold > 0) {
        row("pixels over the fail threshold",
            fmt::format("{} of {} ({:.3g}%; fail {:g}, allowed {:g}%)", r.failingPixels, r.pixelCount,
                        100.0 * double(r.failingPixels) / double(std::max<int64_t>(r.pixelCount, 1)),
                        result.settings.failThreshold, result.settings.failPercent));
    } else {
        row("pixels that differ", fmt::format("{} of {} ({:.3g}%)", r.failingPixels, r.pixelCount,
                                              100.0 * double(r.failingPixels) /
                                                  double(std::max<int64_t>(r.pixelCount, 1))));
    }
    return "<table>\n" + rows + "</table>\n";
}

const char* kStyle = R"(body { font-family: sans-serif; margin: 2em; }
section { border-top: 1px solid #ccc; padding-top: 1em; margin-top: 1em; }
figure { display: inline-block; margin: 0 1em 1em 0; text-align: center; }
img { width: 256px; image-rendering: pixelated; border: 1px solid #888; }
img.thumb { width: 96px; }
table { border-collapse: collapse; } th, td { text-align: left; padding: 0.1em 0.8em 0.1em 0; }
.FAIL, .ERROR, .MISSING { color: #b00; })";

} // namespace

std::string writeReport(const std::string& reportDir, const RunSummary& summary) {
    std::error_code ec;
    fs::create_directories(reportDir, ec);
    if (!fs::is_directory(reportDir, ec))
        return fmt::format("{}: cannot create the report folder", reportDir);
    const fs::path dir(reportDir);

    std::string body, passedRows;
    int listed = 0;
    for (const CaseResult& r : summary.cases) {
        if (r.outcome == Outcome::Pass || r.outcome == Outcome::Updated) {
            // A passing test: its golden preview, if there is one, in a gallery row.
            std::string thumbnail;
            if (!r.previewPath.empty()) {
                const std::string bytes = fileBytes(r.previewPath);
                if (!bytes.empty())
                    thumbnail = fmt::format("<img class=\"thumb\" src=\"data:image/png;base64,{}\" alt=\"{}\">",
                                            base64(bytes), escapeMarkup(r.name));
            }
            passedRows += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{:.2f} s</td><td>{}</td></tr>\n",
                                      thumbnail, escapeMarkup(r.name), policyName(r.policy), r.seconds,
                                      outcomeName(r.outcome));
            continue;
        }
        ++listed;
        body += fmt::format(
            "<section id=\"{0}\">\n<h2>{0} <span class=\"{1}\">{1}</span> ({2} policy)</h2>\n<p>{3}</p>\n",
            escapeMarkup(r.name), outcomeName(r.outcome), policyName(r.policy), escapeMarkup(r.message));
        if (!r.scenePath.empty())
            body += fmt::format("<p>scene: <code>{}</code></p>\n", escapeMarkup(r.scenePath));
        if (!r.details.empty())
            body += "<pre>" + escapeMarkup(r.details) + "</pre>\n";
        if (r.candidate.width == 0 || r.golden.width == 0) {
            body += "</section>\n";
            continue;
        }
        // The pictures, embedded; the candidate also as an EXR file beside the
        // page so it can be inspected or compared by hand.
        const bool sameSize = r.candidate.width == r.golden.width && r.candidate.height == r.golden.height &&
                              r.candidate.channels == r.golden.channels;
        std::vector<std::pair<Image, std::string>> figures;
        figures.emplace_back(r.candidate, "candidate");
        figures.emplace_back(r.golden, "golden");
        if (sameSize) {
            const double scale = r.comparison ? r.comparison->maxError : 0;
            figures.emplace_back(
                errorHeatmap(r.candidate, r.golden),
                fmt::format("heatmap of |error|: black 0, pale yellow {:.3g} (square-root ramp), green NaN/Inf", scale));
            if (r.policy == Policy::Statistical && r.goldenVariance.width == r.golden.width) {
                VarianceImages variance;
                variance.reference = &r.goldenVariance;
                if (r.candidateVariance.width == r.candidate.width)
                    variance.candidate = &r.candidateVariance;
                figures.emplace_back(zScoreMap(r.candidate, r.golden, variance),
                                     "z-map of candidate - golden: blue -4, white 0, red +4");
            }
        }
        for (size_t i = 0; i < figures.size(); ++i) {
            std::string problem;
            const std::string uri = pngDataUri(dir, fmt::format(".{}.figure{}", r.name, i), figures[i].first, problem);
            if (!problem.empty())
                return problem;
            body += figure(uri, figures[i].second);
        }
        if (r.comparison)
            body += figuresTable(r);
        const std::string exr = r.name + ".candidate.exr";
        if (std::string problem = writeImage((dir / exr).string(), r.candidate); !problem.empty())
            return problem;
        body += fmt::format("<p><a href=\"{0}\">{0}</a>: the candidate in linear floats.</p>\n", escapeMarkup(exr));
        body += "</section>\n";
    }
    if (!passedRows.empty())
        body += "<section id=\"passed\">\n<h2>Passed</h2>\n<table>\n"
                "<tr><th>golden</th><th>test</th><th>policy</th><th>time</th><th></th></tr>\n" +
                passedRows + "</table>\n</section>\n";

    const std::string title = fmt::format("drt test {}: {} passed, {} failed, {} missing, {} errors", summary.folder,
                                          summary.passed, summary.failed, summary.missing, summary.errors);
    const std::string page = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>\n"
        "<style>\n{1}\n</style>\n</head>\n<body>\n<h1>{0}</h1>\n{2}{3}</body>\n</html>\n",
        escapeMarkup(title), kStyle, listed == 0 ? "<p>Every test passed.</p>\n" : "", body);
    return writeTextFile((dir / "index.html").string(), page);
}

} // namespace drt::golden
