// Owen-scrambled Sobol points (private to src/sampling; the renderer uses the
// Sampler interface).
//
// The Sobol sequence in base 2: point i in dimension d is the XOR of the
// direction numbers v_d[j] for every set bit j of i (Bratley & Fox 1988), with
// v_d derived from a primitive polynomial and initial numbers m from Joe & Kuo
// (2008), "Constructing Sobol sequences with better two-dimensional
// projections". Any aligned block of 2^m points is a (t, m, s)-net.
//
// Scrambling follows Burley (2020), "Practical Hash-based Owen Scrambling": a
// nested uniform (Owen) scramble flips each binary digit by a random function of
// the digits above it; done by a hash in which every bit depends only on less
// significant bits (Laine & Karras 2011), applied to the bit-reversed value. It
// keeps every net property and makes each point uniform on [0, 1)^s.
#pragma once

#include "sampling/sampler.h"

#include <cstdint>
#include <memory>

namespace drt {

// Number of dimensions with direction numbers: the five jointly stratified
// camera dimensions (pixel 0-1, time 2, lens 3-4).
inline constexpr int kSobolDimensions = 5;

// Dimension d (0 <= d < kSobolDimensions) of Sobol point `index`, as a 32-bit
// fraction (value / 2^32).
uint32_t sobolValue(uint32_t index, int dimension);

// Nested uniform scramble of a 32-bit fraction; the most significant bit is
// the first digit. A bijection for every seed.
uint32_t owenScramble(uint32_t value, uint32_t seed);

// A scramble seed with the second seed owenScramble derives from it, for
// callers that scramble many values with one seed.
struct OwenSeed {
    uint32_t seed = 0, seed2 = 0;
    OwenSeed() = default;
    explicit OwenSeed(uint32_t s);
};
uint32_t owenScramble(uint32_t value, const OwenSeed& seed); // == owenScramble(value, seed.seed)

// A double in [0, 1) from a 32-bit fraction.
inline double fractionToUnit(uint32_t v) { return v * 0x1.0p-32; }

std::unique_ptr<Sampler> makeSobolSampler(int samplesPerPixel, uint64_t seed);

} // namespace drt
