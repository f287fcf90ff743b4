// The image process (image/image_process.h): the parent's side (a table of
// calls that are sent to it) and the child's (a loop that answers them).
//
// Wire: each message is a 64-bit length and that many bytes. The child sends
// one message when its load has ended (the load's error, "" on success), then
// answers each request with one message. A request starts with its operation:
// 'h' hasWriter, 'w' writeFile, 'r' readImage, 'e' readImageEncoded. An
// image's pixels follow the message that gives its size (a write's request, a
// read's answer), straight from and into its buffer.
#include "image/image_process.h"

#include "core/modules.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fmt/format.h>
#include <memory>
#include <mutex>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace drt {

// image.cpp: the module loaded in this process.
const LoadedModule<ImageIoModule>& imageIoInThisProcess();

namespace {

// ---------------------------------------------------------------- the wire

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

// An image's pixels go after its message as they are: their count, then the
// floats, written from and read into the image's own buffer (no copy of a
// large image is made on the way).
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

// ---------------------------------------------------------------- the child

void writeBudget(Writer& w, const ReadBudget& budget) {
    w.u64(budget.megabytes);
    w.text(budget.hint);
}

ReadBudget readBudget(Reader& r) {
    ReadBudget budget{r.u64(), {}};
    budget.hint = r.text();
    return budget;
}

[[noreturn]] void serve(int fd) {
    // The parent's interrupt is its own to handle (it still writes the
    // partial image through this process); this one ends with the parent
    // (PR_SET_PDEATHSIG) or when the parent closes the socket.
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    const LoadedModule<ImageIoModule>& io = imageIoInThisProcess();
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

// ---------------------------------------------------------------- the parent

struct Process {
    std::mutex mutex; // one exchange at a time
    int fd = -1;
    pid_t pid = -1;
    std::atomic<bool> noticed{false};
    LoadedModule<ImageIoModule> module; // set with noticed
    bool ended = false;                 // the process is gone (mutex)
    std::string endedWhy;
};

std::atomic<bool> allowed{false};
std::atomic<bool> started{false};

Process& process() {
    static Process p;
    return p;
}

// Why the process is gone, once (mutex held).
const std::string& markEnded(Process& p) {
    if (!p.ended) {
        p.ended = true;
        int status = 0;
        std::string how = "it ended unexpectedly";
        // The socket ended: the process is leaving (it closes it only by
        // ending), so waiting for it is short.
        pid_t waited = -1;
        while (p.pid > 0 && (waited = ::waitpid(p.pid, &status, 0)) < 0 && errno == EINTR) {
        }
        if (p.pid > 0 && waited == p.pid) {
            p.pid = -1;
            if (WIFSIGNALED(status)) how = fmt::format("it was ended by signal {}", WTERMSIG(status));
            else if (WIFEXITED(status)) how = fmt::format("it exited with status {}", WEXITSTATUS(status));
        }
        p.endedWhy = "drt's image process (OpenImageIO) is gone: " + how;
    }
    return p.endedWhy;
}

// Reads the load notice (mutex held).
void receiveNotice(Process& p) {
    if (p.noticed.load()) return;
    std::string bytes;
    if (!receiveMessage(p.fd, bytes)) {
        p.module.error = markEnded(p);
    } else {
        Reader in(bytes);
        p.module.error = in.text();
    }
    if (!p.module.error.empty()) p.module.table = nullptr; // no module: the callers report the error
    p.noticed.store(true);
}

// One request and its answer, with the pixels that follow the request
// (`sent`) or the answer (`received`); false (with `why`) if the process is gone.
bool exchange(const Writer& request, std::string& answer, std::string& why,
              const std::vector<float>* sent = nullptr, std::vector<float>* received = nullptr) {
    Process& p = process();
    const std::lock_guard<std::mutex> lock(p.mutex);
    receiveNotice(p);
    if (p.ended || !sendMessage(p.fd, request.bytes()) || (sent && !sendPixels(p.fd, *sent)) ||
        !receiveMessage(p.fd, answer) || (received && !receivePixels(p.fd, *received))) {
        why = markEnded(p);
        return false;
    }
    return true;
}

bool remoteHasWriter(const std::string& path) {
    Writer w;
    w.u8('h');
    w.text(path);
    std::string answer, why;
    // A process that is gone: say yes, so that the write reports why it fails.
    if (!exchange(w, answer, why)) return true;
    Reader in(answer);
    return in.u8() != 0;
}

std::string remoteWriteFile(const std::string& file, const std::string& path, const Image& image,
                            const Metadata& metadata) {
    Writer w;
    w.u8('w');
    w.text(file);
    w.text(path);
    w.size(image);
    w.metadata(metadata);
    std::string answer, why;
    if (!exchange(w, answer, why, &image.pixels)) return why;
    Reader in(answer);
    return in.text();
}

// A read's exchange: the request (its operation and fields so far) with the
// budget, then the answer's reason and image; `rest` reads what follows them
// and returns what stores it, called only if the read succeeded.
template <class Rest>
std::string remoteRead(Writer& request, const std::string& path, const ReadBudget& budget, Image& image, Rest&& rest) {
    writeBudget(request, budget);
    std::string answer, why;
    Image read;
    if (!exchange(request, answer, why, nullptr, &read.pixels)) return "cannot read '" + path + "': " + why;
    Reader in(answer);
    std::string problem = in.text();
    in.size(read);
    const auto keep = rest(in);
    if (in.bad() || (problem.empty() && !holdsItsPixels(read)))
        return "cannot read '" + path + "': a malformed answer from drt's image process";
    if (!problem.empty()) return problem;
    image = std::move(read);
    keep();
    return "";
}

std::string remoteReadImage(const std::string& path, Image& image, Metadata* metadata, const ReadBudget& budget) {
    Writer w;
    w.u8('r');
    w.text(path);
    w.u8(metadata ? 1 : 0);
    return remoteRead(w, path, budget, image, [metadata](Reader& in) {
        auto read = std::make_shared<Metadata>();
        in.metadata(*read);
        return [metadata, read] {
            if (metadata) *metadata = std::move(*read);
        };
    });
}

std::string remoteReadImageEncoded(const std::string& path, Image& image, ImageFileInfo& info,
                                   const ReadBudget& budget) {
    Writer w;
    w.u8('e');
    w.text(path);
    return remoteRead(w, path, budget, image, [&info](Reader& in) {
        ImageFileInfo got;
        got.bitsPerChannel = int(in.u64());
        got.isFloat = in.u8() != 0;
        got.srgbEncoded = in.u8() != 0;
        got.fileGamma = in.f64();
        return [&info, got] { info = got; };
    });
}

constexpr ImageIoModule kRemoteTable{kImageIoModuleVersion, remoteHasWriter, remoteWriteFile, remoteReadImage,
                                     remoteReadImageEncoded};

// Whether this process has exactly one thread: fork copies only the calling
// one, and a lock another thread held would stay held in the child.
bool singleThreaded() {
    DIR* tasks = ::opendir("/proc/self/task");
    if (!tasks) return false;
    int count = 0;
    while (const dirent* entry = ::readdir(tasks))
        if (entry->d_name[0] != '.') ++count;
    ::closedir(tasks);
    return count == 1;
}

} // namespace

void allowImageIoProcess() { allowed.store(true); }

bool imageIoProcessStarted() { return started.load(); }

bool startImageIoProcess() {
    if (started.load()) return true;
    if (!allowed.load()) return false;
    if (const char* setting = std::getenv("DRT_IMAGE_PROCESS"); setting && std::string(setting) == "0") return false;
    if (!singleThreaded()) return false;
    int sockets[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) return false;
    const pid_t parent = ::getpid();
    std::fflush(nullptr); // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(sockets[0]);
        ::close(sockets[1]);
        return false;
    }
    if (pid == 0) {
        ::close(sockets[0]);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) std::_Exit(0); // the parent ended before the line above
        serve(sockets[1]);
    }
    ::close(sockets[1]);
    Process& p = process();
    p.fd = sockets[0];
    p.pid = pid;
    p.module.table = &kRemoteTable;
    started.store(true);
    return true;
}

