// The frames of an animation over the processes (ranks) of an MPI job, whole
// frames per rank:
//     mpirun -np N drt render scene.drt --frames 1..240 -o frames/f_%04d.png
// Rank 0 hands out the next frame to whichever rank asks for one: a rank that
// finishes early takes the next frame (no static split). Each rank renders its
// frame alone on its own threads and writes that frame's files itself, so a
// frame is the one a single process makes, bit for bit. Rank 0 renders frames
// too, on a thread beside its main thread, which serves the other ranks.
// docs/distributed.md says when frames go whole to ranks and when each frame is
// split into tiles over every rank (distributed/mpi_render.h) instead.
#pragma once

#include "distributed/mpi_render.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace drt {

// What rendering one frame gave: its exit status (0: its files are written)
// and everything it printed.
struct FrameOutcome {
    int status = 0;
    std::string messages;
};

// What the ranks did, for the summary and the figures in docs/distributed.md.
struct FrameDistributionReport {
    int ranks = 1;
    std::vector<int> framesPerRank;
    uint64_t messages = 0; // point-to-point messages, both ways
    uint64_t bytes = 0;    // their payload bytes
};

// Whether `frames` frames go to `ranks` ranks whole (one rank renders a frame
// on its threads) rather than one after another, each split into tiles over
// every rank: whole when every rank gets at least one frame. Fewer frames than
// ranks would leave ranks idle, so then each frame is split.
bool wholeFramesPerRank(int frames, int ranks);

// Renders frames 0 .. count-1 (the caller's indices) over every rank of `job`.
// `render(i)` renders frame i in this process and writes its files; an
// exception it throws counts as a failed frame (status 1). On rank 0,
// `finished(i, rank, outcome)` is called on the main thread for each frame as it
// finishes. After a frame fails (non-zero status), or once `stop` (rank 0's,
// may be null) is set, no frame is started; the frames in progress finish.
// Returns on every rank the status of the first frame that failed (in the order
// they finished), else `stoppedStatus()` if `stop` left frames unstarted, else 0.
// Collective; throws RenderError without MPI.
int renderFramesDistributed(MpiJob& job, int count, const std::function<FrameOutcome(int index)>& render,
                            const std::function<void(int index, int rank, const FrameOutcome&)>& finished,
                            const std::atomic<bool>* stop, const std::function<int()>& stoppedStatus,
                            FrameDistributionReport* report = nullptr);

} // namespace drt
