// The bench runner: scene -> references -> one render per (method, spp,
// seed) -> metrics -> results.csv, charts and summary.md (bench/report.h).
#include "bench/bench.h"
#include "bench/chart.h"
#include "assets/assets.h"

#include "bench/reference.h"
#include "bench/report.h"
#include "compare/compare.h"
#include "accel/geometry_query.h"
#include "lang/load.h"
#include "sampling/filter.h"
#include "sampling/sampler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace drt::bench {

namespace {

// References use a seed no bench render uses (those take seeds 1..K).
constexpr uint64_t kReferenceSeed = 0x5eed5eedULL;
// Independent renders a bench reference averages (see makeReference).
constexpr int kReferenceParts = 8;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Writes text through a temporary file renamed over `path` when complete.
void writeTextFile(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out.flush()) throw BenchError(fmt::format("cannot write '{}'", path), true);
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) throw BenchError(fmt::format("cannot write '{}': {}", path, ec.message()), true);
}

struct Reference {
    Image color;
    Image variance;
    bool hasVariance = false;
    std::string note;
};

std::string filterOf(const Scene& scene) { return scene.render.filter.value_or(defaultFilterName()); }

// Methods that change the expected image need their own reference; only the
// filter does so among the methods (bench/methods.h), so the key is the filter.
std::string referenceKey(const Scene& scene, const Scene& tweaked) {
    return filterOf(tweaked) == filterOf(scene) ? "" : "filter-" + filterOf(tweaked);
}

// The reference's share of E[relMSE] (a noisy reference inflates every
// error: docs/accuracy.md).
double referenceNoise(const Reference& reference) {
    return reference.hasVariance ? bench::referenceNoise(reference.color, reference.variance) : 0;
}

// Global z-score: sum of errors over every finite pixel and channel divided by
// the standard deviation of that sum, sqrt(sum Var(x) + Var(r)).
double globalBiasZ(const Image& candidate, const Image& candidateVariance, const Reference& reference) {
    double sumError = 0, sumVariance = 0;
    const int channels = std::min({3, candidate.channels, reference.color.channels});
    for (int y = 0; y < candidate.height; ++y)
        for (int x = 0; x < candidate.width; ++x)
            for (int c = 0; c < channels; ++c) {
                const double e = double(candidate.at(x, y, c)) - reference.color.at(x, y, c);
                double v = candidateVariance.at(x, y, c);
                if (reference.hasVariance)
                    v += reference.variance.at(x, y, std::min(c, reference.variance.channels - 1));
                if (std::isfinite(e) && std::isfinite(v)) sumError += e, sumVariance += v;
            }
    return sumVariance > 0 ? sumError / std::sqrt(sumVariance) : 0;
}

Reference loadGivenReference(const std::string& path, int width, int height) {
    Reference reference;
    if (std::string problem = readImage(path, reference.color); !problem.empty())
        throw BenchError(fmt::format("cannot read the reference: {}", problem), true);
    if (reference.color.width != width || reference.color.height != height)
        throw BenchError(fmt::format("the reference '{}' is {}x{} but the bench renders {}x{} (use --width and "
                                     "--height)",
                                     path, reference.color.width, reference.color.height, width, height),
                         false);
    const fs::path variancePath = fs::path(path).replace_extension(".variance.exr");
    std::error_code ec;
    if (fs::exists(variancePath, ec) && readImage(variancePath.string(), reference.variance).empty() &&
        reference.variance.width == width && reference.variance.height == height)
        reference.hasVariance = true;
    reference.note = fmt::format("`{}` (given{})", path,
                                 reference.hasVariance ? ", with its variance image" : ", no variance image: "
                                                                                       "bias z uses the candidate's "
                                                                                       "variance only");
    return reference;
}

