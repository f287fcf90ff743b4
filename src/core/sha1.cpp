// SHA-1 (core/sha1.h): 512-bit blocks, 80 rounds per block; the message is
// padded with a 1 bit, zeros, and its length in bits as a big-endian 64-bit
// number to a multiple of 64 bytes.
#include "core/sha1.h"

#include <fmt/format.h>

namespace drt {

namespace {

constexpr uint32_t rotl(uint32_t x, int n) { return (x << n) | (x >> (32 - n)); }

} // namespace

void Sha1::compress(const uint8_t* block) {
    uint32_t w[80];
    for (int t = 0; t < 16; ++t)
        w[t] = uint32_t(block[4 * t]) << 24 | uint32_t(block[4 * t + 1]) << 16 | uint32_t(block[4 * t + 2]) << 8 |
               uint32_t(block[4 * t + 3]);
    for (int t = 16; t < 80; ++t)
        w[t] = rotl(w[t - 3] ^ w[t - 8] ^ w[t - 14] ^ w[t - 16], 1);
    uint32_t a = state_[0], b = state_[1], c = state_[2], d = state_[3], e = state_[4];
    for (int t = 0; t < 80; ++t) {
        uint32_t f, k;
        if (t < 20)
            f = (b & c) | (~b & d), k = 0x5A827999u; // choose
        else if (t < 40)
            f = b ^ c ^ d, k = 0x6ED9EBA1u; // parity
        else if (t < 60)
            f = (b & c) | (b & d) | (c & d), k = 0x8F1BBCDCu; // majority
        else
            f = b ^ c ^ d, k = 0xCA62C1D6u; // parity
        const uint32_t next = rotl(a, 5) + f + e + k + w[t];
        e = d, d = c, c = rotl(b, 30), b = a, a = next;
    }
    state_[0] += a, state_[1] += b, state_[2] += c, state_[3] += d, state_[4] += e;
}

void Sha1::append(std::string_view bytes) {
    length_ += bytes.size();
    for (char ch : bytes) {
        buffer_[buffered_++] = static_cast<uint8_t>(ch);
        if (buffered_ == buffer_.size()) {
            compress(buffer_.data());
            buffered_ = 0;
        }
    }
}

std::string Sha1::hexDigest() {
    const uint64_t bits = length_ * 8;
    const uint8_t one = 0x80, zero = 0;
    append(std::string_view(reinterpret_cast<const char*>(&one), 1));
    while (buffered_ != 56)
        append(std::string_view(reinterpret_cast<const char*>(&zero), 1));
    uint8_t lengthBytes[8];
    for (int i = 0; i < 8; ++i)
        lengthBytes[i] = uint8_t(bits >> (56 - 8 * i));
    append(std::string_view(reinterpret_cast<const char*>(lengthBytes), 8));
    std::string hex;
    for (uint32_t word : state_)
        hex += fmt::format("{:08x}", word);
    return hex;
}

} // namespace drt