const LoadedModule<ImageIoModule>* imageIoProcessModule() {
    if (!started.load()) return nullptr;
    Process& p = process();
    if (!p.noticed.load()) {
        const std::lock_guard<std::mutex> lock(p.mutex);
        receiveNotice(p);
    }
    return &p.module;
}

bool imageIoProcessLoading() {
    if (!started.load()) return false;
    Process& p = process();
    if (p.noticed.load()) return false;
    std::unique_lock<std::mutex> lock(p.mutex, std::try_to_lock);
    if (!lock.owns_lock()) return true; // another thread waits for the notice, or asks
    pollfd ready{p.fd, POLLIN, 0};
    if (::poll(&ready, 1, 0) == 1) receiveNotice(p);
    return !p.noticed.load();
}

void endImageIoProcess() {
    if (!started.load()) return;
    Process& p = process();
    const std::lock_guard<std::mutex> lock(p.mutex);
    if (p.fd >= 0) {
        // A load still running is of no more use (a render that failed
        // before its first image): stop it rather than wait for it.
        pollfd ready{p.fd, POLLIN, 0};
        if (!p.noticed.load() && !p.ended && ::poll(&ready, 1, 0) == 0 && p.pid > 0) ::kill(p.pid, SIGKILL);
        ::close(p.fd); // the process sees the end and leaves
        p.fd = -1;
    }
    if (p.pid > 0) {
        int status = 0;
        while (::waitpid(p.pid, &status, 0) < 0 && errno == EINTR) {
        }
        p.pid = -1;
    }
    p.ended = true;
    p.endedWhy = "drt's image process (OpenImageIO) has ended";
}

} // namespace drt