// Renders the reference for `scene` (already tweaked) at `spp`, or reuses the
// one in the output folder if its recorded identity matches.
Reference makeReference(const Scene& scene, RenderOptions options, int spp, const std::string& identity,
                        const fs::path& colorPath, std::ostream& log) {
    const fs::path variancePath = fs::path(colorPath).replace_extension(".variance.exr");
    Reference reference;
    std::error_code ec;
    if (fs::exists(colorPath, ec) && fs::exists(variancePath, ec)) {
        Metadata metadata;
        if (readImage(colorPath.string(), reference.color, &metadata).empty() &&
            readImage(variancePath.string(), reference.variance).empty() &&
            std::find(metadata.begin(), metadata.end(), std::pair<std::string, std::string>{"drt:bench_reference",
                                                                                            identity}) !=
                metadata.end() &&
            reference.variance.width == reference.color.width && reference.variance.height == reference.color.height) {
            reference.hasVariance = true;
            reference.note = fmt::format("`{}` ({} spp, reused)", colorPath.filename().string(), spp);
            log << fmt::format("bench: reusing reference {}\n", colorPath.string());
            return reference;
        }
    }
    log << fmt::format("bench: rendering reference {} (sobol, {} spp as {} renders)...\n", colorPath.string(), spp,
                       kReferenceParts);
    // The reference is the mean of kReferenceParts independent sobol renders
    // (different scrambling seeds), and its variance of the mean comes from
    // their spread: sum (m_k - m)^2 / (K (K - 1)). One render's per-pixel
    // sample variance / N would over-state a stratified mean's variance many
    // times over, and subtracting it from relMSE would over-correct.
    options.sampler = "sobol";
    options.samplesPerPixel = std::max(1, spp / kReferenceParts);
    options.adaptive = false;
    const auto start = std::chrono::steady_clock::now();
    std::vector<Image> parts;
    for (int k = 0; k < kReferenceParts; ++k) {
        options.seed = kReferenceSeed + uint64_t(k);
        try {
            parts.push_back(render(scene, options).color);
        } catch (const RenderError& e) {
            throw BenchError(fmt::format("reference render failed: {}", e.what()), false);
        }
    }
    AveragedImage result = averageImages(parts);
    const Metadata metadata = {{"Software", fmt::format("drt {}", DRT_VERSION)},
                               {"drt:bench_reference", identity},
                               {"drt:spp", std::to_string(options.samplesPerPixel * kReferenceParts)},
                               {"drt:seed", std::to_string(kReferenceSeed)}};
    if (std::string problem = writeImage(colorPath.string(), result.mean, metadata); !problem.empty())
        throw BenchError(problem, true);
    if (std::string problem = writeImage(variancePath.string(), result.varianceOfMean, metadata); !problem.empty())
        throw BenchError(problem, true);
    log << fmt::format("bench: reference done in {:.1f} s\n", secondsSince(start));
    reference.color = std::move(result.mean);
    reference.variance = std::move(result.varianceOfMean);
    reference.hasVariance = true;
    reference.note = fmt::format("`{}` ({} spp, made in {:.1f} s)", colorPath.filename().string(), spp,
                                 secondsSince(start));
    return reference;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

} // namespace

