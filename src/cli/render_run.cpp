// `drt render`'s render: in this process, or over the ranks of an MPI job
// (distributed/mpi_render.h); from the start or from a checkpoint (--resume);
// with periodic checkpoints (--checkpoint-every) and, on SIGINT or SIGTERM,
// the finished tiles and a checkpoint saved before exiting 128 + signal. An
// animation's frames are rendered one after another, or under MPI, when there
// are enough of them, whole frames per rank (distributed/frame_distribution.h).
//
// Under MPI every rank parses the scene itself (from the same files, which a
// cluster shares): a scene model holds meshes, images and closures that have no
// wire format, and parsing is deterministic. The ranks then check that they
// parsed the same scene (its hash) and agree on the outcome, so an error on one
// rank stops all of them with its message instead of leaving the others waiting.
#include "accel/accel.h"
#include "cli/commands.h"

#include "cli/interrupt.h"
#include "cli/paths.h"
#include "cli/progress.h"
#include "cli/render_parts.h"
#include "distributed/checkpoint.h"
#include "distributed/crop_merge.h"
#include "distributed/frame_distribution.h"
#include "distributed/mpi_render.h"
#include "sampling/filter.h"
#include "image/image.h"
#include "image/image_process.h"

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fmt/format.h>
#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace drt::cli {

