// The MPI job and the distributed tile loop (distributed/mpi_render.h).
//
// Protocol (point-to-point, MPI_BYTE messages; only each rank's main thread
// calls MPI, its render threads run beside it):
//   worker -> 0  kRequest  int n: "send me n more tasks"
//   0 -> worker  kTask     TileTask, then (adaptive, after the first round) the tile's packed pixel states
//   worker -> 0  kResult   TileTask + TileCounts, then the tile's packed pixels
//   0 -> worker  kStop     no more tasks: the render is finished or cancelled
// A worker keeps as many tasks asked for or queued as it has threads, so its
// threads rarely wait for the network and a rank holds at most one task per
// thread beyond those it renders (the imbalance at the end). Rank 0's own
// threads take tasks from the same pool directly. Requests that arrive at an
// adaptive round's barrier wait in rank 0 until the round is decided.
// The main threads poll (MPI_Iprobe) and sleep between polls instead of
// blocking in MPI: Open MPI's blocking calls spin a core, which the render
// threads need.
#include "distributed/mpi_render.h"

#include <cstdlib>
#include <deque>
#include <exception>
#include <thread>

#ifdef DRT_HAVE_MPI
#include "core/modules.h"
#include "distributed/mpi_messages.h"
#endif

namespace drt {

bool MpiJob::launched() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
        if (std::getenv(variable)) return true;
    return false;
}

#ifndef DRT_HAVE_MPI

bool MpiJob::available() { return false; }
MpiJob::MpiJob() { throw RenderError("this drt was built without MPI (install libopenmpi-dev and rebuild)"); }
MpiJob::~MpiJob() = default;
int MpiJob::agree(int status) { return status; }
uint64_t MpiJob::broadcast(uint64_t value) { return value; }
std::string MpiJob::broadcast(const std::string& value) { return value; }
void MpiJob::abort(int status) { std::_Exit(status); }
TileRenderInfo renderDistributed(MpiJob&, const Scene&, const RenderOptions&, RenderState&, LocalTileScheduler*,
                                 DistributedReport*) {
    throw RenderError("this drt was built without MPI");
}

#else

bool MpiJob::available() { return true; }

namespace {

// The build tree's path comes from CMake (DRT_MPI_MODULE_BUILD_PATH).
constexpr ModuleSpec kMpiSpec{kMpiModuleFile, kMpiModuleSymbol, "DRT_MPI_MODULE", DRT_MPI_MODULE_BUILD_PATH,
                              "drt's MPI module"};

} // namespace

const MpiModule& mpiModule() {
    const LoadedModule<MpiModule>& loaded = moduleOnce<MpiModule>(kMpiSpec, kMpiModuleVersion);
    if (!loaded.table) throw RenderError(loaded.error);
    return *loaded.table;
}

MpiJob::MpiJob() {
    if (std::string problem = mpiModule().start(rank_, size_); !problem.empty()) throw RenderError(problem);
}

MpiJob::~MpiJob() { mpiModule().finish(); }

int MpiJob::agree(int status) { return mpiModule().largest(status); }

uint64_t MpiJob::broadcast(uint64_t value) {
    uint64_t v = value;
    mpiModule().broadcast(&v, int(sizeof v));
    return v;
}

std::string MpiJob::broadcast(const std::string& value) {
    std::string text = value;
    text.resize(broadcast(uint64_t(value.size())));
    mpiModule().broadcast(text.data(), int(text.size()));
    return text;
}

void MpiJob::abort(int status) {
    mpiModule().abort(status);
    std::_Exit(status);
}

namespace {

using namespace mpi_wire;

enum Tag { kRequest = 1, kTask = 2, kResult = 3, kStop = 4, kReport = 5 };

// Forwards to another scheduler, counting the tasks and the time spent on them.
class CountingScheduler : public TileScheduler {
public:
    explicit CountingScheduler(TileScheduler& inner) : inner_(inner) {}
    std::optional<TileTask> next() override { return inner_.next(); }
    void done(TileResult&& result) override {
        tasks_.fetch_add(1);
        inner_.done(std::move(result));
    }
    int tasks() const { return tasks_.load(); }

private:
    TileScheduler& inner_;
    std::atomic<int> tasks_{0};
};

// A worker rank's tasks: queued by the main thread as they arrive, results
// handed back to it.
class WorkerScheduler : public TileScheduler {
public:
    explicit WorkerScheduler(RenderState& state) : state_(state) {}