std::vector<int> parseSppList(const std::string& text) {
    std::vector<int> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        size_t used = 0;
        int value = 0;
        try {
            value = std::stoi(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || value < 1)
            throw std::invalid_argument(fmt::format("'{}' is not a positive sample count", item));
        values.push_back(value);
    }
    if (values.empty()) throw std::invalid_argument("the sample-count list is empty");
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

std::string formatResultsCsv(const std::vector<BenchRow>& rows) {
    std::string out = "scene,method,sampler,filter,spp,mean_spp,seed,threads,width,height,render_seconds,"
                      "parse_seconds,build_seconds,rays,mrays_per_second,mse,relmse,relmse_raw,robust_relmse,"
                      "mean_signed_error,bias_z,nonfinite\n";
    for (const BenchRow& r : rows)
        out += fmt::format("{},{},{},{},{},{:.6g},{},{},{},{},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.6g},{:.6g},"
                           "{:.6g},{:.6g},{:.4f},{}\n",
                           csvField(r.scene), csvField(r.method), r.sampler, r.filter, r.spp, r.meanSpp, r.seed,
                           r.threads, r.width, r.height, r.renderSeconds, r.parseSeconds, r.buildSeconds, r.rays,
                           r.mraysPerSecond, r.mse, r.relMse, r.relMseRaw, r.robustRelMse, r.meanSignedError,
                           r.biasZ, r.nonFinite);
    return out;
}

BenchReport runBench(const BenchOptions& given, std::ostream& log) {
    BenchOptions o = given;
    if (o.spp.empty()) o.spp = o.quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 4, 16, 64, 256};
    if (o.seeds <= 0) o.seeds = o.quick ? 1 : 3;
    if (o.referenceSpp <= 0) o.referenceSpp = o.quick ? 256 : 16 * *std::max_element(o.spp.begin(), o.spp.end());
    for (const std::string& name : o.methods)
        if (!findBenchMethod(name))
            throw BenchError(fmt::format("unknown method '{}' (known: {})", name,
                                         fmt::join(benchMethodNames(), ", ")),
                             false);

    // The charts come last: a bench that could not draw them stops now, before any render.
    if (std::string problem = chartsUnavailable(); !problem.empty()) throw BenchError(problem, true);

    // Parse (timed once: every render shares the parsed scene).
    std::error_code ec;
    if (!fs::is_regular_file(o.scenePath, ec))
        throw BenchError(fmt::format("cannot read scene '{}': no such file", o.scenePath), true);
    Diagnostics diagnostics;
    const auto parseStart = std::chrono::steady_clock::now();
    LoadOptions load; // .drt or .pov, by the extension
    const std::unique_ptr<SceneGeometryQuery> geometry = makeGeometryQuery();
    load.geometry = geometry.get();
    std::optional<Scene> loaded = loadScene(o.scenePath, diagnostics, load);
    if (loaded && !diagnostics.hasErrors()) resolveAssets(*loaded, diagnostics);
    const double parseSeconds = secondsSince(parseStart);
    if (diagnostics.hasErrors() || !loaded)
        throw BenchError(diagnostics.formatAll() + fmt::format("{}: {} error(s)", o.scenePath,
                                                               diagnostics.errorCount()),
                         false);
    const Scene& scene = *loaded;

    fs::create_directories(o.outputDir, ec);
    if (!fs::is_directory(o.outputDir, ec))
        throw BenchError(fmt::format("cannot create the output folder '{}'", o.outputDir), true);
    const fs::path dir(o.outputDir);
    if (std::string problem = checkWritable((dir / "reference.exr").string()); !problem.empty())
        throw BenchError(problem, true);

    RenderOptions base = resolveRenderOptions(scene.render);
    const double aspect = double(base.height) / double(base.width);
    base.width = o.width > 0 ? o.width : (o.quick ? 48 : 96);
    base.height = o.height > 0 ? o.height : std::max(1, int(std::lround(base.width * aspect)));
    base.threads = o.threads;
    base.adaptive = false;

    BenchReport report;
    report.sceneName = fs::path(o.scenePath).filename().string();
    report.width = base.width;
    report.height = base.height;
    report.threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    report.spp = o.spp;
    report.seeds = o.seeds;
    report.parseSeconds = parseSeconds;

    std::vector<const BenchMethod*> methods;
    for (const BenchMethod& method : benchMethods()) {
        if (!o.methods.empty() && std::find(o.methods.begin(), o.methods.end(), method.name) == o.methods.end())
            continue;
        if (std::string why = method.whyNotApplicable(scene); !why.empty()) {
            report.skipped.push_back({method.name, why});
            log << fmt::format("bench: skipping {}: {}\n", method.name, why);
            continue;
        }
        methods.push_back(&method);
        report.methods.push_back(method.name);
    }
    if (methods.empty()) throw BenchError("no method applies to this scene", false);

    // One reference per distinct expected image.
    const std::string sceneHash = fmt::format("{:016x}", std::hash<std::string>{}(readFile(o.scenePath)));
    std::map<std::string, Reference> references;
    const auto referenceFor = [&](const Scene& tweaked) -> const Reference& {
        const std::string key = referenceKey(scene, tweaked);
        if (auto found = references.find(key); found != references.end()) return found->second;
        Reference reference;
        if (key.empty() && !o.referencePath.empty()) {
            reference = loadGivenReference(o.referencePath, base.width, base.height);
        } else {
            const std::string identity =
                fmt::format("{} {} {}x{} spp {} in {} {}", report.sceneName, sceneHash, base.width, base.height,
                            o.referenceSpp, kReferenceParts, key.empty() ? "as written" : key);
            const fs::path path = dir / (key.empty() ? "reference.exr" : "reference-" + key + ".exr");
            reference = makeReference(key.empty() ? scene : tweaked, base, o.referenceSpp, identity, path, log);
        }
        report.referenceNotes.push_back(fmt::format("{}: {}", key.empty() ? "the scene as written" : key,
                                                    reference.note));
        return references.emplace(key, std::move(reference)).first->second;
    };

    const int total = int(methods.size() * o.spp.size()) * o.seeds;
    int done = 0;
    for (const BenchMethod* method : methods) {
        for (int spp : o.spp) {
            for (int seed = 1; seed <= o.seeds; ++seed) {
                Scene tweaked = scene;
                RenderOptions options = base;
                options.samplesPerPixel = spp;
                options.seed = uint64_t(seed);
                method->apply(tweaked, options, spp);
                const Reference& reference = referenceFor(tweaked);
                RenderResult result;
                try {
                    result = render(tweaked, options);
                } catch (const RenderError& e) {
                    throw BenchError(fmt::format("{} at {} spp: render failed: {}", method->name, spp, e.what()),
                                     false);
                }
                const VarianceImages variance{reference.hasVariance ? &reference.variance : nullptr,
                                              &result.variance};
                const CompareResult cmp = compareImages(result.color, reference.color, CompareOptions{}, variance);
                const double noise = referenceNoise(reference);
                const RenderStats& s = result.stats;
                BenchRow row;
                row.scene = report.sceneName;
                row.method = method->name;
                row.sampler = options.sampler.empty() ? defaultSamplerName() : options.sampler;
                row.filter = filterOf(tweaked);
                row.spp = spp;
                row.meanSpp = s.pixelSamples > 0 ? double(s.pixelSamples) / (double(options.width) * options.height)
                                                 : double(spp);
                row.seed = uint64_t(seed);
                row.threads = report.threads;
                row.width = options.width;
                row.height = options.height;
                row.parseSeconds = parseSeconds;
                row.buildSeconds = s.buildSeconds;
                row.renderSeconds = s.renderSeconds;
                row.rays = s.totalRays();
                row.mraysPerSecond = s.renderSeconds > 0 ? double(row.rays) / s.renderSeconds / 1e6 : 0;
                row.mse = cmp.rmse * cmp.rmse;
                row.relMseRaw = cmp.relMse;
                row.relMse = cmp.relMse - noise;
                row.robustRelMse = cmp.robustRelMse - noise;
                row.meanSignedError = cmp.meanSignedError;
                // One sample gives no variance estimate: no z-score below two.
                row.biasZ = row.meanSpp >= 2 ? globalBiasZ(result.color, result.variance, reference)
                                             : std::numeric_limits<double>::quiet_NaN();
                row.nonFinite = int64_t(s.nonFiniteSamples) + cmp.nonFinitePixels;
                report.rows.push_back(row);
                ++done;
                log << fmt::format("bench: [{:>{}}/{}] {:<17} {:>5} spp seed {}: {:8.4f} s, relMSE {:.3e}\n", done,
                                   int(std::to_string(total).size()), total, method->name, spp, seed, row.seconds(),
                                   row.relMse);
            }
        }
    }

    writeTextFile((dir / "results.csv").string(), formatResultsCsv(report.rows));
    if (std::string problem = writeCharts(report, dir.string()); !problem.empty()) throw BenchError(problem, true);
    writeTextFile((dir / "summary.md").string(), formatSummary(report));
    log << fmt::format("bench: wrote results.csv, error-vs-time.svg/.png, error-vs-spp.svg/.png and summary.md in "
                       "{}\n",
                       dir.string());
    return report;
}

} // namespace drt::bench
