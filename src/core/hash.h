// Counter-based randomness: every random number in drt is a pure function of
// (seed, pixel, sample index, dimension), so images never depend on thread
// count or tile order.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace drt {

// The 64-bit finaliser of MurmurHash3 (fmix64): a bijective avalanche mix.
constexpr uint64_t mix64(uint64_t k) {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ULL;
    k ^= k >> 33;
    return k;
}

// Hash of a list of integers, order-sensitive.
constexpr uint64_t hashValues(std::initializer_list<uint64_t> values) {
    uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (uint64_t v : values) h = mix64(h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
    return h;
}

// A double in [0, 1) from the top 53 bits of a hash.
constexpr double unitFromHash(uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

// Kensler's hash-based permutation ("Correlated Multi-Jittered Sampling", 2013):
// element i of a pseudo-random permutation of [0, n) chosen by `key`.
uint32_t permuteIndex(uint32_t i, uint32_t n, uint32_t key);

} // namespace drt