    std::optional<TileTask> next() override {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || stopped_; });
        if (queue_.empty()) return std::nullopt;
        const TileTask task = queue_.front();
        queue_.pop_front();
        ++rendering_;
        return task;
    }

    void done(TileResult&& result) override {
        std::lock_guard lock(mutex_);
        std::vector<std::byte> message;
        append(message, result.task);
        append(message, result.counts);
        state_.store(result);
        state_.packTile(result.task.tile, message);
        outbox_.push_back(std::move(message));
        --rendering_;
        ++tasks_;
    }

    // Main thread: a task (its tile's pixel states already in the state).
    void push(const TileTask& task) {
        {
            std::lock_guard lock(mutex_);
            queue_.push_back(task);
        }
        changed_.notify_all();
    }
    // Main thread: no more tasks; the queued ones are dropped (the render was cancelled).
    void stop() {
        {
            std::lock_guard lock(mutex_);
            stopped_ = true;
            queue_.clear();
        }
        changed_.notify_all();
    }
    std::vector<std::vector<std::byte>> takeResults() {
        std::lock_guard lock(mutex_);
        std::vector<std::vector<std::byte>> results;
        results.swap(outbox_);
        return results;
    }
    int held() {
        std::lock_guard lock(mutex_);
        return int(queue_.size()) + rendering_;
    }
    int tasks() {
        std::lock_guard lock(mutex_);
        return tasks_;
    }
    // Unpacks a task's incoming pixel states into the state (no thread renders that tile now).
    void unpack(int tile, const std::byte* data, size_t size) {
        std::lock_guard lock(mutex_);
        state_.unpackTile(tile, data, size);
    }

private:
    RenderState& state_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<TileTask> queue_;
    std::vector<std::vector<std::byte>> outbox_;
    int rendering_ = 0;
    int tasks_ = 0;
    bool stopped_ = false;
};

// Runs renderTiles on a thread beside the main thread; rethrows its error.
class RenderThread {
public:
    RenderThread(const Scene& scene, const RenderOptions& options, RenderState& state, TileScheduler& scheduler)
        : thread_([&, this] {
              try {
                  info_ = renderTiles(scene, options, state, scheduler);
              } catch (...) {
                  error_ = std::current_exception();
              }
              finished_.store(true);
          }) {}
    ~RenderThread() {
        if (thread_.joinable()) thread_.join();
    }
    bool finished() const { return finished_.load(); }
    std::exception_ptr error() const { return finished() ? error_ : nullptr; }
    TileRenderInfo join() {
        thread_.join();
        if (error_) std::rethrow_exception(error_);
        return info_;
    }

private:
    TileRenderInfo info_;
    std::exception_ptr error_;
    std::atomic<bool> finished_{false};
    std::thread thread_;
};

int threadCount(const RenderOptions& options) {
    return options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

// Rank 0's figures and those the workers send at the end.
struct RankFigures {
    int tasks = 0;
    uint64_t messages = 0, bytes = 0;
    double renderSeconds = 0;
};

// An error on this rank ends the job: every rank stops (Open MPI's mpirun
// then reports which rank aborted, and exits non-zero).
[[noreturn]] void abortOn(MpiJob& job, const std::exception& e) {
    std::fprintf(stderr, "drt (rank %d of %d): render failed: %s\n", job.rank(), job.size(), e.what());
    std::fflush(stderr);
    job.abort(1);
}

// Ends the job if this rank's render thread failed.
void abortIfFailed(MpiJob& job, const RenderThread& thread) {
    if (std::exception_ptr error = thread.error()) {
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            abortOn(job, e);
        }
    }
}

