// SHA-1 (FIPS 180-4), for naming content: the hash drt records of a scene's
// text and its includes in the files it writes, the same digest `sha1sum`
// prints. Not for security (SHA-1 collisions can be made); it identifies text.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace drt {

class Sha1 {
  public:
    void append(std::string_view bytes);
    // Lower-case hex of the digest of everything appended (the object is then spent).
    std::string hexDigest();

  private:
    void compress(const uint8_t* block);

    std::array<uint32_t, 5> state_{0x67452301u, 0xEFCDAB89u, 0x98BADCFEu, 0x10325476u, 0xC3D2E1F0u};
    std::array<uint8_t, 64> buffer_{};
    size_t buffered_ = 0;
    uint64_t length_ = 0; // bytes appended
};

} // namespace drt
