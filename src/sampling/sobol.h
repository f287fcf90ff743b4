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

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace drt {

// Number of dimensions with direction numbers: the five jointly stratified
// camera dimensions (pixel 0-1, time 2, lens 3-4).
inline constexpr int kSobolDimensions = 5;

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

// Inline below, as the sampler calls them a few times per camera sample:
// Dimension d (0 <= d < kSobolDimensions) of Sobol point `index`, as a 32-bit
// fraction (value / 2^32).
constexpr uint32_t sobolValue(uint32_t index, int dimension);
// == owenScramble(value, seed.seed)
constexpr uint32_t owenScramble(uint32_t value, const OwenSeed& seed);
// == owenScramble(sobolValue(index, 0), seed), with two bit reversals fewer.
constexpr uint32_t scrambledSobol0(uint32_t index, const OwenSeed& seed);
// == owenScramble(sobolValue(index, dimension), seed)
constexpr uint32_t owenScrambledSobol(uint32_t index, int dimension, const OwenSeed& seed);

namespace sobol_detail {

// Primitive polynomial of degree s over GF(2) with inner coefficients a
// (a_1 ... a_{s-1}, a_1 the most significant of the s-1 bits) and initial
// direction integers m_1..m_s: the first rows of Joe & Kuo's
// new-joe-kuo-6.21201 table (its dimensions 2-5; its dimension 1 is the van der
// Corput sequence, our dimension 0).
struct Polynomial {
    int degree;
    uint32_t a;
    std::array<uint32_t, 3> m;
};
constexpr std::array<Polynomial, kSobolDimensions - 1> kPolynomials{{
    {1, 0, {1, 0, 0}},
    {2, 1, {1, 3, 0}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
}};

using DirectionNumbers = std::array<std::array<uint32_t, 32>, kSobolDimensions>;

// v_k = m_k / 2^k, with the recurrence (Bratley & Fox 1988)
//   m_k = 2 a_1 m_{k-1} ^ 4 a_2 m_{k-2} ^ ... ^ 2^{s-1} a_{s-1} m_{k-s+1} ^ 2^s m_{k-s} ^ m_{k-s}.
constexpr DirectionNumbers makeDirectionNumbers() {
    DirectionNumbers v{};
    for (int k = 0; k < 32; ++k) v[0][k] = 1u << (31 - k);
    for (int d = 1; d < kSobolDimensions; ++d) {
        const Polynomial& p = kPolynomials[d - 1];
        std::array<uint64_t, 33> m{}; // m[1..32]
        for (int k = 1; k <= 32; ++k) {
            if (k <= p.degree) {
                m[k] = p.m[k - 1];
                continue;
            }
            const int s = p.degree;
            uint64_t value = (m[k - s] << s) ^ m[k - s];
            for (int i = 1; i < s; ++i)
                if ((p.a >> (s - 1 - i)) & 1u) value ^= m[k - i] << i;
            m[k] = value;
        }
        for (int k = 1; k <= 32; ++k) v[d][k - 1] = static_cast<uint32_t>(m[k] << (32 - k));
    }
    return v;
}
constexpr DirectionNumbers kDirections = makeDirectionNumbers();

// A byte swap (one instruction), then the bits within each byte.
constexpr uint32_t reverseBits(uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// The bits of each byte value reversed: reverseBits(v) == kReversedByte[v] << 24
// for v < 256, and reverseBits(x) & 255 == kReversedByte[x >> 24].
constexpr std::array<uint8_t, 256> makeReversedBytes() {
    std::array<uint8_t, 256> t{};
    for (uint32_t v = 0; v < 256; ++v) t[v] = static_cast<uint8_t>(reverseBits(v) >> 24);
    return t;
}
inline constexpr std::array<uint8_t, 256> kReversedByte = makeReversedBytes();

// Dimensions 1.. of the sequence bit-reversed, a byte of the index at a time:
// kReversedBytes[d - 1][b][v] is the XOR of the reversed direction numbers
// reverseBits(v_d[8 b + j]) over the set bits j of v. Reversing commutes with
// XOR, so XORing one entry per byte of the index gives the reversed value,
// which is what the scramble works on: a look-up per byte (one for indices
// below 256, a pixel's usual sample indices) instead of a step per bit and
// two reversals.
using ReversedByteTables = std::array<std::array<std::array<uint32_t, 256>, 4>, kSobolDimensions - 1>;
constexpr ReversedByteTables makeReversedByteTables() {
    ReversedByteTables t{};
    for (int d = 1; d < kSobolDimensions; ++d)
        for (int b = 0; b < 4; ++b)
            for (uint32_t v = 0; v < 256; ++v) {
                uint32_t x = 0;
                for (int j = 0; j < 8; ++j)
                    if ((v >> j) & 1u) x ^= reverseBits(kDirections[size_t(d)][size_t(8 * b + j)]);
                t[size_t(d - 1)][size_t(b)][v] = x;
            }
    return t;
}
inline constexpr ReversedByteTables kReversedBytes = makeReversedByteTables();

// reverseBits(sobolValue(index, dimension)).
constexpr uint32_t sobolReversed(uint32_t index, int dimension) {
    if (dimension == 0) return index; // van der Corput's: the index reversed, reversed back
    const auto& bytes = kReversedBytes[static_cast<size_t>(dimension - 1)];
    uint32_t result = bytes[0][index & 255u];
    for (size_t b = 1; (index >>= 8) != 0; ++b) result ^= bytes[b][index & 255u];
    return result;
}

// The scramble on the bit-reversed word, where the first digit is bit 0. Each
// step changes bit j by a function of bits 0..j-1 only (adding: carries travel
// upward; x ^= x * even: bit j of the product sees bits below j; x *= odd: x
// plus an even multiple), so digit j is flipped by a function of the digits
// before it: a nested uniform scramble. The seed enters three times so that
// the flip functions of deep digits also vary with it.
constexpr uint32_t scrambleReversed(uint32_t x, const OwenSeed& key) {
    const uint32_t seed = key.seed, seed2 = key.seed2;
    x += seed;
    x ^= x * 0x9e3779b8u;
    x *= seed2 | 1u;
    x ^= x * 0x85ebca6cu;
    x += seed2 >> 7;
    x ^= x * 0xc2b2ae36u;
    x ^= x * (seed & ~1u);
    return x;
}

} // namespace sobol_detail

constexpr uint32_t sobolValue(uint32_t index, int dimension) {
    return sobol_detail::reverseBits(sobol_detail::sobolReversed(index, dimension));
}

constexpr uint32_t owenScramble(uint32_t value, const OwenSeed& key) {
    return sobol_detail::reverseBits(sobol_detail::scrambleReversed(sobol_detail::reverseBits(value), key));
}

// Dimension 0's value is the index bit-reversed: reversed again for the
// scramble, it is the index itself.
constexpr uint32_t scrambledSobol0(uint32_t index, const OwenSeed& key) {
    return sobol_detail::reverseBits(sobol_detail::scrambleReversed(index, key));
}

// The value is scrambled bit-reversed: the reversed table gives it so directly.
constexpr uint32_t owenScrambledSobol(uint32_t index, int dimension, const OwenSeed& key) {
    return sobol_detail::reverseBits(
        sobol_detail::scrambleReversed(sobol_detail::sobolReversed(index, dimension), key));
}

// Sixteen samples at once (sobol_lanes.cpp). For the sample indices index[l]
// of one pixel: joint[l], the index shuffled as the sampler shuffles it,
// (i & ~mask) | (owenScramble(i, shuffle) & mask), and for every dimension d
// whose bit is set in `dimensions`, values[d][l], that joint index's point in
// dimension d scrambled with seeds[d] (scrambledSobol0 for d = 0, else
// owenScrambledSobol). With AVX2 the lanes are worked out side by side, as the
// same integer arithmetic, in two groups of eight whose steps interleave;
// elsewhere one after another (jointLanesScalar).
namespace sobol_detail {
inline constexpr int kLanes = 16;
bool haveJointLanes(); // the processor runs the AVX2 lanes
void jointLanes(const uint32_t index[kLanes], uint32_t mask, const OwenSeed& shuffle, const OwenSeed* seeds,
                unsigned dimensions, uint32_t joint[kLanes], uint32_t values[][kLanes]);
void jointLanesScalar(const uint32_t index[kLanes], uint32_t mask, const OwenSeed& shuffle, const OwenSeed* seeds,
                      unsigned dimensions, uint32_t joint[kLanes], uint32_t values[][kLanes]);

// Eight points of a power-of-two run of stratified points (the sampler's
// get2DStratifiedRun) at once: for k < 8, first[k] = scrambledSobol0(index | k,
// seed0) and second[k] = reverseBits(scrambleReversed(reversed1 ^
// kReversedBytes[0][0][offset + k], seed1)), index's low three bits clear and
// offset a multiple of 8. With AVX2 the eight lanes side by side; elsewhere
// (runLanesScalar) one after another, the same values.
inline constexpr int kRunLanes = 8;
void runLanes(uint32_t index, uint32_t reversed1, int offset, const OwenSeed& seed0, const OwenSeed& seed1,
              uint32_t first[kRunLanes], uint32_t second[kRunLanes]);
void runLanesScalar(uint32_t index, uint32_t reversed1, int offset, const OwenSeed& seed0, const OwenSeed& seed1,
                    uint32_t first[kRunLanes], uint32_t second[kRunLanes]);
} // namespace sobol_detail

// A double in [0, 1) from a 32-bit fraction.
inline double fractionToUnit(uint32_t v) { return v * 0x1.0p-32; }

// `lanes`: a packet's camera dimensions are drawn sixteen samples at once
// (sobol_detail::jointLanes) where the processor has AVX2 and the packet is
// not tiny; false draws them one sample at a time, the same values (the tests
// compare the two).
std::unique_ptr<Sampler> makeSobolSampler(int samplesPerPixel, uint64_t seed, bool lanes = true);

} // namespace drt
