#include "core/temporary_files.h"

#include <array>
#include <atomic>
#include <cstring>
#include <unistd.h>

namespace drt {

namespace {

// A fixed table, so the signal handler needs no allocation or lock: a slot is
// free (0), being filled or emptied (1), or holds a path (2).
constexpr int kSlots = 32;
constexpr size_t kPathBytes = 4096;
struct Slot {
    std::atomic<int> state{0};
    char path[kPathBytes];
};
std::array<Slot, kSlots> slots;

} // namespace

TemporaryFile::TemporaryFile(const std::string& path) {
    if (path.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (!slots[size_t(i)].state.compare_exchange_strong(expected, 1)) continue;
        std::memcpy(slots[size_t(i)].path, path.c_str(), path.size() + 1);
        slots[size_t(i)].state.store(2);
        slot_ = i;
        return;
    }
}

TemporaryFile::~TemporaryFile() {
    if (slot_ >= 0) slots[size_t(slot_)].state.store(0);
}

void removeTemporaryFiles() noexcept {
    for (Slot& slot : slots)
        if (slot.state.load() == 2) ::unlink(slot.path);
}

} // namespace drt
