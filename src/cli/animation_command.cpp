// `drt render` over time: a frame range (--frames, --clock, --subset,
// --cyclic, or a POV-Ray .ini file), one frame at a clock value (--clock,
// --clock-delta), and the shutter (--shutter). Each frame is evaluated,
// moved and rendered on its own (animation/animation.h), so frame k of a run
// is the image `--frames A..B --subset k..k` gives by itself.
#include "animation/ini.h"
#include "cli/commands.h"

#include <filesystem>
#include <fmt/format.h>
#include <ostream>

namespace fs = std::filesystem;

namespace drt::cli {

namespace {

bool isIni(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".ini";
}

std::string shutterProblem(const AnimationRequest& a) {
    if (a.shutter && !(*a.shutter >= 0 && *a.shutter <= 1))
        return "--shutter must be a fraction of the frame interval, in [0, 1]";
    return "";
}

} // namespace

bool wantsAnimation(const RenderCommand& command) {
    return command.animation.frames || isIni(command.scene) || !command.animation.ini.empty();
}

FrameClock stillFrameClock(const RenderCommand& command) {
    if (command.animation.frame) return *command.animation.frame;
    FrameClock frame;
    if (command.animation.clock) frame.clock = *command.animation.clock;
    if (command.animation.clockDelta) frame.clockDelta = *command.animation.clockDelta;
    return frame;
}

FrameOptions frameOptions(const RenderCommand& command) { return {command.animation.shutter}; }

int planAnimation(const RenderCommand& given, std::ostream& err, std::vector<AnimationFrame>& frames) {
    frames.clear();
    RenderCommand command = given;
    const AnimationRequest& request = given.animation;
    if (std::string problem = shutterProblem(request); !problem.empty()) {
        err << "drt: " << problem << "\n";
        return kUsageError;
    }
    Animation animation;
    // A POV-Ray .ini file: its options, under the command line's.
    const std::string iniPath = isIni(given.scene) ? given.scene : request.ini;
    if (!iniPath.empty()) {
        Diagnostics diagnostics;
        const std::optional<IniSettings> ini = readIniFile(iniPath, diagnostics);
        err << diagnostics.formatAll();
        if (!ini) return fs::exists(iniPath) ? kSceneError : kIoError;
        applyIni(*ini, animation);
        if (isIni(given.scene)) {
            if (!ini->input) {
                err << fmt::format("drt: {}: no Input_File_Name: the .ini does not name a scene\n", iniPath);
                return kSceneError;
            }
            command.scene = *ini->input;
        }
        if (command.output.empty()) {
            if (!ini->output) {
                err << fmt::format("drt: {}: no Output_File_Name and no --output: where would the frames go?\n",
                                   iniPath);
                return kUsageError;
            }
            command.output = *ini->output;
        }
        if (!command.overrides.width && ini->width) command.overrides.width = *ini->width;
        if (!command.overrides.height && ini->height) command.overrides.height = *ini->height;
        command.pov.includePaths.insert(command.pov.includePaths.end(), ini->libraryPaths.begin(),
                                        ini->libraryPaths.end());
        if (ini->clock && !ini->initialFrame && !ini->finalFrame && !request.frames)
            animation.initialClock = animation.finalClock = *ini->clock;
    }
    if (request.frames) {
        animation.initialFrame = request.frames->first;
        animation.finalFrame = request.frames->second;
        animation.subsetStart.reset();
        animation.subsetEnd.reset();
    }
    if (request.clockRange) {
        animation.initialClock = request.clockRange->first;
        animation.finalClock = request.clockRange->second;
    } else if (request.clock) {
        animation.initialClock = animation.finalClock = *request.clock;
    }
    if (request.subset) {
        animation.subsetStart = request.subset->first;
        animation.subsetEnd = request.subset->second;
    }
    if (request.cyclic) animation.cyclic = true;
    if (std::string problem = animationProblem(animation); !problem.empty()) {
        err << "drt: " << problem << "\n";
        return kUsageError;
    }

    const int first = firstRenderedFrame(animation), last = lastRenderedFrame(animation);
    const bool several = last > first;
    for (int frame = first; frame <= last; ++frame) {
        const std::string output = several || isFramePattern(command.output)
                                       ? frameFileName(command.output, frame, animation.finalFrame)
                                       : command.output;
        FrameClock clock = frameClockOf(animation, frame);
        if (!several && request.clockDelta) clock.clockDelta = *request.clockDelta;
        RenderCommand frameCommand = command; // every output of a frame gets its number
        if (several && !command.varianceOutput.empty())
            frameCommand.varianceOutput = frameFileName(command.varianceOutput, frame, animation.finalFrame);
        if (several && !command.sppImageOutput.empty())
            frameCommand.sppImageOutput = frameFileName(command.sppImageOutput, frame, animation.finalFrame);
        // The frame is an ordinary render at its clock (crops, checkpoints and
        // MPI ranks included), so it equals a one-frame render byte for byte.
        frameCommand.output = output;
        frameCommand.animation = AnimationRequest{};
        frameCommand.animation.shutter = request.shutter;
        frameCommand.animation.frame = clock;
        frames.push_back({frame, clock.clock, std::move(frameCommand)});
    }
    return kSuccess;
}

std::string describeFrame(const AnimationFrame& frame) {
    return fmt::format("frame {} (clock {:g})", frame.number, frame.clock);
}

int runAnimation(const RenderCommand& command, std::ostream& err,
                 const std::function<int(const RenderCommand& frame)>& renderFrame) {
    std::vector<AnimationFrame> frames;
    if (int status = planAnimation(command, err, frames); status != kSuccess) return status;
    return renderFramesInTurn(frames, command.quiet, err, renderFrame);
}

int renderFramesInTurn(const std::vector<AnimationFrame>& frames, bool quiet, std::ostream& err,
                       const std::function<int(const RenderCommand& frame)>& renderFrame) {
    for (const AnimationFrame& frame : frames) {
        if (!quiet) err << "drt: " << describeFrame(frame) << "\n";
        if (int status = renderFrame(frame.command); status != kSuccess) return status;
    }
    return kSuccess;
}

void printFrameReport(const RenderCommand& command, const FrameReport& report, std::ostream& err) {
    if (command.quiet) return;
    if (report.evaluations > 1)
        err << fmt::format("drt: motion from the clock: {} evaluations, {} objects, {} lights{}\n",
                           report.evaluations, report.objectsFromClock, report.lightsFromClock,
                           report.cameraFromClock ? ", the camera" : "");
    for (const std::string& note : report.unpaired)
        err << fmt::format("drt: {}:{}: held still (cannot be paired over the shutter)\n", command.scene, note);
}

} // namespace drt::cli
