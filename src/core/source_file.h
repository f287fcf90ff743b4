// Reading scene text from a file, for both front ends: only regular files (a
// FIFO, a device like /dev/zero or a folder is refused before reading), at
// most a given size, with a UTF-8 byte-order mark dropped.
#pragma once

#include <cstdint>
#include <string>

namespace drt {

// Reads `path` into `text`. Returns "" or why it cannot be read, e.g.
// "'/dev/zero' is not a regular file" or "'big.inc' is 80000000 bytes, over the
// limit of ... (limit include_bytes = ...; raise it with --limit include_bytes=N)".
// `maxBytes` < 0: no size limit.
std::string readSourceFile(const std::string& path, int64_t maxBytes, std::string& text);

// Drops a UTF-8 byte-order mark (EF BB BF) at the start of `text`.
void stripByteOrderMark(std::string& text);

// Whether a file name says it holds scene text (.drt .pov .inc .mcr), so that its lines may be quoted under an error. An #include of any
// other file (a user's /etc/passwd) is read, but its lines are never printed.
bool hasSceneExtension(const std::string& path);

} // namespace drt
