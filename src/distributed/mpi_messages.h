// The messages of drt's MPI protocols (distributed/mpi_render.cpp: tiles of
// one image; distributed/frame_distribution.cpp: whole frames): non-blocking
// sends and the packing of plain values; messages are received with the MPI
// module's receive (distributed/mpi_module.h), polled. Only files built with
// MPI include this.
#pragma once

#include "core/error.h"
#include "distributed/mpi_module.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <list>
#include <thread>
#include <vector>

namespace drt::mpi_wire {

// Between polls, a rank's main thread sleeps instead of blocking in MPI:
// Open MPI's blocking calls spin a core, which the render threads need.
inline void pauseBriefly() {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
}

// What a rank sends, without blocking: a blocking send of a large message
// waits for the receiver to take it, and two ranks each sending to the other
// would wait for ever. Each message keeps its bytes until MPI is done with them.
class Outbox {
  public:
    ~Outbox() { flush(); }
    void send(std::vector<std::byte> bytes, int to, int tag) {
        ++messages;
        this->bytes += bytes.size();
        pending_.push_back({std::move(bytes), nullptr});
        Pending& p = pending_.back();
        p.request = mpiModule().send(p.bytes.data(), int(p.bytes.size()), to, tag);
        progress();
    }
    // Forgets the messages MPI has sent.
    void progress() {
        for (auto it = pending_.begin(); it != pending_.end();)
            it = mpiModule().sent(it->request) ? pending_.erase(it) : std::next(it);
    }
    // Waits until every message is sent.
    void flush() {
        while (progress(), !pending_.empty())
            pauseBriefly();
    }
    uint64_t messages = 0, bytes = 0;

  private:
    struct Pending {
        std::vector<std::byte> bytes;
        void* request; // the module's handle of the send
    };
    std::list<Pending> pending_; // a list: MPI holds pointers into the bytes
};

template <class T> inline void append(std::vector<std::byte>& out, const T& value) {
    const size_t at = out.size();
    out.resize(at + sizeof value);
    std::memcpy(out.data() + at, &value, sizeof value);
}

template <class T> inline T readAt(const std::vector<std::byte>& bytes, size_t offset) {
    if (offset + sizeof(T) > bytes.size())
        throw RenderError("malformed message between ranks");
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

} // namespace drt::mpi_wire