namespace {

// Everything a rank knows before it renders.
struct Prepared {
    std::optional<Scene> scene;
    RenderOptions options;
    RenderIdentity identity;
    RunRecord record; // for the files' metadata
    std::optional<Checkpoint> checkpoint; // --resume, rank 0
    bool alreadyWritten = false;          // --resume, rank 0: a frame finished by an earlier run
    double loadSeconds = 0;               // parsing and the files the scene names (--stats)
};

// The frame's clock, in the render's identity when it is not a still image's
// (a checkpoint or crop made at another clock is another image).
std::string frameSettings(const RenderCommand& command) {
    const FrameClock frame = stillFrameClock(command);
    std::string settings;
    if (frame.clockOn || frame.clock != 0 || frame.clockDelta != 1)
        settings = fmt::format(" frame={} clock={:.17g} clock_delta={:.17g}", frame.frameNumber, frame.clock,
                               frame.clockDelta);
    if (command.animation.shutter) settings += fmt::format(" shutter={:.17g}", *command.animation.shutter);
    return settings;
}

// Whether `output` is the whole image of this render (its identity, no crop
// or the same one, not a partial image), written by an earlier run.
bool writtenBefore(const std::string& output, const RenderIdentity& identity, const RenderOptions& options) {
    std::error_code ec;
    if (!fs::is_regular_file(output, ec)) return false;
    Image image;
    Metadata metadata;
    if (!readImage(output, image, &metadata).empty()) return false;
    if (metadataValue(metadata, "drt:partial") || readIdentity(metadata) != identity) return false;
    const std::optional<std::string> crop = metadataValue(metadata, "drt:crop");
    return options.crop ? crop == formatWindow(*options.crop) : !crop;
}

int prepare(const RenderCommand& command, bool writes, std::ostream& err, Prepared& p) {
    // Refused before anything is read: an output that would replace the scene
    // or another output, whatever the spelling.
    if (std::string clash = outputClash({{"the scene", command.scene}}, {{"-o", command.output},
                                                                        {"--variance", command.varianceOutput},
                                                                        {"--spp-image", command.sppImageOutput}});
        !clash.empty()) {
        err << "drt render: " << clash << "\n";
        return kUsageError;
    }
    p.record.started = std::time(nullptr);
    const auto loadStart = std::chrono::steady_clock::now();
    FrameReport report; // the scene at its frame's clock, moving over the shutter
    if (int status = loadScene(command.scene, err, p.scene, command.pov, command.overrides, &p.record.sceneSha1,
                               stillFrameClock(command), frameOptions(command), &report);
        status != kSuccess)
        return status;
    p.loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
    printFrameReport(command, report, err);
    p.record.filter = p.scene->render.filter.value_or(defaultFilterName());
    p.options = resolveRenderOptions(overlaySettings(p.scene->render, command.overrides));
    if (command.tileSize) p.options.tileSize = *command.tileSize;
    // Sizes and thread counts past the limits are refused before the render
    // allocates anything: a usage error when the command line asked for them.
    if (std::string problem = renderLimitProblem(p.options); !problem.empty()) {
        const bool fromCommandLine = command.overrides.width || command.overrides.height || command.overrides.threads;
        err << fmt::format("drt: {}: {}\n", fromCommandLine ? "render" : command.scene, problem);
        return fromCommandLine ? kUsageError : kSceneError;
    }
    if (!command.crop.empty()) {
        PixelWindow window;
        if (std::string problem = parseCropWindow(command.crop, p.options.width, p.options.height, window);
            !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kUsageError;
        }
        p.options.crop = window;
    }
    p.identity = renderIdentity(p.options, p.record.sceneSha1);
    p.identity.settings += frameSettings(command);
    if (!writes) return kSuccess;
    // Every output is checked before the (possibly long) render starts.
    if (int status = checkOutputs(command, err); status != kSuccess) return status;
    if (!command.resume) return kSuccess;
    const std::string path = checkpointPathFor(command.output);
    std::error_code ec;
    if (command.animation.frame && !fs::exists(path, ec)) {
        // A frame of an animation without a checkpoint: kept if an earlier run
        // wrote it whole, else rendered from the start.
        p.alreadyWritten = writtenBefore(command.output, p.identity, p.options);
        return kSuccess;
    }
    Checkpoint checkpoint;
    if (std::string problem = readCheckpoint(path, checkpoint); !problem.empty()) {
        err << "drt: cannot resume: " << problem << "\n";
        return kIoError;
    }
    if (std::string problem = checkpointMismatch(checkpoint, path, p.identity, p.options); !problem.empty()) {
        err << "drt: cannot resume: " << problem << "\n";
        return kUsageError;
    }
    if (command.tileSize && *command.tileSize != checkpoint.tileSize)
        err << fmt::format("drt: resuming with the checkpoint's tile size {} (the image does not depend on it)\n",
                           checkpoint.tileSize);
    p.options.tileSize = checkpoint.tileSize;
    p.checkpoint = std::move(checkpoint);
    return kSuccess;
}

// Saves the checkpoint and the image so far every `seconds` (0: never), and at
// once when the render is interrupted: an MPI launcher that passes on a Ctrl-C
// kills its processes a moment after (Open MPI: one second), before the tiles
// in progress could finish. The render then saves again when they have.
class ProgressSaver {
public:
    ProgressSaver(double seconds, const std::atomic<bool>* interrupted, std::function<void()> save)
        : seconds_(seconds), interrupted_(interrupted), save_(std::move(save)),
          thread_([this] { run(); }) {}
    ~ProgressSaver() { stop(); }
    void stop() {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        if (thread_.joinable()) thread_.join();
    }

private:
    void run() {
        using Clock = std::chrono::steady_clock;
        const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds_));
        auto due = Clock::now() + period;
        bool savedInterrupted = false;
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(20), [&] { return stopping_; })) {
            const bool interrupted = interrupted_->load() && !savedInterrupted;
            const bool periodic = seconds_ > 0 && Clock::now() >= due;
            if (!interrupted && !periodic) continue;
            savedInterrupted = savedInterrupted || interrupted;
            due = Clock::now() + period;
            lock.unlock();
            save_();
            lock.lock();
        }
    }
    double seconds_;
    const std::atomic<bool>* interrupted_;
    std::function<void()> save_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    std::thread thread_; // last: starts when the rest is ready
};

// Formats that hold an alpha channel get one (0: not rendered yet); the others
// show unfinished pixels black.
bool keepsAlpha(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext != ".jpg" && ext != ".jpeg" && ext != ".hdr" && ext != ".ppm" && ext != ".pnm";
}

std::string progressText(const RenderState& state) {
    if (state.adaptive())
        return fmt::format("adaptive round {} of at most {}: {} of {} tiles done", state.round() + 1,
                           state.roundCount(), state.tilesDoneThisRound(), state.tileCount());
    return fmt::format("{} of {} tiles done", state.tilesDoneThisRound(), state.tileCount());
}

// The checkpoint, then the image so far: both complete files, or the old ones.
std::string saveProgress(const RenderCommand& command, const Prepared& p, const Checkpoint& checkpoint,
                         Image partial, const std::string& progress) {
    const std::string checkpointPath = checkpointPathFor(command.output);
    if (std::string problem = writeCheckpoint(checkpointPath, checkpoint); !problem.empty()) return problem;
    if (!keepsAlpha(command.output)) {
        Image rgb(partial.width, partial.height, 3);
        for (int y = 0; y < partial.height; ++y)
            for (int x = 0; x < partial.width; ++x)
                for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = partial.at(x, y, c);
        partial = std::move(rgb);
    }
    Metadata metadata = renderMetadata(command, p.options, p.identity, p.record, RenderStats{}, 0);
    metadata.emplace_back("drt:partial", progress);
    metadata.emplace_back("drt:checkpoint", checkpointPath);
    return writeImage(command.output, partial, metadata);
}

