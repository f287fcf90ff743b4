#include "core/temporary_files.h"

#include <atomic>
#include <csignal>
#include <cstring>
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

void onTerminatingSignal(int signal) {
    removeRegisteredTemporaryFiles();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

TemporaryFile::TemporaryFile(std::string path) : path_(std::move(path)) {
    if (path_.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slotStates[i].compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slotPaths[i], path_.c_str(), path_.size() + 1);
        slotStates[i].store(kRegistered);
        slot_ = i;
        return;
    }
}

TemporaryFile::~TemporaryFile() {
    if (slot_ >= 0) slotStates[slot_].store(kFree);
}

void removeRegisteredTemporaryFiles() noexcept {
    for (int i = 0; i < kSlots; ++i)
        if (slotStates[i].load() == kRegistered) ::unlink(slotPaths[i]);
}

void removeTemporaryFilesOnSignal() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true)) return;
    struct sigaction action {};
    action.sa_handler = onTerminatingSignal;
    sigemptyset(&action.sa_mask);
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

} // namespace drt
