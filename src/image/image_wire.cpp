// The image process's wire and its serving side (image/image_wire.h).
#include "image/image_wire.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <sys/socket.h>
#include <sys/types.h>
#include <unistd.h>

namespace drt::image_wire {

namespace {

bool sendAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        const ssize_t sent = ::send(fd, data, size, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR) continue;
        if (sent <= 0) return false;
        data += sent;
        size -= size_t(sent);
    }
    return true;
}

bool receiveAll(int fd, char* data, size_t size) {
    while (size > 0) {
        const ssize_t got = ::recv(fd, data, size, 0);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        data += got;
        size -= size_t(got);
    }
    return true;
}

} // namespace

bool sendMessage(int fd, const std::string& bytes) {
    const uint64_t size = bytes.size();
    return sendAll(fd, reinterpret_cast<const char*>(&size), sizeof size) && sendAll(fd, bytes.data(), bytes.size());
}

bool receiveMessage(int fd, std::string& bytes) {
    uint64_t size = 0;
    if (!receiveAll(fd, reinterpret_cast<char*>(&size), sizeof size)) return false;
    if (size > (uint64_t(1) << 40)) return false; // not a message of ours
    bytes.resize(size);
    return receiveAll(fd, bytes.data(), size);
}

bool sendPixels(int fd, const std::vector<float>& pixels) {
    const uint64_t count = pixels.size();
    return sendAll(fd, reinterpret_cast<const char*>(&count), sizeof count) &&
           sendAll(fd, reinterpret_cast<const char*>(pixels.data()), count * sizeof(float));
}

bool receivePixels(int fd, std::vector<float>& pixels) {
    uint64_t count = 0;
    if (!receiveAll(fd, reinterpret_cast<char*>(&count), sizeof count)) return false;
    if (count > (uint64_t(1) << 38)) return false; // not a message of ours
    pixels.resize(count);
    return receiveAll(fd, reinterpret_cast<char*>(pixels.data()), count * sizeof(float));
}

bool holdsItsPixels(const Image& image) {
    return image.width >= 0 && image.height >= 0 && image.channels >= 0 &&
           image.pixels.size() == size_t(image.width) * size_t(image.height) * size_t(image.channels);
}

void writeBudget(Writer& w, const ReadBudget& budget) {
    w.u64(budget.megabytes);
    w.text(budget.hint);
}

ReadBudget readBudget(Reader& r) {
    ReadBudget budget{r.u64(), {}};
    budget.hint = r.text();
    return budget;
}

[[noreturn]] void serve(int fd, const LoadedModule<ImageIoModule>& io) {
    // The parent's interrupt is its own to handle (it still writes the
    // partial image through this process); this one ends with the parent
    // (PR_SET_PDEATHSIG) or when the parent closes the socket.
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    {
        Writer notice;
        notice.text(io.table ? std::string() : io.error);
        if (!sendMessage(fd, notice.bytes())) std::_Exit(0);
    }
    if (const char* test = std::getenv("DRT_TEST_IMAGE_PROCESS_ENDS"); test && *test == '1')
        std::_Exit(3); // tests: the process ends as if killed after its load
    std::string request;
    while (receiveMessage(fd, request)) {
        Reader in(request);
        Writer out;
        Image image;                              // a read's image, sent after the answer
        const std::vector<float>* pixels = nullptr; // set when the answer has pixels
        const uint8_t operation = in.u8();
        if (!io.table) std::_Exit(0); // the parent never asks after a failed load
        if (operation == 'h') {
            const std::string path = in.text();
            out.u8(io.table->hasWriter(path) ? 1 : 0);
        } else if (operation == 'w') {
            const std::string file = in.text(), path = in.text();
            in.size(image);
            Metadata metadata;
            in.metadata(metadata);
            if (!receivePixels(fd, image.pixels)) break;
            out.text(in.bad() || !holdsItsPixels(image) ? std::string("a malformed request")
                                                        : io.table->writeFile(file, path, image, metadata));
        } else if (operation == 'r') {
            const std::string path = in.text();
            const bool wantsMetadata = in.u8() != 0;
            const ReadBudget budget = readBudget(in);
            Metadata metadata;
            out.text(io.table->readImage(path, image, wantsMetadata ? &metadata : nullptr, budget));
            out.size(image);
            out.metadata(metadata);
            pixels = &image.pixels;
        } else if (operation == 'e') {
            const std::string path = in.text();
            const ReadBudget budget = readBudget(in);
            ImageFileInfo info;
            out.text(io.table->readImageEncoded(path, image, info, budget));
            out.size(image);
            out.u64(uint64_t(info.bitsPerChannel));
            out.u8(info.isFloat ? 1 : 0);
            out.u8(info.srgbEncoded ? 1 : 0);
            out.f64(info.fileGamma);
            pixels = &image.pixels;
        } else {
            std::_Exit(0);
        }
        if (!sendMessage(fd, out.bytes()) || (pixels && !sendPixels(fd, *pixels))) break;
    }
    std::_Exit(0);
}

} // namespace drt::image_wire
