// The HTML failure report of `drt test --report DIR`: one section per failed
// test with candidate, golden, error heatmap and (statistical tests) z-score
// map side by side, and the comparison's figures. Images are PNG files beside
// index.html, linked by relative paths, so the folder can be moved or archived.
#include "golden/golden.h"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace fs = std::filesystem;

namespace drt::golden {

namespace {

std::string escapeHtml(const std::string& text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += ch;
        }
    }
    return out;
}

std::string figure(const std::string& file, const std::string& caption) {
    return fmt::format("<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption>{1}</figcaption>"
                       "</figure>\n",
                       escapeHtml(file), escapeHtml(caption));
}

std::string figuresTable(const CompareResult& r) {
    std::string rows;
    auto row = [&rows](const std::string& name, const std::string& value) {
        rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, escapeHtml(value));
    };
    row("size", fmt::format("{}x{}, {} channels", r.width, r.height, r.channels));
    row("NaN/Inf pixels", std::to_string(r.nonFinitePixels));
    row("RMSE", fmt::format("{:.6g}", r.rmse));
    row("relMSE", fmt::format("{:.6g}", r.relMse));
    row("mean signed error (bias)", fmt::format("{:.6g}", r.meanSignedError));
    row("max error", fmt::format("{:.6g} at ({}, {}) channel {}", r.maxError, r.maxErrorX, r.maxErrorY,
                                 r.maxErrorChannel));
    row("PSNR", std::isinf(r.psnr) ? "identical" : fmt::format("{:.2f} dB", r.psnr));
    row("pixels over the fail threshold", std::to_string(r.failingPixels));
    if (r.statistical) {
        std::string z;
        for (double g : r.globalZ)
            z += fmt::format("{}{:+.2f}", z.empty() ? "" : ", ", g);
        row("global z per channel", fmt::format("{} (reject above {:.2f})", z, r.globalZThreshold));
        row("failing tiles",
            fmt::format("{} of {} (|z| > {:.2f})", r.failingTiles, r.tileTests, r.tileZThreshold));
        row("worst tile",
            fmt::format("at ({}, {}) channel {}: z {:+.2f}, mean error {:.4g}", r.worstTile.x0,
                        r.worstTile.y0, r.worstTile.channel, r.worstTile.z, r.worstTile.meanError));
    }
    return "<table>\n" + rows + "</table>\n";
}

const char* kStyle = R"(body { font-family: sans-serif; margin: 2em; }
section { border-top: 1px solid #ccc; padding-top: 1em; margin-top: 1em; }
figure { display: inline-block; margin: 0 1em 1em 0; text-align: center; }
img { width: 256px; image-rendering: pixelated; border: 1px solid #888; }
table { border-collapse: collapse; } th, td { text-align: left; padding: 0.1em 0.8em 0.1em 0; }
.FAIL, .ERROR, .MISSING { color: #b00; })";

} // namespace

std::string writeReport(const std::string& reportDir, const RunSummary& summary) {
    std::error_code ec;
    fs::create_directories(reportDir, ec);
    if (!fs::is_directory(reportDir, ec))
        return fmt::format("{}: cannot create the report folder", reportDir);
    const fs::path dir(reportDir);

    std::string body;
    int listed = 0;
    for (const CaseResult& r : summary.cases) {
        if (r.outcome == Outcome::Pass || r.outcome == Outcome::Updated)
            continue;
        ++listed;
        body += fmt::format(
            "<section id=\"{0}\">\n<h2>{0} <span class=\"{1}\">{1}</span> ({2})</h2>\n<p>{3}</p>\n",
            escapeHtml(r.name), outcomeName(r.outcome), policyName(r.policy), escapeHtml(r.message));
        if (!r.details.empty())
            body += "<pre>" + escapeHtml(r.details) + "</pre>\n";
        if (r.candidate.width == 0 || r.golden.width == 0) {
            body += "</section>\n";
            continue;
        }
        // The images: written as 8-bit sRGB PNG (clamped), the candidate also as
        // EXR so it can be inspected or promoted to the golden by hand.
        const bool sameSize = r.candidate.width == r.golden.width && r.candidate.height == r.golden.height &&
                              r.candidate.channels == r.golden.channels;
        std::vector<std::pair<std::string, std::string>> figures;
        std::vector<std::pair<std::string, Image>> images;
        images.emplace_back(r.name + ".candidate.png", r.candidate);
        images.emplace_back(r.name + ".candidate.exr", r.candidate);
        images.emplace_back(r.name + ".golden.png", r.golden);
        figures.emplace_back(r.name + ".candidate.png", "candidate");
        figures.emplace_back(r.name + ".golden.png", "golden");
        if (sameSize) {
            const double scale = r.comparison ? r.comparison->maxError : 0;
            images.emplace_back(r.name + ".diff.png", errorHeatmap(r.candidate, r.golden));
            figures.emplace_back(
                r.name + ".diff.png",
                fmt::format("|error|: black 0, pale yellow {:.3g} (square-root ramp), green NaN/Inf", scale));
            if (r.policy == Policy::Statistical && r.goldenVariance.width == r.golden.width) {
                VarianceImages variance;
                variance.reference = &r.goldenVariance;
                if (r.candidateVariance.width == r.candidate.width)
                    variance.candidate = &r.candidateVariance;
                images.emplace_back(r.name + ".zmap.png", zScoreMap(r.candidate, r.golden, variance));
                figures.emplace_back(r.name + ".zmap.png",
                                     "z-score of candidate - golden: blue -4, white 0, red +4");
            }
        }
        for (const auto& [file, image] : images)
            if (std::string problem = writeImage((dir / file).string(), image); !problem.empty())
                return problem;
        for (const auto& [file, caption] : figures)
            body += figure(file, caption);
        if (r.comparison)
            body += figuresTable(*r.comparison);
        body += fmt::format("<p><a href=\"{0}\">{0}</a>: the candidate in linear floats.</p>\n",
                            escapeHtml(r.name + ".candidate.exr"));
        body += "</section>\n";
    }

    const std::string title = fmt::format("drt test: {} passed, {} failed, {} missing, {} errors",
                                          summary.passed, summary.failed, summary.missing, summary.errors);
    const std::string page = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>\n"
        "<style>\n{1}\n</style>\n</head>\n<body>\n<h1>{0}</h1>\n{2}{3}</body>\n</html>\n",
        escapeHtml(title), kStyle, listed == 0 ? "<p>Every test passed.</p>\n" : "", body);
    const fs::path index = dir / "index.html";
    const fs::path temporary = dir / "index.html.tmp";
    {
        std::ofstream out(temporary);
        out << page;
        if (!out)
            return fmt::format("{}: cannot write", index.string());
    }
    fs::rename(temporary, index, ec);
    if (ec)
        return fmt::format("{}: cannot write: {}", index.string(), ec.message());
    return "";
}

} // namespace drt::golden
