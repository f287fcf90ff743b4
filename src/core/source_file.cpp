#include "core/source_file.h"

#include "core/limits.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace drt {

std::string readSourceFile(const std::string& path, int64_t maxBytes, std::string& text) {
    // O_NONBLOCK: opening a FIFO with no writer must not wait; fstat on the
    // open file then refuses it (and devices, folders) without a race.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return fmt::format("cannot open '{}': {}", path, std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0) return fmt::format("cannot read '{}': {}", path, std::strerror(errno));
    if (!S_ISREG(info.st_mode))
        return fmt::format("'{}' is not a regular file ({})", path,
                           S_ISDIR(info.st_mode) ? "a folder" : S_ISFIFO(info.st_mode) ? "a pipe" : "a device");
    if (maxBytes >= 0 && info.st_size > maxBytes) {
        Limits limits;
        limits.includeBytes = maxBytes;
        return fmt::format("'{}' is {} bytes, over the limit of {} ({})", path, int64_t(info.st_size), maxBytes,
                           limitHint(limits, &Limits::includeBytes));
    }
    text.assign(size_t(info.st_size), '\0');
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t got = ::read(fd, text.data() + done, text.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return fmt::format("cannot read '{}': {}", path, std::strerror(errno));
        if (got == 0) break; // the file shrank while being read
        done += size_t(got);
    }
    text.resize(done);
    stripByteOrderMark(text);
    return "";
}

void stripByteOrderMark(std::string& text) {
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
}

bool hasSceneExtension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* known : {"drt", "pov", "inc", "mcr"})
        if (ext == known) return true;
    return false;
}

} // namespace drt