std::string rankFigures(const DistributedReport& report) {
    std::string tiles;
    for (size_t rank = 0; rank < report.tilesPerRank.size(); ++rank)
        tiles += fmt::format("{}{} ({:.2f} s)", rank ? ", " : "", report.tilesPerRank[rank],
                             report.renderSecondsPerRank[rank]);
    return fmt::format("drt: MPI: {} ranks; tasks per rank {}; {} messages, {:.3f} MB\n", report.ranks, tiles,
                       report.messages, double(report.bytes) / 1e6);
}

// `lastImages`: the command writes no image after this render's, so the image
// process may leave as soon as they are written (releaseImageIoProcess).
int renderProcess(const RenderCommand& command, std::ostream& err, const InterruptHandler& interrupt,
                  MpiJob* mpi, bool lastImages = false) {
    const auto commandStart = std::chrono::steady_clock::now();
    const bool rank0 = !mpi || mpi->rank() == 0;
    // Ranks other than 0 keep their messages unless they alone failed (the
    // same scene error from every rank would print once per rank).
    std::ostringstream held;
    std::ostream& messages = rank0 ? err : held;
    Prepared p;
    int status = kSuccess;
    {
        // A lone process quits on the first signal while it reads the scene;
        // MPI ranks read on and stop together (a rank that quit alone would
        // end the job before the others saved their checkpoints). That holds
        // for a rank rendering whole frames too, which is given no MpiJob.
        std::optional<InterruptHandler::NothingToSave> quit;
        if (!mpi && !MpiJob::launched()) quit.emplace();
        status = prepare(command, rank0, messages, p);
    }
    if (mpi) {
        const int rank0Status = int(mpi->broadcast(uint64_t(status)));
        // Collective: every rank takes part when rank 0 could start, even one that could not.
        const std::string rank0Scene = rank0Status == kSuccess ? mpi->broadcast(p.identity.sceneHash) : "";
        if (status == kSuccess && rank0Status == kSuccess && rank0Scene != p.identity.sceneHash) {
            messages << fmt::format("drt: the scene '{}' (or a file it includes) differs from rank 0's (are the "
                                    "files the same on every node?)\n",
                                    command.scene);
            status = kSceneError;
        }
        const int worst = mpi->agree(status);
        if (worst != kSuccess) {
            if (!rank0 && status != kSuccess && rank0Status == kSuccess) {
                std::istringstream lines(held.str());
                for (std::string line; std::getline(lines, line);)
                    err << fmt::format("drt (rank {} of {}): {}\n", mpi->rank(), mpi->size(),
                                       line.rfind("drt: ", 0) == 0 ? line.substr(5) : line);
            }
            if (rank0 && status == kSuccess)
                err << "drt: another rank could not start the render (its messages are above); stopping\n";
            return worst;
        }
        p.options.tileSize = int(mpi->broadcast(uint64_t(p.options.tileSize))); // a resumed render's
        p.alreadyWritten = mpi->broadcast(uint64_t(p.alreadyWritten)) != 0;
    } else if (status != kSuccess) {
        return status;
    }
    if (p.alreadyWritten) {
        if (rank0 && !command.quiet)
            err << fmt::format("drt: '{}' was written whole by an earlier run (same scene, frame and settings): "
                               "kept\n",
                               command.output);
        return kSuccess;
    }
    if (!mpi && interrupt.interrupted()) {
        err << "drt: interrupted before the render started: nothing to save\n";
        return interrupt.exitStatus();
    }

    std::optional<ProgressLine> progress;
    if (rank0 && command.progress && !command.quiet) progress.emplace(err);
    // Without an image process (image/image_process.h: under MPI, or
    // DRT_IMAGE_PROCESS=0) the image module loads in this process while the
    // render runs rather than before or after it, from the first finished
    // tile on: by then the render's threads run.
    // Not earlier: while dlopen runs, starting a thread or a TBB arena waits for
    // it (each takes the dynamic loader's lock).
    std::atomic<bool> loadRequested{false};
    const std::function<void(double)> report = [&progress, &loadRequested, rank0](double fraction) {
        if (rank0 && !loadRequested.exchange(true)) loadImageIoInBackground();
        if (progress) progress->update(fraction);
    };
    const auto start = std::chrono::steady_clock::now();
    std::optional<RenderState> state;
    status = kSuccess;
    try {
        state.emplace(p.options);
        if (p.checkpoint) state->restore(p.checkpoint->state.data(), p.checkpoint->state.size());
    } catch (const RenderError& e) {
        err << fmt::format("drt: {}: {}\n", p.checkpoint ? "cannot resume" : command.scene, e.what());
        status = p.checkpoint ? kUsageError : kSceneError;
    }
    if (mpi) status = mpi->agree(status); // every rank stops, or none
    if (status != kSuccess) return status;
    LocalTileScheduler scheduler(*state, interrupt.flag(), report);
    const auto snapshot = [&](Checkpoint& checkpoint, Image& partial, std::string& text) {
        scheduler.withState([&](const RenderState& s) {
            checkpoint = makeCheckpoint(p.identity, s);
            partial = partialImage(*p.scene, s);
            text = progressText(s);
        });
    };
    std::optional<ProgressSaver> saver;
    if (rank0) saver.emplace(command.checkpointSeconds, interrupt.flag(), [&] {
        Checkpoint checkpoint;
        Image partial;
        std::string text;
        snapshot(checkpoint, partial, text);
        if (std::string problem = saveProgress(command, p, checkpoint, std::move(partial), text); !problem.empty())
            err << "drt: periodic checkpoint failed: " << problem << "\n";
    });
    TileRenderInfo info;
    DistributedReport ranks;
    try {
        if (mpi) {
            info = renderDistributed(*mpi, *p.scene, p.options, *state, rank0 ? &scheduler : nullptr, &ranks);
        } else {
            // When the render's threads fill every core, one of them waits
            // while the image module loads: the load has a core of its own
            // and the render the others, rather than both sharing them all
            // and the end of a short render waiting for the load.
            const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
            const int threads = p.options.threads > 0 ? p.options.threads : int(cores);
            const bool lend = threads >= 2 && unsigned(threads) >= cores;
            LendingScheduler lending(scheduler, [lend] { return lend && imageIoLoading(); }, waitForImageIoLoad);
            info = renderTiles(*p.scene, p.options, *state, lending);
        }
    } catch (const RenderError& e) {
        saver.reset();
        if (progress) progress->finish();
        err << fmt::format("drt: {}: render failed: {}\n", command.scene, e.what());
        return kSceneError;
    }
    saver.reset();
    if (progress) progress->finish();
    if (!rank0) return kSuccess;

    if (!state->finished()) {
        Checkpoint checkpoint;
        Image partial;
        std::string text;
        snapshot(checkpoint, partial, text);
        if (std::string problem = saveProgress(command, p, checkpoint, std::move(partial), text); !problem.empty()) {
            err << "drt: interrupted, and saving failed: " << problem << "\n";
            return interrupt.exitStatus();
        }
        err << fmt::format("drt: interrupted: {}; saved to '{}' ({}) and the checkpoint '{}'; add --resume to the "
                           "same command to continue\n",
                           text, command.output,
                           keepsAlpha(command.output) ? "unfinished pixels transparent black"
                                                      : "unfinished pixels black",
                           checkpointPathFor(command.output));
        return interrupt.exitStatus();
    }
    RenderResult result = finishRender(*p.scene, *state, info);
    if (result.stats.untraceableRays > 0)
        err << fmt::format("drt: {}: warning: {} rays started or pointed beyond {:g} from the origin, farther than "
                           "drt traces (Embree's single precision), and were taken to meet nothing; move the camera "
                           "and the objects nearer the origin\n",
                           command.scene, result.stats.untraceableRays, Accelerator::kLargestCoordinate);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    uint64_t nonFinitePixels = 0;
    if (int written = writeOutputs(command, p.options, p.identity, p.record, result, nonFinitePixels, err);
        written != kSuccess)
        return written;
    if (!command.statsOutput.empty()) {
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - commandStart).count();
        if (std::string problem = writeStatsJson(command, p.options, result, {p.loadSeconds, seconds, total});
            !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kIoError;
        }
    }
    if (!command.quiet) {
        printSummary(command, p.options, result, nonFinitePixels, seconds, err);
        if (mpi) err << rankFigures(ranks);
    }
    // The image process's exit (about 5 ms: its ~260 libraries unmapped)
    // overlaps this render's own tidying up (the scene, the state, the images).
    if (lastImages) releaseImageIoProcess();
    return kSuccess;
}

