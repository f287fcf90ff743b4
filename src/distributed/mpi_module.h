// The seam between drt and MPI: the few MPI calls of drt's distributed
// rendering (distributed/mpi_render.cpp, distributed/frame_distribution.cpp)
// live in the module libdrt_mpi.so (src/distributed/mpi/), which drt loads only
// when an MPI launcher started it (MpiJob). Open MPI and its libraries (8 of
// them) are then not linked into drt, whose every render searched them for each
// of the image module's ~170,000 symbols (about 11 ms of its fixed cost:
// docs/performance.md, "The fixed cost of a render").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace drt {

// Bumped whenever this table changes: a module from another build is refused.
inline constexpr int kMpiModuleVersion = 1;

// A message from any rank (receive's `source`).
inline constexpr int kAnyRank = -1;

struct MpiModule {
    int version;
    // MPI_Init_thread with MPI_THREAD_FUNNELED (only the main thread calls
    // MPI): "" and this rank and the job's size, or why not.
    std::string (*start)(int& rank, int& size);
    void (*finish)(); // MPI_Finalize
    // The largest of every rank's `value` (collective).
    int (*largest)(int value);
    // Rank 0's `bytes` bytes at `data` into every rank's (collective).
    void (*broadcast)(void* data, int bytes);
    // Ends every rank of the job (MPI_Abort).
    void (*abort)(int status);
    // Starts sending `bytes` bytes to rank `to` without blocking: the data must
    // stay until sent() says so. Returns the send's handle.
    void* (*send)(const void* data, int bytes, int to, int tag);
    // Whether the send is done; the handle is released once it is.
    bool (*sent)(void* handle);
    // The next message from `source` (kAnyRank: anyone), if one is waiting:
    // its bytes, sender and tag.
    bool (*receive)(int source, std::vector<std::byte>& bytes, int& from, int& tag);
};

// The loaded module (MpiJob loads it; throws RenderError if it cannot).
const MpiModule& mpiModule();

inline constexpr const char* kMpiModuleFile = "libdrt_mpi.so";
inline constexpr const char* kMpiModuleSymbol = "drt_mpi_module";

} // namespace drt
