#include "sampling/sampler.h"

#include "core/hash.h"
#include "sampling/sobol.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt {

// Default: the k-th of `count` jittered points, one per cell of a near-square
// nx x ny grid; the cells are visited in a random order per (pixel sample,
// dimension), so the first `count` cells are a random subset when count < nx ny.
Vec2 Sampler::get2DStratified(int dimension, int k, int count) {
    const int nx = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(count))));
    const int ny = (count + nx - 1) / nx;
    const uint64_t key = hashValues({seed_, uint64_t(x_), uint64_t(y_), uint64_t(index_), uint64_t(dimension), 0x57a7ULL});
    const uint32_t cell = permuteIndex(static_cast<uint32_t>(k), static_cast<uint32_t>(nx * ny),
                                       static_cast<uint32_t>(key >> 32));
    const uint64_t h = hashValues({key, uint64_t(k)});
    const Vec2 j{unitFromHash(mix64(h)), unitFromHash(mix64(h ^ 0xabcdefULL))};
    return {(cell % nx + j.x) / nx, (cell / nx + j.y) / ny};
}

void Sampler::get2DStratifiedRun(int dimension, int count, Vec2* out) {
    for (int k = 0; k < count; ++k) out[k] = get2DStratified(dimension, k, count);
}

void Sampler::getCameraDimensions(int x, int y, int first, int count, Vec2* pixel, double* time, Vec2* lens) {
    for (int j = 0; j < count; ++j) {
        startPixelSample(x, y, first + j);
        pixel[j] = get2D(kDimPixel);
        if (time) time[j] = get1D(kDimTime);
        if (lens) lens[j] = get2D(kDimLens);
    }
}

namespace {

// Independent uniform random values: the N^-1/2 baseline.
class IndependentSampler final : public Sampler {
public:
    IndependentSampler(int spp, uint64_t seed) : Sampler(spp, seed) {}
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }
    void startPixelSample(int x, int y, int index) override {
        x_ = x;
        y_ = y;
        index_ = index;
    }
    double get1D(int dimension) override {
        return unitFromHash(hashValues({seed_, uint64_t(x_), uint64_t(y_), uint64_t(index_), uint64_t(dimension)}));
    }
    Vec2 get2D(int dimension) override { return {get1D(dimension), get1D(dimension + 1)}; }
    std::string name() const override { return "independent"; }
};

// Jittered (stratified) sampling: each 2D dimension pair is an nx x ny jittered
// grid over the pixel's samples, 1D dimensions are jittered strata; the strata
// of each dimension are visited in an independent random order per pixel
// ("padding"), so pairs are decorrelated from each other.
class StratifiedSampler final : public Sampler {
public:
    StratifiedSampler(int spp, uint64_t seed) : Sampler(spp, seed) {
        nx_ = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(spp)))));
        ny_ = (spp + nx_ - 1) / nx_;
    }
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }
    void startPixelSample(int x, int y, int index) override {
        x_ = x;
        y_ = y;
        index_ = index;
    }
    double get1D(int dimension) override {
        const uint64_t key = pixelKey(dimension);
        const uint32_t stratum = permuteIndex(static_cast<uint32_t>(index_), static_cast<uint32_t>(samplesPerPixel_),
                                              static_cast<uint32_t>(key));
        return (stratum + jitter(key, 0)) / samplesPerPixel_;
    }
    Vec2 get2D(int dimension) override {
        // With spp not a multiple of nx, a random subset of the nx*ny cells is
        // used: each cell is equally likely, so the estimate stays unbiased.
        const uint64_t key = pixelKey(dimension);
        const uint32_t cells = static_cast<uint32_t>(nx_ * ny_);
        const uint32_t cell = permuteIndex(static_cast<uint32_t>(index_), cells, static_cast<uint32_t>(key));
        return {(cell % nx_ + jitter(key, 1)) / nx_, (cell / nx_ + jitter(key, 2)) / ny_};
    }
    std::string name() const override { return "stratified"; }

private:
    uint64_t pixelKey(int dimension) const {
        return hashValues({seed_, uint64_t(x_), uint64_t(y_), uint64_t(dimension), 0x5742ULL});
    }
    double jitter(uint64_t key, int which) const {
        return unitFromHash(hashValues({key, uint64_t(index_), uint64_t(which)}));
    }
    int nx_, ny_;
};

} // namespace

const std::vector<std::string>& samplerNames() {
    static const std::vector<std::string> names{"sobol", "independent", "stratified"};
    return names;
}

// Owen-scrambled Sobol: stratified jointly over pixel, time and lens (sobol_sampler.cpp).
std::string defaultSamplerName() { return "sobol"; }

std::unique_ptr<Sampler> makeSampler(const std::string& name, int spp, uint64_t seed) {
    if (spp < 1) throw std::invalid_argument("samples per pixel must be at least 1");
    if (name == "independent") return std::make_unique<IndependentSampler>(spp, seed);
    if (name == "stratified") return std::make_unique<StratifiedSampler>(spp, seed);
    if (name == "sobol") return makeSobolSampler(spp, seed);
    std::string accepted;
    for (const auto& n : samplerNames()) accepted += (accepted.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown sampler '" + name + "' (expected one of: " + accepted + ")");
}

} // namespace drt