std::string frameFigures(const FrameDistributionReport& report) {
    std::string frames;
    for (size_t rank = 0; rank < report.framesPerRank.size(); ++rank)
        frames += fmt::format("{}{}", rank ? ", " : "", report.framesPerRank[rank]);
    return fmt::format("drt: MPI: {} ranks, whole frames; frames per rank {}; {} messages, {:.3f} MB\n",
                       report.ranks, frames, report.messages, double(report.bytes) / 1e6);
}

// Each rank renders whole frames, as one process would, and writes them
// (distributed/frame_distribution.h); rank 0 prints every frame's messages as
// the frame finishes, so a frame's lines stay together.
int renderWholeFrames(MpiJob& mpi, const std::vector<AnimationFrame>& frames, bool quiet, std::ostream& err,
                      const InterruptHandler& interrupt) {
    // Every rank writes images: its dynamic linking (half a second of CPU)
    // overlaps the start of the job rather than stalling the first frame's render.
    loadImageIoInBackground();
    const auto render = [&](int index) {
        RenderCommand command = frames[size_t(index)].command;
        command.progress = false; // one progress line cannot show frames rendered at once
        std::ostringstream messages;
        FrameOutcome outcome;
        outcome.status = renderProcess(command, messages, interrupt, nullptr);
        outcome.messages = messages.str();
        return outcome;
    };
    const auto finished = [&](int index, int rank, const FrameOutcome& outcome) {
        const std::string frame = describeFrame(frames[size_t(index)]);
        if (!quiet) err << fmt::format("drt: {}, rendered by rank {} of {}\n", frame, rank, mpi.size());
        err << outcome.messages;
        if (outcome.status != kSuccess)
            err << fmt::format("drt: {} failed on rank {} of {} (exit status {}): no more frames are started\n",
                               frame, rank, mpi.size(), outcome.status);
    };
    FrameDistributionReport report;
    const int status =
        renderFramesDistributed(mpi, int(frames.size()), render, finished, interrupt.flag(),
                                [&interrupt] { return interrupt.exitStatus(); }, &report);
    if (mpi.rank() == 0 && !quiet) err << frameFigures(report);
    return status;
}

} // namespace

