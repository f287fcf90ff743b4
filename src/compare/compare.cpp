// Error metrics and the pass/fail decision of `drt compare`.
#include "compare/compare.h"

#include "compare/statistical.h"
#include "image/srgb.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace drt {

const char* compareStatusName(CompareStatus status) {
    switch (status) {
    case CompareStatus::Pass:
        return "PASS";
    case CompareStatus::Warn:
        return "WARNING";
    case CompareStatus::Fail:
        return "FAILURE";
    case CompareStatus::SizeMismatch:
        return "SIZE MISMATCH";
    case CompareStatus::FileError:
        return "FILE ERROR";
    }
    return "?";
}

int comparedChannels(const Image& a, const Image& b) {
    return std::min({a.channels, b.channels, 3});
}

bool pixelIsFinite(const Image& image, int x, int y, int channels) {
    for (int c = 0; c < channels; ++c)
        if (!std::isfinite(image.at(x, y, c)))
            return false;
    return true;
}

namespace {

std::string sizeOf(const Image& image) {
    return fmt::format("{}x{}", image.width, image.height);
}

// The error metrics of docs/accuracy.md over the finite pixels.
void measureErrors(const Image& candidate, const Image& reference, const CompareOptions& options,
                   const VarianceImages& variance, CompareResult& r) {
    const int nc = r.channels;
    double sumSquared = 0, sumRelative = 0, sumSigned = 0, sumAbsolute = 0, sumToneSquared = 0;
    int64_t finitePixels = 0;
    std::vector<double> pixelRelative; // per pixel, mean over channels, for the robust relMSE
    pixelRelative.reserve(size_t(r.pixelCount));
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (!pixelIsFinite(candidate, x, y, nc) || !pixelIsFinite(reference, x, y, nc) ||
                !varianceIsFinite(variance, x, y, nc)) {
                ++r.nonFinitePixels;
                continue;
            }
            ++finitePixels;
            double pixelRel = 0, pixelMax = 0;
            for (int c = 0; c < nc; ++c) {
                const double a = candidate.at(x, y, c), b = reference.at(x, y, c);
                const double e = a - b;
                sumSquared += e * e;
                const double rel = e * e / (b * b + 0.01);
                sumRelative += rel;
                pixelRel += rel / nc;
                sumSigned += e;
                sumAbsolute += std::abs(e);
                const double tone = srgbEncode(a) - srgbEncode(b);
                sumToneSquared += tone * tone;
                if (std::abs(e) > r.maxError || r.maxErrorX < 0) {
                    r.maxError = std::abs(e);
                    r.maxErrorX = x, r.maxErrorY = y, r.maxErrorChannel = c;
                }
                pixelMax = std::max(pixelMax, std::abs(e));
            }
            pixelRelative.push_back(pixelRel);
            if (pixelMax > options.failThreshold)
                ++r.failingPixels;
            if (pixelMax > options.warnThreshold)
                ++r.warningPixels;
        }
    if (finitePixels == 0)
        return;
    const double values = double(finitePixels) * nc;
    r.rmse = std::sqrt(sumSquared / values);
    r.relMse = sumRelative / values;
    r.meanSignedError = sumSigned / values;
    r.meanAbsoluteError = sumAbsolute / values;
    const double toneMse = sumToneSquared / values;
    r.psnr = toneMse > 0 ? 10 * std::log10(1 / toneMse) : std::numeric_limits<double>::infinity();

    // Drop the worst 0.1% of pixels (rounded down: images under 1000 pixels drop none).
    const size_t dropped = pixelRelative.size() / 1000;
    const size_t kept = pixelRelative.size() - dropped;
    std::nth_element(pixelRelative.begin(), pixelRelative.begin() + long(kept - 1), pixelRelative.end());
    double sumKept = 0;
    for (size_t i = 0; i < kept; ++i)
        sumKept += pixelRelative[i];
    r.robustRelMse = sumKept / double(kept);
}

void decide(const CompareOptions& options, CompareResult& r) {
    auto fail = [&](CompareStatus status, std::string why) {
        if (r.status == CompareStatus::Pass ||
            (status == CompareStatus::Fail && r.status == CompareStatus::Warn)) {
            r.status = status;
            r.message = std::move(why);
        }
    };
    if (r.nonFinitePixels > 0)
        fail(CompareStatus::Fail, fmt::format("{} pixels are NaN or Inf", r.nonFinitePixels));
    if (r.statistical) {
        for (size_t c = 0; c < r.globalZ.size(); ++c)
            if (!(std::abs(r.globalZ[c]) <= r.globalZThreshold))
                fail(CompareStatus::Fail,
                     fmt::format("biased: the mean error of channel {} has z = {:.2f} (|z| > {:.2f}); bias over "
                                 "all channels {:+.3g}",
                                 channelName(int(c)), r.globalZ[c], r.globalZThreshold, r.meanSignedError));
        if (r.failingTiles > 0)
            fail(CompareStatus::Fail,
                 fmt::format(
                     "{} of {} tile tests biased; worst: tile at ({}, {}) channel {} mean error {:.3g}, "
                     "z = {:.2f} (|z| > {:.2f})",
                     r.failingTiles, r.tileTests, r.worstTile.x0, r.worstTile.y0, channelName(r.worstTile.channel),
                     r.worstTile.meanError, r.worstTile.z, r.tileZThreshold));
    }
    if (r.statistical && !options.thresholdsWithVariance)
        return;
    const double n = double(std::max<int64_t>(r.pixelCount, 1));
    if (100.0 * double(r.failingPixels) / n > options.failPercent)
        fail(CompareStatus::Fail, fmt::format("{} pixels ({:.3g}%) differ by more than {:g}", r.failingPixels,
                                              100.0 * double(r.failingPixels) / n, options.failThreshold));
    if (100.0 * double(r.warningPixels) / n > options.warnPercent)
        fail(CompareStatus::Warn, fmt::format("{} pixels ({:.3g}%) differ by more than {:g}", r.warningPixels,
                                              100.0 * double(r.warningPixels) / n, options.warnThreshold));
}

} // namespace

CompareResult compareImages(const Image& candidate, const Image& reference, const CompareOptions& options,
                            const VarianceImages& variance) {
    CompareResult r;
    r.width = reference.width, r.height = reference.height;
    r.channels = comparedChannels(candidate, reference);
    r.pixelCount = int64_t(r.width) * r.height;
    if (candidate.width != reference.width || candidate.height != reference.height) {
        r.status = CompareStatus::SizeMismatch;
        r.message = fmt::format("size mismatch: {} against {}", sizeOf(candidate), sizeOf(reference));
        return r;
    }
    for (const Image* v : {variance.reference, variance.candidate})
        if (v && (v->width != reference.width || v->height != reference.height)) {
            r.status = CompareStatus::SizeMismatch;
            r.message = fmt::format("size mismatch: variance image {} against images {}", sizeOf(*v),
                                    sizeOf(reference));
            return r;
        }
    measureErrors(candidate, reference, options, variance, r);
    if (variance.any())
        runStatisticalTests(candidate, reference, variance, options, r);
    decide(options, r);
    return r;
}

} // namespace drt