TileRenderInfo renderAsRank0(MpiJob& job, const Scene& scene, const RenderOptions& options, RenderState& state,
                             LocalTileScheduler& pool, DistributedReport* report) {
    CountingScheduler local(pool);
    RenderThread thread(scene, options, state, local);
    Outbox traffic;
    std::vector<int> wanted(size_t(job.size()), 0); // tasks each rank asked for and has not had
    std::vector<std::byte> message;
    int from = 0, tag = 0;
    const auto serve = [&] {
        for (int rank = 1; rank < job.size(); ++rank)
            while (wanted[size_t(rank)] > 0) {
                const std::optional<TileTask> task = pool.tryNext();
                if (!task) return;
                std::vector<std::byte> payload;
                append(payload, *task);
                // A tile's states before the first round are the initial ones, which the rank has.
                if (state.adaptive() && task->round > 0)
                    pool.withState([&](const RenderState& s) { s.packTile(task->tile, payload); });
                traffic.send(std::move(payload), rank, kTask);
                --wanted[size_t(rank)];
            }
    };
    while (true) {
        abortIfFailed(job, thread);
        traffic.progress();
        bool busy = false;
        while (mpiModule().receive(kAnyRank, message, from, tag)) {
            busy = true;
            if (tag == kRequest) {
                wanted[size_t(from)] += readAt<int>(message, 0);
            } else if (tag == kResult) {
                const auto task = readAt<TileTask>(message, 0);
                const auto counts = readAt<TileCounts>(message, sizeof(TileTask));
                const size_t offset = sizeof(TileTask) + sizeof(TileCounts);
                try {
                    pool.donePacked(task, counts, message.data() + offset, message.size() - offset);
                } catch (const RenderError& e) {
                    abortOn(job, e);
                }
            }
        }
        serve();
        if (pool.over()) break;
        if (!busy) pauseBriefly();
    }
    pool.wake();
    for (int rank = 1; rank < job.size(); ++rank) traffic.send({}, rank, kStop);
    const TileRenderInfo info = thread.join();

    // The workers' figures (they send them after kStop): tasks, messages, bytes, busy seconds.
    RankFigures mine{local.tasks(), traffic.messages, traffic.bytes, info.renderSeconds};
    if (report) {
        report->ranks = job.size();
        report->tilesPerRank.assign(size_t(job.size()), 0);
        report->renderSecondsPerRank.assign(size_t(job.size()), 0);
        report->tilesPerRank[0] = mine.tasks;
        report->renderSecondsPerRank[0] = mine.renderSeconds;
        report->messages = mine.messages;
        report->bytes = mine.bytes;
    }
    int reported = 1;
    while (reported < job.size()) {
        traffic.progress();
        if (!mpiModule().receive(kAnyRank, message, from, tag)) {
            pauseBriefly();
            continue;
        }
        if (tag != kReport) continue; // a request or result that crossed kStop
        const auto figures = readAt<RankFigures>(message, 0);
        ++reported;
        if (!report) continue;
        report->tilesPerRank[size_t(from)] = figures.tasks;
        report->renderSecondsPerRank[size_t(from)] = figures.renderSeconds;
        report->messages += figures.messages;
        report->bytes += figures.bytes;
    }
    return info;
}

TileRenderInfo renderAsWorker(MpiJob& job, const Scene& scene, const RenderOptions& options, RenderState& state) {
    WorkerScheduler scheduler(state);
    RenderThread thread(scene, options, state, scheduler);
    Outbox traffic;
    const int target = threadCount(options) + 1; // one task queued per rank beyond those rendering
    int asked = 0; // tasks asked for and not yet received
    bool stopped = false;
    std::vector<std::byte> message;
    int from = 0, tag = 0;
    while (!stopped) {
        abortIfFailed(job, thread);
        traffic.progress();
        bool busy = false;
        for (std::vector<std::byte>& result : scheduler.takeResults()) {
            traffic.send(std::move(result), 0, kResult);
            busy = true;
        }
        if (const int want = target - asked - scheduler.held(); want > 0) {
            std::vector<std::byte> request;
            append(request, want);
            traffic.send(std::move(request), 0, kRequest);
            asked += want;
        }
        while (!stopped && mpiModule().receive(0, message, from, tag)) {
            busy = true;
            if (tag == kStop) {
                stopped = true;
            } else if (tag == kTask) {
                const auto task = readAt<TileTask>(message, 0);
                try {
                    if (state.adaptive() && message.size() > sizeof task)
                        scheduler.unpack(task.tile, message.data() + sizeof task, message.size() - sizeof task);
                } catch (const RenderError& e) {
                    abortOn(job, e);
                }
                --asked;
                scheduler.push(task);
            }
        }
        if (!busy) pauseBriefly();
    }
    scheduler.stop();
    const TileRenderInfo info = thread.join();
    // Results finished after kStop are not needed: the render is over.
    const RankFigures figures{scheduler.tasks(), traffic.messages, traffic.bytes, info.renderSeconds};
    std::vector<std::byte> report;
    append(report, figures);
    traffic.send(std::move(report), 0, kReport);
    traffic.flush();
    return info;
}

} // namespace

TileRenderInfo renderDistributed(MpiJob& job, const Scene& scene, const RenderOptions& options, RenderState& state,
                                 LocalTileScheduler* rank0, DistributedReport* report) {
    if (job.rank() == 0) {
        if (!rank0) throw RenderError("rank 0 needs the render's scheduler");
        return renderAsRank0(job, scene, options, state, *rank0, report);
    }
    return renderAsWorker(job, scene, options, state);
}

#endif

} // namespace drt
