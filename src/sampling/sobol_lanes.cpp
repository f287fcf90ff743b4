// The joint Sobol values of sixteen pixel samples at once, with AVX2 (see
// sobol.h, "Sixteen samples at once"). Every step is the integer arithmetic of
// the one-sample functions in sobol.h on 32-bit lanes, two groups of eight, so
// each lane is bit for bit the value those give; tests/sampler_test.cpp
// checks it.
//
// Only the functions marked with the avx2 target use AVX2 instructions, and
// they run only where the processor reports AVX2: the rest of the program is
// built for the baseline x86-64.
#include "sampling/sobol.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DRT_SOBOL_LANES 1
#include <immintrin.h>
#endif

namespace drt::sobol_detail {

namespace {

// reverseBits(direction number k of dimension d): point i of dimension d,
// bit-reversed, is the XOR of these over the set bits k of i (sobolReversed).
using ReversedDirections = std::array<std::array<uint32_t, 32>, kSobolDimensions>;
constexpr ReversedDirections makeReversedDirections() {
    ReversedDirections r{};
    for (int d = 0; d < kSobolDimensions; ++d)
        for (int k = 0; k < 32; ++k) r[size_t(d)][size_t(k)] = reverseBits(kDirections[size_t(d)][size_t(k)]);
    return r;
}
constexpr ReversedDirections kReversedDirections = makeReversedDirections();

} // namespace

#ifdef DRT_SOBOL_LANES

namespace {

#define DRT_LANES __attribute__((target("avx2"), always_inline)) inline

// reverseBits: the bytes reversed within each lane, then the bits within
// each byte, a nibble at a time from a 16-entry table.
DRT_LANES __m256i reverseLanes(__m256i x) {
    const __m256i swapBytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, //
                                               3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
    const __m256i reversedNibble = _mm256_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                    0xb, 0x7, 0xf, //
                                                    0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                    0xb, 0x7, 0xf);
    const __m256i low4 = _mm256_set1_epi8(0x0f);
    x = _mm256_shuffle_epi8(x, swapBytes);
    const __m256i low = _mm256_and_si256(x, low4), high = _mm256_and_si256(_mm256_srli_epi16(x, 4), low4);
    // A reversed nibble is at most 0xf: shifted left by 4 it stays in its byte.
    return _mm256_or_si256(_mm256_slli_epi16(_mm256_shuffle_epi8(reversedNibble, low), 4),
                           _mm256_shuffle_epi8(reversedNibble, high));
}

DRT_LANES __m256i times(__m256i x, uint32_t factor) {
    return _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(factor)));
}

// scrambleReversed, step for step.
DRT_LANES __m256i scrambleLanes(__m256i x, const OwenSeed& key) {
    const uint32_t seed = key.seed, seed2 = key.seed2;
    x = _mm256_add_epi32(x, _mm256_set1_epi32(static_cast<int>(seed)));
    x = _mm256_xor_si256(x, times(x, 0x9e3779b8u));
    x = times(x, seed2 | 1u);
    x = _mm256_xor_si256(x, times(x, 0x85ebca6cu));
    x = _mm256_add_epi32(x, _mm256_set1_epi32(static_cast<int>(seed2 >> 7)));
    x = _mm256_xor_si256(x, times(x, 0xc2b2ae36u));
    x = _mm256_xor_si256(x, times(x, seed & ~1u));
    return x;
}

// sobolReversed for dimension d >= 1 of indices below 2^bits: the XOR of the
// reversed direction numbers of each lane's set bits.
DRT_LANES __m256i sobolReversedLanes(__m256i index, int dimension, int bits) {
    const auto& directions = kReversedDirections[size_t(dimension)];
    __m256i value = _mm256_setzero_si256();
    for (int k = 0; k < bits; ++k) {
        const __m256i bit = _mm256_set1_epi32(static_cast<int>(1u << k));
        const __m256i set = _mm256_cmpeq_epi32(_mm256_and_si256(index, bit), bit);
        value = _mm256_xor_si256(value,
                                 _mm256_and_si256(set, _mm256_set1_epi32(static_cast<int>(directions[size_t(k)]))));
    }
    return value;
}

// One group of eight lanes' steps, for the two groups side by side: each
// step's multiplies wait some ten cycles for their result, and the other
// group's step fills that time.
struct Pair {
    __m256i a, b;
};

DRT_LANES Pair reverseLanes(Pair x) { return {reverseLanes(x.a), reverseLanes(x.b)}; }
DRT_LANES Pair scrambleLanes(Pair x, const OwenSeed& key) { return {scrambleLanes(x.a, key), scrambleLanes(x.b, key)}; }

DRT_LANES __m256i load(const uint32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
DRT_LANES void store(uint32_t* p, const Pair& x) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), x.a);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p + 8), x.b);
}

