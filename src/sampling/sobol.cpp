#include "sampling/sobol.h"

#include "core/hash.h"

namespace drt {

static_assert(sobol_detail::reverseBits(1u) == 0x80000000u && sobol_detail::reverseBits(0x12345678u) == 0x1e6a2c48u);

OwenSeed::OwenSeed(uint32_t s) : seed(s), seed2(static_cast<uint32_t>(mix64(s))) {}

uint32_t owenScramble(uint32_t value, uint32_t seed) { return owenScramble(value, OwenSeed(seed)); }

} // namespace drt
