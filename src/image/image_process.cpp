// The image process (image/image_process.h): the parent's side, a table of
// calls sent over the wire (image/image_wire.h) to the process, which runs
// the program drt_image_process or, where that is not found, serves from the
// forked copy of drt.
#include "image/image_process.h"

#include "core/modules.h"
#include "image/image_wire.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <memory>
#include <mutex>
#include <poll.h>
#include <string>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace drt {

namespace {

using namespace image_wire;

// The program that serves the image process; the build tree's path comes from
// CMake (DRT_IMAGE_PROCESS_PROGRAM_BUILD_PATH).
constexpr ModuleSpec kProgramSpec{kProgramFile, "", "DRT_IMAGE_PROCESS_PROGRAM", DRT_IMAGE_PROCESS_PROGRAM_BUILD_PATH,
                                  "drt's image process program"};

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
    // Made before fork: the child only calls what is safe there.
    std::string program = findModuleFile(kProgramSpec);
    std::string socketText = std::to_string(sockets[1]);
    std::fflush(nullptr); // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(sockets[0]);
        ::close(sockets[1]);
        return false;
    }
    if (pid == 0) {
        ::close(sockets[0]);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // kept across exec
        if (::getppid() != parent) std::_Exit(0); // the parent ended before the line above
        // The program loads OpenImageIO with only the C and C++ runtimes
        // before it in the loader's search list, where this copy of drt has
        // all of drt's libraries (docs/performance.md, "The image process as a
        // program of its own"). If it cannot be run, this copy serves: the same
        // code, the same answers.
        const int flags = program.empty() ? -1 : ::fcntl(sockets[1], F_GETFD);
        if (flags >= 0 && ::fcntl(sockets[1], F_SETFD, flags & ~FD_CLOEXEC) == 0) {
            char* const argv[] = {program.data(), const_cast<char*>(kProtocol), socketText.data(), nullptr};
            ::execv(program.c_str(), argv);
        }
        serve(sockets[1], imageIoInThisProcess());
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

namespace {

// Closes the socket: the process sees the end and leaves; a later exchange
// reports it ended (mutex held).
void closeSocket(Process& p) {
    if (p.fd >= 0) ::close(p.fd);
    p.fd = -1;
    p.ended = true;
    p.endedWhy = "drt's image process (OpenImageIO) has ended";
}

} // namespace

void releaseImageIoProcess() {
    if (!started.load()) return;
    Process& p = process();
    const std::lock_guard<std::mutex> lock(p.mutex);
    if (p.fd >= 0 && !p.ended && p.noticed.load()) closeSocket(p);
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
    }
    closeSocket(p);
    if (p.pid > 0) {
        int status = 0;
        while (::waitpid(p.pid, &status, 0) < 0 && errno == EINTR) {
        }
        p.pid = -1;
    }
}

} // namespace drt
