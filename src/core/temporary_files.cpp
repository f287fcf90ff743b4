#include "core/temporary_files.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <ctime>
#include <sys/syscall.h>
#include <unistd.h>

namespace drt {

namespace {

constexpr int kSlots = 64;
constexpr size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kRegistered = 2 };
// Fixed storage: the signal handler may read it at any moment, so nothing here
// allocates or locks.
char slotPaths[kSlots][kPathBytes];
std::atomic<int> slotStates[kSlots];
std::atomic<long> slotOwners[kSlots]; // the thread writing the file (its kernel thread id)
std::atomic<bool> removing{false};     // a signal handler is removing the files: the process is ending

long currentThread() noexcept { return ::syscall(SYS_gettid); } // async-signal-safe

bool writtenByAnotherThread(long self) noexcept {
    for (int i = 0; i < kSlots; ++i)
        if (slotStates[i].load() == kRegistered && slotOwners[i].load() != self) return true;
    return false;
}

void onTerminatingSignal(int signal) {
    makeNoMoreTemporaryFiles();
    removeRegisteredTemporaryFiles();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

TemporaryFile::TemporaryFile(std::string path) : path_(std::move(path)) {
    // The process is ending: a file made now could outlive the handler's
    // removal, so this thread makes none and waits for the end.
    while (removing.load()) {
        const timespec second{1, 0};
        ::nanosleep(&second, nullptr);
    }
    if (path_.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slotStates[i].compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slotPaths[i], path_.c_str(), path_.size() + 1);
        slotOwners[i].store(currentThread());
        slotStates[i].store(kRegistered);
        slot_ = i;
        return;
    }
}

TemporaryFile::~TemporaryFile() {
    if (slot_ >= 0) slotStates[slot_].store(kFree);
}

void removeRegisteredTemporaryFiles() noexcept {
    auto unlinkAll = [] {
        for (int i = 0; i < kSlots; ++i)
            if (slotStates[i].load() == kRegistered) ::unlink(slotPaths[i]);
    };
    unlinkAll();
    // A writer on another thread goes on while this handler runs: it may be
    // about to create its file (after the unlink above) or to rename it into
    // place. Either way it unregisters within one write, so wait for that (a
    // bounded time: it may wait for a lock this thread holds), then unlink
    // whatever is still registered. A writer interrupted on this thread cannot
    // move, so its file, if it exists, is already gone.
    const long self = currentThread();
    for (int waited = 0; waited < 200 && writtenByAnotherThread(self); ++waited) {
        const timespec tenMilliseconds{0, 10'000'000};
        ::nanosleep(&tenMilliseconds, nullptr);
    }
    unlinkAll();
}

void makeNoMoreTemporaryFiles() noexcept { removing.store(true); }

void removeTemporaryFilesOnSignal() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true)) return;
    struct sigaction action {};
    action.sa_handler = onTerminatingSignal;
    sigemptyset(&action.sa_mask);
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

} // namespace drt
