// Interrupting drt render with real signals (SIGINT, SIGTERM) sent to a child
// process: it saves the finished tiles (alpha 0 where unfinished) and a
// checkpoint, exits 128 + signal, and --resume finishes the image bit-identical
// to an uninterrupted render, from interruptions at several points, for fixed
// and adaptive sampling. A second signal quits at once without leaving a
// temporary file; a checkpoint of another render is refused.
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <tuple>
#include <unistd.h>

extern char** environ;

namespace fs = std::filesystem;

namespace drt {
namespace {

// A drt child process, its stderr in a file.
class Child {
public:
    Child(const std::vector<std::string>& args, const std::string& errPath) {
        std::vector<std::string> argv = {test::drtExecutable()};
        argv.insert(argv.end(), args.begin(), args.end());
        std::vector<char*> pointers;
        for (std::string& a : argv) pointers.push_back(a.data());
        pointers.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
        if (posix_spawn(&pid_, pointers[0], &actions, nullptr, pointers.data(), environ) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
    }
    ~Child() {
        if (pid_ > 0 && !exited_) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    bool running() {
        if (exited_) return false;
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) record(status);
        return !exited_;
    }
    // Only a child not yet reaped: its pid cannot have been reused, and
    // kill(-1, ...) (no child) would signal every process we may signal.
    void signal(int number) {
        if (pid_ > 0 && !exited_) ::kill(pid_, number);
    }
    // The exit status (128 + signal if a signal ended it); -1 after `seconds`.
    int wait(double seconds = 300) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (running() && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        return exited_ ? status_ : -1;
    }

private:
    void record(int status) {
        exited_ = true;
        status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    pid_t pid_ = -1;
    bool exited_ = false;
    int status_ = -1;
};

// Which file `path` is now: its inode and its change time (a rename sets
// it), so that an inode number freed and given again is still a new file.
std::tuple<ino_t, time_t, long> versionOf(const std::string& path) {
    struct stat s {};
    if (::stat(path.c_str(), &s) != 0) return {0, 0, 0};
    return {s.st_ino, s.st_ctim.tv_sec, s.st_ctim.tv_nsec};
}

// Waits until `path` has been (re)written `times` times (each checkpoint is a
// new file renamed over the old one); false if the child exits first.
bool waitForWrites(Child& child, const std::string& path, int times) {
    auto last = versionOf(path);
    for (int seen = 0; seen < times;) {
        if (!child.running()) return false;
        const auto now = versionOf(path);
        if (std::get<0>(now) != 0 && now != last) ++seen, last = now;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

std::vector<std::string> renderArgs(const std::string& output, bool adaptive) {
    std::vector<std::string> args = {"render",   test::sourcePath("examples/soft_shadows.drt"),
                                     "-o",       output,
                                     "--width",  "96",
                                     "--height", "72",
                                     "--seed",   "5",
                                     "--tile-size", "8",
                                     "--threads", "1",
                                     "-q"};
    if (adaptive) {
        // About 6.2M samples (the fixed case: 4.4M), so several checkpoints come first.
        for (const char* a : {"--adaptive", "--min-spp", "16", "--max-spp", "2048", "--adaptive-error", "0.0003"})
            args.push_back(a);
    } else {
        args.insert(args.end(), {"--spp", "640"}); // long enough for several checkpoints
    }
    return args;
}

std::vector<std::string> with(std::vector<std::string> args, std::initializer_list<const char*> more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

Image pixelsOf(const std::string& path) {
    Image image;
    EXPECT_EQ(readImage(path, image), "");
    return image;
}

void interruptTwiceThenResume(bool adaptive) {
    const std::string dir = test::tempDir();
    const std::string full = dir + "/full.exr", out = dir + "/out.exr", checkpoint = out + ".drt-checkpoint";
    {
        Child reference(renderArgs(full, adaptive), dir + "/full.err");
        ASSERT_EQ(reference.wait(), 0) << test::readFile(dir + "/full.err");
    }
    // Early: right after the first periodic checkpoint.
    {
        Child child(with(renderArgs(out, adaptive), {"--checkpoint-every", "0.05"}), dir + "/1.err");
        ASSERT_TRUE(waitForWrites(child, checkpoint, 1)) << "finished before the interruption";
        child.signal(SIGINT);
        EXPECT_EQ(child.wait(), 130) << test::readFile(dir + "/1.err");
    }
    const std::string message = test::readFile(dir + "/1.err");
    EXPECT_NE(message.find("add --resume to the same command"), std::string::npos) << message;
    ASSERT_TRUE(fs::exists(checkpoint));
    // The partial image: finished pixels as in the full render (alpha 1), the others black with alpha 0.
    const Image partial = pixelsOf(out), reference = pixelsOf(full);
    ASSERT_EQ(partial.channels, 4);
    int finished = 0, unfinished = 0;
    for (int y = 0; y < partial.height; ++y)
        for (int x = 0; x < partial.width; ++x) {
            if (partial.at(x, y, 3) == 0) {
                ++unfinished;
                EXPECT_EQ(partial.at(x, y, 0), 0.0f);
                continue;
            }
            ++finished;
            if (adaptive) continue; // an adaptive pixel's mean so far is not its final value
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(partial.at(x, y, c), reference.at(x, y, c)) << x << "," << y;
            }
        }
    if (!adaptive) {
        EXPECT_GT(finished, 0);
        EXPECT_GT(unfinished, 0);
    }
    // Later: a resumed render interrupted after a few more checkpoints, by SIGTERM.
    {
        Child child(with(renderArgs(out, adaptive), {"--resume", "--checkpoint-every", "0.05"}), dir + "/2.err");
        ASSERT_TRUE(waitForWrites(child, checkpoint, 4)) << "finished before the interruption";
        child.signal(SIGTERM);
        EXPECT_EQ(child.wait(), 143) << test::readFile(dir + "/2.err");
    }
    // Then to the end, on another thread count.
    std::vector<std::string> last = with(renderArgs(out, adaptive), {"--resume"});
    *(std::find(last.begin(), last.end(), "--threads") + 1) = "2";
    {
        Child child(last, dir + "/3.err");
        ASSERT_EQ(child.wait(), 0) << test::readFile(dir + "/3.err");
    }
    const Image resumed = pixelsOf(out);
    EXPECT_EQ(resumed.channels, 3);
    EXPECT_TRUE(resumed.pixels == reference.pixels) << "the resumed render differs from the uninterrupted one";
    EXPECT_FALSE(fs::exists(checkpoint)) << "a finished render removes its checkpoint";
    fs::remove_all(dir);
}

TEST(Interrupt, FixedSamplingInterruptedTwiceAndResumedIsBitIdentical) { interruptTwiceThenResume(false); }

TEST(Interrupt, AdaptiveSamplingInterruptedTwiceAndResumedIsBitIdentical) { interruptTwiceThenResume(true); }

TEST(Interrupt, ASecondSignalQuitsAtOnceLeavingNoTemporaryFile) {
    const std::string dir = test::tempDir();
    const std::string out = dir + "/out.png";
    Child child(with(renderArgs(out, false), {"--checkpoint-every", "0.02"}), dir + "/err");
    ASSERT_TRUE(waitForWrites(child, out + ".drt-checkpoint", 2));
    child.signal(SIGINT);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    child.signal(SIGINT);
    EXPECT_EQ(child.wait(), 130);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << "left behind: " << entry.path();
    // What is there is complete: the last checkpoint saved, and a readable image.
    Image image;
    EXPECT_EQ(readImage(out, image), "");
    fs::remove_all(dir);
}

TEST(Interrupt, ResumeRefusesAMissingCheckpointOrOneOfAnotherRender) {
    const std::string dir = test::tempDir();
    const std::string out = dir + "/out.exr";
    {
        Child child(with(renderArgs(out, false), {"--resume"}), dir + "/missing.err");
        EXPECT_EQ(child.wait(), 3);
        EXPECT_NE(test::readFile(dir + "/missing.err").find("no checkpoint"), std::string::npos);
    }
    {
        Child child(with(renderArgs(out, false), {"--checkpoint-every", "0.05"}), dir + "/1.err");
        ASSERT_TRUE(waitForWrites(child, out + ".drt-checkpoint", 1));
        child.signal(SIGINT);
        EXPECT_EQ(child.wait(), 130);
    }
    const std::pair<std::vector<std::string>, std::string> refusals[] = {
        {{"--seed", "6"}, "has other settings: seed=5 there, seed=6 here"},
        {{"--width", "97"}, "size=96x72 there, size=97x72 here"},
        {{"--spp", "641"}, "spp=640 there, spp=641 here"},
        {{"--crop", "0,8,0,8"}, "is of the whole image, this render is of the crop 0,8,0,8"},
    };
    for (const auto& [extra, message] : refusals) {
        SCOPED_TRACE(message);
        std::vector<std::string> args = with(renderArgs(out, false), {"--resume"});
        // The option's new value, or the option added.
        if (auto given = std::find(args.begin(), args.end(), extra[0]); given != args.end()) *(given + 1) = extra[1];
        else args.insert(args.end(), extra.begin(), extra.end());
        Child child(args, dir + "/refused.err");
        EXPECT_EQ(child.wait(), 2);
        EXPECT_NE(test::readFile(dir + "/refused.err").find(message), std::string::npos)
            << test::readFile(dir + "/refused.err");
    }
    // Another scene: the same file with one more comment.
    const std::string other = test::writeFile(
        dir + "/other.drt", test::readFile(test::sourcePath("examples/soft_shadows.drt")) + "\n// another\n");
    std::vector<std::string> args = with(renderArgs(out, false), {"--resume"});
    args[1] = other;
    Child child(args, dir + "/scene.err");
    EXPECT_EQ(child.wait(), 2);
    EXPECT_NE(test::readFile(dir + "/scene.err").find("is of another scene"), std::string::npos);
    fs::remove_all(dir);
}

// An animation resumed: a frame with a checkpoint continues from it, a frame an
// earlier run wrote whole is kept, any other frame is rendered from the start;
// a frame or checkpoint made at another clock is not taken for this frame's.
TEST(Interrupt, AnAnimationResumedKeepsTheFramesWrittenWholeAndRendersTheRest) {
    const std::string dir = test::tempDir();
    const std::string scene =
        test::writeFile(dir + "/anim.drt", "render { width 24 height 18 samples 4 }\n"
                                           "camera { location <0, 1, -5> look_at <0, 0.5, 0> }\n"
                                           "light_source { <-3, 5, -3>, rgb 1 }\n"
                                           "sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } "
                                           "translate <clock * 2 - 1, 0, 0> }\n");
    const std::string frames = " --frames 0..3 --clock 0..1";
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + dir + "/one_%d.exr' -q" + frames).exitCode, 0);
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + dir + "/f_%d.exr' -q" + frames).exitCode, 0);
    fs::remove(dir + "/f_2.exr");
    // Frame 1 of another clock range: the same scene and settings, another image.
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + dir + "/f_%d.exr' -q --frames 0..3 --clock 0..2 " +
                           "--subset 1..1")
                  .exitCode,
              0);
    const test::CommandResult resumed = test::runDrt("render '" + scene + "' -o '" + dir + "/f_%d.exr'" + frames +
                                                     " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    for (int frame : {0, 3})
        EXPECT_NE(resumed.err.find("f_" + std::to_string(frame) + ".exr' was written whole by an earlier run"),
                  std::string::npos)
            << resumed.err;
    for (int frame : {1, 2}) EXPECT_EQ(resumed.err.find("f_" + std::to_string(frame) + ".exr' was"), std::string::npos);
    for (int frame = 0; frame <= 3; ++frame) {
        const std::string number = std::to_string(frame);
        EXPECT_TRUE(pixelsOf(dir + "/f_" + number + ".exr").pixels == pixelsOf(dir + "/one_" + number + ".exr").pixels)
            << frame;
    }
    // A checkpoint saved at one clock is refused at another.
    const std::string out = dir + "/clock.exr";
    {
        Child child(with(renderArgs(out, false), {"--clock", "0.25", "--checkpoint-every", "0.05"}), dir + "/c.err");
        ASSERT_TRUE(waitForWrites(child, out + ".drt-checkpoint", 1));
        child.signal(SIGTERM);
        EXPECT_EQ(child.wait(), 143);
    }
    Child other(with(renderArgs(out, false), {"--clock", "0.5", "--resume"}), dir + "/refused.err");
    EXPECT_EQ(other.wait(), 2);
    EXPECT_NE(test::readFile(dir + "/refused.err").find("clock=0.25 there, clock=0.5 here"), std::string::npos)
        << test::readFile(dir + "/refused.err");
    fs::remove_all(dir);
}

} // namespace
} // namespace drt