__attribute__((target("avx2"))) void jointLanesAvx2(const uint32_t index[kLanes], uint32_t mask,
                                                     const OwenSeed& shuffle, const OwenSeed* seeds,
                                                     unsigned dimensions, uint32_t joint[kLanes],
                                                     uint32_t values[][kLanes]) {
    static_assert(kLanes == 16, "two groups of eight 32-bit lanes");
    const Pair i{load(index), load(index + 8)};
    const __m256i keep = _mm256_set1_epi32(static_cast<int>(~mask)), take = _mm256_set1_epi32(static_cast<int>(mask));
    // shuffledIndex: (i & ~mask) | (owenScramble(i, shuffle) & mask).
    const Pair shuffled = reverseLanes(scrambleLanes(reverseLanes(i), shuffle));
    const Pair j{_mm256_or_si256(_mm256_and_si256(i.a, keep), _mm256_and_si256(shuffled.a, take)),
                 _mm256_or_si256(_mm256_and_si256(i.b, keep), _mm256_and_si256(shuffled.b, take))};
    store(joint, j);
    // The joint indices' significant bits, for sobolReversedLanes.
    uint32_t any = 0;
    for (int lane = 0; lane < kLanes; ++lane) any |= joint[lane];
    const int bits = any == 0 ? 0 : 32 - __builtin_clz(any);
    for (int d = 0; d < kSobolDimensions; ++d) {
        if (!((dimensions >> d) & 1u)) continue;
        const Pair reversed = d == 0 ? j : Pair{sobolReversedLanes(j.a, d, bits), sobolReversedLanes(j.b, d, bits)};
        store(values[d], reverseLanes(scrambleLanes(reversed, seeds[d])));
    }
}

__attribute__((target("avx2"))) void runLanesAvx2(uint32_t index, uint32_t reversed1, int offset,
                                                   const OwenSeed& seed0, const OwenSeed& seed1,
                                                   uint32_t first[kRunLanes], uint32_t second[kRunLanes]) {
    static_assert(kRunLanes == 8, "one group of eight 32-bit lanes");
    const __m256i k = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i a = _mm256_or_si256(_mm256_set1_epi32(static_cast<int>(index)), k);
    const auto& bytes = kReversedBytes[0][0];
    const __m256i firstByte = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(bytes.data() + offset));
    const __m256i b = _mm256_xor_si256(_mm256_set1_epi32(static_cast<int>(reversed1)), firstByte);
    // The two scrambles are independent: their multiplies interleave.
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(first), reverseLanes(scrambleLanes(a, seed0)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(second), reverseLanes(scrambleLanes(b, seed1)));
}

#undef DRT_LANES

} // namespace

void runLanes(uint32_t index, uint32_t reversed1, int offset, const OwenSeed& seed0, const OwenSeed& seed1,
              uint32_t first[kRunLanes], uint32_t second[kRunLanes]) {
    if (haveJointLanes()) {
        runLanesAvx2(index, reversed1, offset, seed0, seed1, first, second);
        return;
    }
    runLanesScalar(index, reversed1, offset, seed0, seed1, first, second);
}

bool haveJointLanes() {
    static const bool have = __builtin_cpu_supports("avx2");
    return have;
}

void jointLanes(const uint32_t index[kLanes], uint32_t mask, const OwenSeed& shuffle, const OwenSeed* seeds,
                unsigned dimensions, uint32_t joint[kLanes], uint32_t values[][kLanes]) {
    if (haveJointLanes()) {
        jointLanesAvx2(index, mask, shuffle, seeds, dimensions, joint, values);
        return;
    }
    jointLanesScalar(index, mask, shuffle, seeds, dimensions, joint, values);
}

#else

bool haveJointLanes() { return false; }

void runLanes(uint32_t index, uint32_t reversed1, int offset, const OwenSeed& seed0, const OwenSeed& seed1,
              uint32_t first[kRunLanes], uint32_t second[kRunLanes]) {
    runLanesScalar(index, reversed1, offset, seed0, seed1, first, second);
}

void jointLanes(const uint32_t index[kLanes], uint32_t mask, const OwenSeed& shuffle, const OwenSeed* seeds,
                unsigned dimensions, uint32_t joint[kLanes], uint32_t values[][kLanes]) {
    jointLanesScalar(index, mask, shuffle, seeds, dimensions, joint, values);
}

#endif

// The one-sample functions, lane by lane: the reference the vector code is
// tested against, and the way on processors without AVX2.
void jointLanesScalar(const uint32_t index[kLanes], uint32_t mask, const OwenSeed& shuffle, const OwenSeed* seeds,
                      unsigned dimensions, uint32_t joint[kLanes], uint32_t values[][kLanes]) {
    for (int lane = 0; lane < kLanes; ++lane) {
        const uint32_t i = index[lane];
        joint[lane] = (i & ~mask) | (owenScramble(i, shuffle) & mask);
        for (int d = 0; d < kSobolDimensions; ++d)
            if ((dimensions >> d) & 1u)
                values[d][lane] = d == 0 ? scrambledSobol0(joint[lane], seeds[d])
                                         : owenScrambledSobol(joint[lane], d, seeds[d]);
    }
}

void runLanesScalar(uint32_t index, uint32_t reversed1, int offset, const OwenSeed& seed0, const OwenSeed& seed1,
                    uint32_t first[kRunLanes], uint32_t second[kRunLanes]) {
    for (int k = 0; k < kRunLanes; ++k) {
        first[k] = scrambledSobol0(index | uint32_t(k), seed0);
        second[k] = reverseBits(scrambleReversed(reversed1 ^ kReversedBytes[0][0][size_t(offset + k)], seed1));
    }
}

} // namespace drt::sobol_detail
