// The image process's wire (image/image_process.h): the messages drt render
// and its image process exchange over their socket, and the image process's
// side of it, which runs either in a program of its own (drt_image_process,
// image/oiio/image_process_main.cpp) or in a forked copy of drt.
//
// Wire: each message is a 64-bit length and that many bytes. The process sends
// one message when its load has ended (the load's error, "" on success), then
// answers each request with one message. A request starts with its operation:
// 'h' hasWriter, 'w' writeFile, 'r' readImage, 'e' readImageEncoded. An
// image's pixels follow the message that gives its size (a write's request, a
// read's answer), straight from and into its buffer.
#pragma once

#include "core/modules.h"
#include "image/image_io_module.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace drt {

// The module loaded in this process, once (image.cpp).
const LoadedModule<ImageIoModule>& imageIoInThisProcess();

namespace image_wire {

// The program that serves the image process, looked for as a module is
// (core/modules.h), and the argument that names the protocol it must speak:
// a program of another build refuses to serve (it exits with status 2).
inline constexpr const char* kProgramFile = "drt_image_process";
inline constexpr const char* kProtocol = "--drt-image-process-protocol=1";

class Writer {
public:
    void u8(uint8_t v) { bytes_.push_back(char(v)); }
    void u64(uint64_t v) { raw(&v, sizeof v); }
    void f64(double v) { raw(&v, sizeof v); }
    void text(const std::string& s) {
        u64(s.size());
        bytes_.append(s);
    }
    // An image's size; its pixels follow the message (sendPixels).
    void size(const Image& image) {
        u64(uint64_t(image.width));
        u64(uint64_t(image.height));
        u64(uint64_t(image.channels));
    }
    void metadata(const Metadata& metadata) {
        u64(metadata.size());
        for (const auto& [key, value] : metadata) {
            text(key);
            text(value);
        }
    }
    const std::string& bytes() const { return bytes_; }

private:
    void raw(const void* data, size_t size) { bytes_.append(static_cast<const char*>(data), size); }
    std::string bytes_;
};

// Reads what Writer wrote; a message too short reads as zeros and sets bad().
class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    uint8_t u8() {
        uint8_t v = 0;
        raw(&v, 1);
        return v;
    }
    uint64_t u64() {
        uint64_t v = 0;
        raw(&v, sizeof v);
        return v;
    }
    double f64() {
        double v = 0;
        raw(&v, sizeof v);
        return v;
    }
    std::string text() {
        const uint64_t size = u64();
        if (size > bytes_.size() - at_) {
            bad_ = true;
            return {};
        }
        std::string s = bytes_.substr(at_, size);
        at_ += size;
        return s;
    }
    void size(Image& image) {
        image.width = int(u64());
        image.height = int(u64());
        image.channels = int(u64());
    }
    void metadata(Metadata& metadata) {
        const uint64_t count = u64();
        metadata.clear();
        for (uint64_t i = 0; i < count && !bad_; ++i) {
            std::string key = text();
            std::string value = text();
            metadata.emplace_back(std::move(key), std::move(value));
        }
    }
    bool bad() const { return bad_; }

private:
    void raw(void* out, size_t size) {
        if (size > bytes_.size() - at_) {
            bad_ = true;
            std::memset(out, 0, size);
            return;
        }
        std::memcpy(out, bytes_.data() + at_, size);
        at_ += size;
    }
    const std::string& bytes_;
    size_t at_ = 0;
    bool bad_ = false;
};

bool sendMessage(int fd, const std::string& bytes);
bool receiveMessage(int fd, std::string& bytes);
// An image's pixels go after its message as they are: their count, then the
// floats, written from and read into the image's own buffer (no copy of a
// large image is made on the way).
bool sendPixels(int fd, const std::vector<float>& pixels);
bool receivePixels(int fd, std::vector<float>& pixels);
bool holdsItsPixels(const Image& image);
void writeBudget(Writer& w, const ReadBudget& budget);
ReadBudget readBudget(Reader& r);

// The image process's side: sends the notice of `io`'s load, then answers
// requests on `fd` until the other side closes it; never returns.
[[noreturn]] void serve(int fd, const LoadedModule<ImageIoModule>& io);

} // namespace image_wire
} // namespace drt
