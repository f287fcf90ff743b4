// One image rendered by the processes (ranks) of an MPI job:
//     mpirun -np N drt render scene.drt -o out.exr
// Rank 0 holds the render's state (render/tile_state.h) and hands out tiles
// one at a time as ranks ask for them: a rank that finishes early asks again
// and takes more (no static split). Each rank renders its tiles on its own
// threads and sends the pixels back; under adaptive sampling a task carries
// its tile's pixel states there and back, and rank 0 alone decides the rounds.
// Every pixel is a function of (seed, pixel, sample index), so the image is the
// same bit for bit for any number of ranks, threads and tile size. Only rank 0
// writes files. docs/distributed.md has the protocol, the measured overhead
// and the scaling model.
#pragma once

#include "render/tile_state.h"

#include <cstdint>
#include <string>
#include <vector>

namespace drt {

// What the ranks did, for the summary and the scaling figures.
struct DistributedReport {
    int ranks = 1;
    std::vector<int> tilesPerRank;        // tasks each rank rendered
    uint64_t messages = 0;                // point-to-point messages, all ranks
    uint64_t bytes = 0;                   // their payload bytes
    std::vector<double> renderSecondsPerRank; // each rank's time from its first task to its last
};

class MpiJob {
public:
    // Whether this drt was built with MPI.
    static bool available();
    // Whether an MPI launcher (mpirun, mpiexec, srun) started this process,
    // from its environment; without one drt never initialises MPI.
    static bool launched();

    // MPI_Init_thread (only the main thread calls MPI). Throws RenderError.
    MpiJob();
    ~MpiJob(); // MPI_Finalize
    MpiJob(const MpiJob&) = delete;
    MpiJob& operator=(const MpiJob&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    // The worst (largest) of every rank's status. Collective.
    int agree(int status);
    // Rank 0's `value` on every rank. Collective.
    uint64_t broadcast(uint64_t value);
    std::string broadcast(const std::string& value);
    // Ends every rank of the job at once (MPI_Abort) with `status`.
    [[noreturn]] void abort(int status);

private:
    int rank_ = 0;
    int size_ = 1;
};

// Renders `state` over every rank of `job`. On rank 0, `rank0` is the
// scheduler of `state` (its cancel flag stops the whole job: the tasks in
// progress anywhere finish, then every rank stops); other ranks pass null and
// their `state` only holds the tiles they render. Returns this rank's
// TileRenderInfo; on rank 0 `report` (if given) gets every rank's figures.
// Throws RenderError; an error on one rank ends the job through abort().
TileRenderInfo renderDistributed(MpiJob& job, const Scene& scene, const RenderOptions& options, RenderState& state,
                                 LocalTileScheduler* rank0, DistributedReport* report = nullptr);

} // namespace drt
