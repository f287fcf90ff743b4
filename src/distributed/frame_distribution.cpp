// Whole frames over the ranks of an MPI job (distributed/frame_distribution.h).
//
// Protocol (point-to-point, MPI_BYTE messages; only each rank's main thread
// calls MPI):
//   worker -> 0  kAsk    int frame, int status, then the frame's messages:
//                        "here is frame `frame` (-1: none yet), send me another"
//   0 -> worker  kFrame  int frame: render it
//   0 -> worker  kDone   int status: no more frames; the job's status
// A worker asks for the next frame when it has finished one: a frame takes
// seconds to hours, so the round trip between frames does not matter, and
// holding no frame in reserve keeps the last frames for whichever rank is idle.
// Rank 0 answers the last asks only when every frame is finished, so that
// kDone carries the job's status and every rank exits with it.
#include "distributed/frame_distribution.h"

#include <algorithm>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#ifdef DRT_HAVE_MPI
#include "distributed/mpi_messages.h"
#endif

namespace drt {

bool wholeFramesPerRank(int frames, int ranks) {
    return frames >= ranks;
}

#ifndef DRT_HAVE_MPI

int renderFramesDistributed(MpiJob&, int, const std::function<FrameOutcome(int)>&,
                            const std::function<void(int, int, const FrameOutcome&)>&,
                            const std::atomic<bool>*, const std::function<int()>&,
                            FrameDistributionReport*) {
    throw RenderError("this drt was built without MPI");
}

#else

namespace {

using namespace mpi_wire;

enum Tag { kAsk = 11, kFrame = 12, kDone = 13 };

FrameOutcome renderSafely(const std::function<FrameOutcome(int)>& render, int index) {
    try {
        return render(index);
    } catch (const std::exception& e) {
        return {1, std::string("drt: render failed: ") + e.what() + "\n"};
    }
}

// The frames not yet started, taken by rank 0's render thread and handed out
// by its main thread; closed after a failure or an interruption.
class FramePool {
  public:
    explicit FramePool(int count) : count_(count) {}
    std::optional<int> take() {
        std::lock_guard lock(mutex_);
        if (closed_ || next_ >= count_)
            return std::nullopt;
        return next_++;
    }
    void close() {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    bool allTaken() {
        std::lock_guard lock(mutex_);
        return next_ >= count_;
    }

  private:
    std::mutex mutex_;
    int next_ = 0;
    int count_;
    bool closed_ = false;
};

// Rank 0's own frames: rendered on a thread, their outcomes collected for the main thread.
class OwnFrames {
  public:
    OwnFrames(FramePool& pool, const std::function<FrameOutcome(int)>& render)
        : thread_([this, &pool, &render] {
              while (const std::optional<int> index = pool.take()) {
                  FrameOutcome outcome = renderSafely(render, *index);
                  if (outcome.status != 0)
                      pool.close(); // before this thread could take another
                  std::lock_guard lock(mutex_);
                  finished_.emplace_back(*index, std::move(outcome));
              }
              std::lock_guard lock(mutex_);
              over_ = true;
          }) {}
    ~OwnFrames() {
        if (thread_.joinable())
            thread_.join();
    }
    // The frames finished since the last call; `over` once no more will come.
    std::deque<std::pair<int, FrameOutcome>> take(bool& over) {
        std::lock_guard lock(mutex_);
        over = over_;
        return std::exchange(finished_, {});
    }

