// The one sampler interface. A sampler hands out the sample values of one
// pixel sample at a time; every value is a pure function of
// (seed, pixel, sample index, dimension).
//
// Dimensions follow Cook et al.'s "association of ray ids": each effect owns
// fixed dimensions, so that a sampler stratified jointly over several
// dimensions (e.g. Owen-scrambled Sobol) keeps pixel, time and lens samples
// stratified against each other:
//   0-1  pixel position (2D)          kDimPixel
//   2    time within the shutter      kDimTime
//   3-4  lens position (2D)           kDimLens
//   5..  per trace depth d: kDimFirstBounce + d * kDimsPerBounce + offset,
//        offsets: light position (2D), light choice (1D), glossy/translucent
//        direction (2D), reflect-or-refract choice (1D), spare (2).
#pragma once

#include "core/vec.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace drt {

inline constexpr int kDimPixel = 0;
inline constexpr int kDimTime = 2;
inline constexpr int kDimLens = 3;
inline constexpr int kDimFirstBounce = 5;
inline constexpr int kDimsPerBounce = 8;
inline constexpr int kOffsetLight = 0;       // 2D
inline constexpr int kOffsetLightChoice = 2; // 1D
inline constexpr int kOffsetLobe = 3;        // 2D
inline constexpr int kOffsetLobeChoice = 5;  // 1D
constexpr int bounceDimension(int depth, int offset) { return kDimFirstBounce + depth * kDimsPerBounce + offset; }

class Sampler {
public:
    virtual ~Sampler() = default;
    // A fresh sampler with the same settings, for another thread.
    virtual std::unique_ptr<Sampler> clone() const = 0;
    // Selects sample `index` (0 <= index < samplesPerPixel) of pixel (x, y).
    virtual void startPixelSample(int x, int y, int index) = 0;
    // Sample values in [0, 1) for the given dimension(s) of the current sample.
    virtual double get1D(int dimension) = 0;
    virtual Vec2 get2D(int dimension) = 0; // uses dimension and dimension + 1
    // The camera dimensions of samples first .. first+count-1 of pixel (x, y),
    // bit for bit what startPixelSample then get2D(kDimPixel), get1D(kDimTime)
    // and get2D(kDimLens) give one sample at a time: pixel[j] always, time[j]
    // and lens[j] unless the array is null (a camera without shutter or lens
    // draws no such value). Afterwards the current sample is unspecified: call
    // startPixelSample before drawing any other value. The renderer takes a
    // packet's camera values this way; the default asks sample by sample.
    virtual void getCameraDimensions(int x, int y, int first, int count, Vec2* pixel, double* time, Vec2* lens);
    // For samplers that can draw more than one point per dimension for one
    // pixel sample (e.g. n1 x n2 area-light cells): the k-th of `count`
    // stratified 2D points in the given dimension.
    virtual Vec2 get2DStratified(int dimension, int k, int count);
    // All `count` of them: out[k] is get2DStratified(dimension, k, count), bit
    // for bit; a sampler may work out what the points share once.
    virtual void get2DStratifiedRun(int dimension, int count, Vec2* out);
    int samplesPerPixel() const { return samplesPerPixel_; }
    uint64_t seed() const { return seed_; }
    virtual std::string name() const = 0;

protected:
    Sampler(int samplesPerPixel, uint64_t seed) : samplesPerPixel_(samplesPerPixel), seed_(seed) {}
    int samplesPerPixel_;
    uint64_t seed_;
    int x_ = 0, y_ = 0, index_ = 0;
};

// Names accepted by --sampler and the scene: see samplerNames().
//   sobol        (default) Owen-scrambled Sobol: dims 0-4 are one 5D point per
//                sample, so pixel x time and pixel x lens are stratified jointly;
//                dims 5+ are padded scrambled (0,2) pairs (sobol_sampler.cpp).
//                Best with power-of-two sample counts.
//   stratified   jittered grid per 2D pair, jittered strata per 1D dimension,
//                pairs padded (decorrelated by independent permutations).
//   independent  uniform random values: the N^-1/2 baseline.
std::unique_ptr<Sampler> makeSampler(const std::string& name, int samplesPerPixel, uint64_t seed);
const std::vector<std::string>& samplerNames();
std::string defaultSamplerName();

} // namespace drt