int runRender(const RenderCommand& command, std::ostream& out, std::ostream& err) {
    (void)out;
    std::optional<MpiJob> mpi;
    if (MpiJob::launched()) {
        if (!MpiJob::available()) {
            err << "drt: started by an MPI launcher (mpirun, srun), but this drt was built without MPI: every "
                   "process would render the whole image; install libopenmpi-dev and rebuild\n";
            return kUsageError;
        }
        try {
            mpi.emplace();
        } catch (const RenderError& e) {
            err << "drt: " << e.what() << "\n";
            return kIoError;
        }
    }
    // OpenImageIO loads in a process of its own from now on, while the scene
    // is parsed (image/image_process.h; not under MPI, whose ranks load it here).
    if (!mpi) startImageIoProcess();
    const InterruptHandler interrupt;
    const auto renderOne = [&](const RenderCommand& c, bool lastImages = false) {
        return renderProcess(c, err, interrupt, mpi ? &*mpi : nullptr, lastImages);
    };
    if (!wantsAnimation(command)) return renderOne(command, true);
    // An animation: every frame is a render of its own. Under MPI with enough
    // frames each rank renders whole frames; else the frames are rendered one
    // after another, each over every rank.
    const bool rank0 = !mpi || mpi->rank() == 0;
    std::ostringstream held; // the same usage errors on every rank are printed once
    std::vector<AnimationFrame> frames;
    int status = planAnimation(command, rank0 ? err : held, frames);
    if (mpi) { // every rank stops, or none (an .ini file that differs between nodes)
        const int worst = mpi->agree(status);
        if (status != kSuccess && !rank0 && worst != kSuccess) {
            std::istringstream lines(held.str());
            for (std::string line; std::getline(lines, line);)
                err << fmt::format("drt (rank {} of {}): {}\n", mpi->rank(), mpi->size(), line);
        }
        status = worst;
    }
    if (status != kSuccess) return status;
    const std::string& split = command.animation.distribute;
    if (mpi && (split == "frames" || (split == "auto" && wholeFramesPerRank(int(frames.size()), mpi->size()))))
        return renderWholeFrames(*mpi, frames, command.quiet, err, interrupt);
    return renderFramesInTurn(frames, command.quiet || !rank0, err, renderOne);
}

} // namespace drt::cli