  private:
    std::mutex mutex_;
    std::deque<std::pair<int, FrameOutcome>> finished_;
    bool over_ = false;
    std::thread thread_; // last: starts when the rest is ready
};

std::vector<std::byte> intMessage(int value) {
    std::vector<std::byte> bytes;
    append(bytes, value);
    return bytes;
}

int coordinate(MpiJob& job, int count, const std::function<FrameOutcome(int)>& render,
               const std::function<void(int, int, const FrameOutcome&)>& finished,
               const std::atomic<bool>* stop, const std::function<int()>& stoppedStatus,
               FrameDistributionReport* report) {
    const size_t ranks = size_t(job.size());
    FramePool pool(count);
    std::vector<int> framesPerRank(ranks, 0);
    int failure = 0;
    const auto record = [&](int index, int rank, const FrameOutcome& outcome) {
        ++framesPerRank[size_t(rank)];
        if (outcome.status != 0 && failure == 0) {
            failure = outcome.status;
            pool.close();
        }
        finished(index, rank, outcome);
    };
    Outbox traffic;
    uint64_t receivedMessages = 0, receivedBytes = 0;
    std::vector<bool> asking(ranks, false); // a worker that waits for its next frame
    int elsewhere = 0;                      // frames the workers are rendering
    bool ownOver = false;
    {
        OwnFrames own(pool, render);
        std::vector<std::byte> message;
        int from = 0, tag = 0;
        while (true) {
            if (stop && stop->load())
                pool.close();
            traffic.progress();
            bool busy = false;
            for (auto& [index, outcome] : own.take(ownOver))
                record(index, 0, outcome), busy = true;
            while (mpiModule().receive(kAnyRank, message, from, tag)) {
                busy = true;
                ++receivedMessages;
                receivedBytes += message.size();
                if (tag != kAsk)
                    throw RenderError("unexpected message between ranks");
                const int index = readAt<int>(message, 0);
                if (index >= 0) {
                    FrameOutcome outcome{readAt<int>(message, sizeof(int)), ""};
                    outcome.messages.assign(reinterpret_cast<const char*>(message.data()) + 2 * sizeof(int),
                                            message.size() - 2 * sizeof(int));
                    --elsewhere;
                    record(index, from, outcome);
                }
                asking[size_t(from)] = true;
            }
            for (size_t rank = 1; rank < ranks; ++rank)
                if (asking[rank])
                    if (const std::optional<int> index = pool.take()) {
                        traffic.send(intMessage(*index), int(rank), kFrame);
                        asking[rank] = false;
                        ++elsewhere;
                    }
            const bool everyWorkerAsks =
                std::count(asking.begin() + 1, asking.end(), true) == long(ranks) - 1;
            if (ownOver && elsewhere == 0 && everyWorkerAsks)
                break;
            if (!busy)
                pauseBriefly();
        }
    }
    // Stopped before every frame was started: the job did not do what it was
    // asked, even when every frame it started was written.
    if (failure == 0 && stop && stop->load() && !pool.allTaken())
        failure = stoppedStatus();
    for (size_t rank = 1; rank < ranks; ++rank)
        traffic.send(intMessage(failure), int(rank), kDone);
    traffic.flush();
    if (report) {
        report->ranks = job.size();
        report->framesPerRank = framesPerRank;
        report->messages = traffic.messages + receivedMessages;
        report->bytes = traffic.bytes + receivedBytes;
    }
    return failure;
}

// A worker's frame, rendered on a thread while the main thread waits (and
// keeps MPI's sends going), as rank 0 and the tile path render too. Rendered on
// the main thread itself, a worker's frames took 2 to 4 times longer on the
// development machine (6 frames on 2 ranks: rank 0 rendered 5 of them, the job
// took 1.35x as long).
FrameOutcome renderBeside(Outbox& traffic, const std::function<FrameOutcome(int)>& render, int index) {
    std::atomic<bool> done{false};
    FrameOutcome outcome;
    std::thread thread([&] {
        outcome = renderSafely(render, index);
        done.store(true);
    });
    while (!done.load()) {
        traffic.progress();
        pauseBriefly();
    }
    thread.join();
    return outcome;
}

int work(const std::function<FrameOutcome(int)>& render) {
    Outbox traffic;
    int index = -1;
    FrameOutcome outcome;
    std::vector<std::byte> message;
    int from = 0, tag = 0;
    while (true) {
        std::vector<std::byte> ask;
        append(ask, index);
        append(ask, outcome.status);
        for (char c : outcome.messages)
            ask.push_back(std::byte(c));
        traffic.send(std::move(ask), 0, kAsk);
        while (!mpiModule().receive(0, message, from, tag)) {
            traffic.progress();
            pauseBriefly();
        }
        if (tag == kDone) {
            traffic.flush();
            return readAt<int>(message, 0);
        }
        if (tag != kFrame)
            throw RenderError("unexpected message between ranks");
        index = readAt<int>(message, 0);
        outcome = renderBeside(traffic, render, index);
    }
}

} // namespace

int renderFramesDistributed(MpiJob& job, int count, const std::function<FrameOutcome(int)>& render,
                            const std::function<void(int, int, const FrameOutcome&)>& finished,
                            const std::atomic<bool>* stop, const std::function<int()>& stoppedStatus,
                            FrameDistributionReport* report) {
    if (job.rank() == 0)
        return coordinate(job, count, render, finished, stop, stoppedStatus, report);
    return work(render);
}

#endif

} // namespace drt
