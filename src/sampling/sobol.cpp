#include "sampling/sobol.h"

#include "core/hash.h"

#include <array>
#include <bit>

namespace drt {
namespace {

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

constexpr uint32_t reverseBits(uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

} // namespace

uint32_t sobolValue(uint32_t index, int dimension) {
    // Dimension 0 is van der Corput's (v_k = 2^(31-k)): the index with its bits reversed.
    if (dimension == 0) return reverseBits(index);
    const auto& v = kDirections[static_cast<size_t>(dimension)];
    uint32_t result = 0;
    // No branch per bit: index bits are random, such a branch mispredicts half the time.
    for (int j = 0; index != 0; ++j, index >>= 1) result ^= v[static_cast<size_t>(j)] & (0u - (index & 1u));
    return result;
}

OwenSeed::OwenSeed(uint32_t s) : seed(s), seed2(static_cast<uint32_t>(mix64(s))) {}

uint32_t owenScramble(uint32_t value, uint32_t seed) { return owenScramble(value, OwenSeed(seed)); }

uint32_t owenScramble(uint32_t value, const OwenSeed& key) {
    const uint32_t seed = key.seed, seed2 = key.seed2;
    // In the bit-reversed word the first digit is bit 0. Each step below changes
    // bit j by a function of bits 0..j-1 only (adding: carries travel upward;
    // x ^= x * even: bit j of the product sees bits below j; x *= odd: x plus an
    // even multiple), so digit j is flipped by a function of the digits before
    // it: a nested uniform scramble. The seed enters three times so that the
    // flip functions of deep digits also vary with it.
    uint32_t x = reverseBits(value);
    x += seed;
    x ^= x * 0x9e3779b8u;
    x *= seed2 | 1u;
    x ^= x * 0x85ebca6cu;
    x += seed2 >> 7;
    x ^= x * 0xc2b2ae36u;
    x ^= x * (seed & ~1u);
    return reverseBits(x);
}

} // namespace drt
