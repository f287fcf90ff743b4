// drt under mpirun (Open MPI, --oversubscribe: more ranks than cores): the
// image, its variance and samples-per-pixel images are bit-identical to a
// single-process render for several rank counts, thread counts and tile sizes,
// for fixed and adaptive sampling, crops and PNG output; a scene error or a
// different scene on one rank, and a rank that dies, end the job with a clear
// error and a non-zero exit, never a hang; an interrupted job resumes on
// another number of ranks. An animation's frames go whole to ranks (or split
// into tiles) and every frame file equals the single-process one byte for
// byte; a scene error in one frame, a dying rank and an interruption end such a
// job too, and --resume finishes it on another number of ranks. Built only with
// MPI (CMake DRT_MPI).
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace drt {
namespace {

// Runs `mpirun --oversubscribe -np N COMMAND` (the CI runs as root, which
// Open MPI refuses unless told), stopped after `seconds` (exit 124).
test::CommandResult mpirun(int ranks, const std::string& command, int seconds = 240) {
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    const std::string dir = test::tempDir();
    // In the sanitizer build, LeakSanitizer reports Open MPI's own one-time
    // allocations at exit, most from plugins it has unloaded by then (no name a
    // suppression could match): the ranks run without leak detection. drt's
    // code on these paths is leak-checked by the single-process tests.
    std::string environment;
    if (const char* asan = std::getenv("ASAN_OPTIONS"))
        environment = "env ASAN_OPTIONS='" + std::string(asan) + ":detect_leaks=0' ";
    const std::string line = environment + "timeout -s KILL " + std::to_string(seconds) + " '" + DRT_MPIRUN +
                             "' --oversubscribe -np " + std::to_string(ranks) + " " + command + " >'" + dir +
                             "/out' 2>'" + dir + "/err' </dev/null";
    const int status = std::system(line.c_str());
    test::CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = test::readFile(dir + "/out");
    r.err = test::readFile(dir + "/err");
    fs::remove_all(dir);
    return r;
}

std::string drt() { return std::string("'") + test::drtExecutable() + "'"; }
std::string scene() { return std::string(1, '\'') + test::sourcePath("examples/soft_shadows.drt") + "'"; }

Image pixelsOf(const std::string& path) {
    Image image;
    EXPECT_EQ(readImage(path, image), "");
    return image;
}

void expectSamePixels(const std::string& a, const std::string& b) {
    EXPECT_TRUE(pixelsOf(a).pixels == pixelsOf(b).pixels) << a << " differs from " << b;
}

struct Setting {
    std::string name, options;
};

TEST(Mpi, ImagesAreBitIdenticalToOneProcessForAnyRankThreadAndTileCount) {
    const std::string dir = test::tempDir();
    const Setting settings[] = {
        {"fixed", "--width 40 --height 30 --spp 3 --seed 2"},
        {"adaptive", "--width 40 --height 30 --adaptive --min-spp 2 --max-spp 32 --adaptive-error 0.05"},
        {"crop", "--width 40 --height 30 --spp 2 --crop 7,33,5,26 --adaptive --min-spp 2 --max-spp 8"},
        {"split", "--width 40 --height 30 --spp 2 --light-samples 4 --seed 3"}, // the scene's area lights, K = 4
    };
    // (ranks, threads per rank, tile size)
    const int runs[][3] = {{2, 1, 8}, {3, 1, 5}, {3, 2, 16}};
    for (const Setting& s : settings) {
        SCOPED_TRACE(s.name);
        const std::string base = dir + "/" + s.name;
        const test::CommandResult one =
            test::runDrt("render " + scene() + " -o '" + base + ".exr' --variance '" + base + ".var.exr' --spp-image '" +
                         base + ".spp.exr' -q " + s.options);
        ASSERT_EQ(one.exitCode, 0) << one.err;
        for (const auto& [ranks, threads, tile] : runs) {
            const std::string name = base + "-" + std::to_string(ranks) + "x" + std::to_string(threads);
            SCOPED_TRACE(name);
            const test::CommandResult r =
                mpirun(ranks, drt() + " render " + scene() + " -o '" + name + ".exr' --variance '" + name +
                                  ".var.exr' --spp-image '" + name + ".spp.exr' " + s.options + " --threads " +
                                  std::to_string(threads) + " --tile-size " + std::to_string(tile));
            ASSERT_EQ(r.exitCode, 0) << r.err;
            EXPECT_NE(r.err.find("drt: MPI: " + std::to_string(ranks) + " ranks"), std::string::npos) << r.err;
            for (const char* kind : {".exr", ".var.exr", ".spp.exr"}) expectSamePixels(name + kind, base + kind);
        }
    }
    fs::remove_all(dir);
}

TEST(Mpi, PngOutputHasTheSamePixelsAsOneProcessWrites) {
    const std::string dir = test::tempDir();
    const std::string options = " --width 40 --height 30 --spp 2 -q";
    ASSERT_EQ(test::runDrt("render " + scene() + " -o '" + dir + "/one.png'" + options).exitCode, 0);
    const test::CommandResult r = mpirun(3, drt() + " render " + scene() + " -o '" + dir + "/three.png'" + options);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The same 8-bit pixels (the files differ in their timing metadata).
    expectSamePixels(dir + "/one.png", dir + "/three.png");
    fs::remove_all(dir);
}

TEST(Mpi, ASceneErrorOnOneRankEndsTheJobWithItsMessage) {
    const std::string dir = test::tempDir();
    const std::string broken = test::writeFile(dir + "/broken.drt", "camera { location <0, 0, -5> \n sphere {\n");
    const std::string other = test::writeFile(
        dir + "/other.drt", test::readFile(test::sourcePath("examples/soft_shadows.drt")) + "\n// other\n");
    // Rank 2 reads another file than ranks 0 and 1 (as if a node had other files).
    const auto onRank2 = [&](const std::string& scene2) {
        return "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 2 ]; then s=" + scene2 + "; else s=" +
               test::sourcePath("examples/soft_shadows.drt") + "; fi; exec " + test::drtExecutable() +
               " render \"$s\" -o " + dir + "/out.exr --width 20 --height 15 -q'";
    };
    const test::CommandResult error = mpirun(3, onRank2(broken), 120);
    EXPECT_EQ(error.exitCode, 1) << error.err;
    EXPECT_NE(error.err.find("drt (rank 2 of 3): "), std::string::npos) << error.err;
    EXPECT_NE(error.err.find("broken.drt:"), std::string::npos) << error.err;
    EXPECT_NE(error.err.find("another rank could not start the render"), std::string::npos) << error.err;
    const test::CommandResult differs = mpirun(3, onRank2(other), 120);
    EXPECT_EQ(differs.exitCode, 1) << differs.err;
    EXPECT_NE(differs.err.find("differs from rank 0's"), std::string::npos) << differs.err;
    const test::CommandResult allBroken = mpirun(2, drt() + " render '" + broken + "' -o '" + dir + "/x.exr'", 120);
    EXPECT_EQ(allBroken.exitCode, 1);
    EXPECT_NE(allBroken.err.find("broken.drt:"), std::string::npos) << allBroken.err;
    EXPECT_EQ(allBroken.err.find("rank 1 of 2"), std::string::npos) << "the same error is printed once";
    EXPECT_FALSE(fs::exists(dir + "/out.exr"));
    fs::remove_all(dir);
}

// MPI is a module drt loads under a launcher (distributed/mpi_module.h): drt
// itself links no MPI library, and a job whose ranks cannot load the module
// ends at once with the reason, writing nothing.
TEST(Mpi, TheMpiModuleIsLoadedUnderALauncherAndItsAbsenceEndsTheJob) {
    const std::string dir = test::tempDir();
    const std::string libraries = test::librariesDrtLoads("--version");
    EXPECT_NE(libraries.find("libembree3"), std::string::npos) << "the listing works";
    EXPECT_EQ(libraries.find("libmpi"), std::string::npos) << libraries;
    const test::CommandResult missing =
        mpirun(2, "env DRT_MPI_MODULE='" + dir + "/no-such-module.so' " + drt() + " render " + scene() + " -o '" +
                      dir + "/out.exr' --width 20 --height 15 -q",
               120);
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.exitCode, 124) << "the job hung";
    EXPECT_NE(missing.err.find("cannot load drt's MPI module libdrt_mpi.so"), std::string::npos) << missing.err;
    EXPECT_NE(missing.err.find("no-such-module.so: no such file"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(dir + "/out.exr"));
    fs::remove_all(dir);
}

// Runs `render` (a drt command line) on 3 ranks, rank 1 killed (SIGKILL) half
// a second in: the job ends non-zero, naming rank 1, long before the time limit.
void expectAKilledRankToEndTheJob(const std::string& render) {
    const std::string command = "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then exec timeout -s KILL 0.5 " +
                                render + "; else exec " + render + "; fi'";
    const auto start = std::chrono::steady_clock::now();
    const test::CommandResult r = mpirun(3, command, 120);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(seconds, 100) << "the job ran into the test's time limit: it hung";
    EXPECT_NE(r.err.find("rank 1"), std::string::npos) << r.err;
}

TEST(Mpi, ARankThatDiesEndsTheJobNonZeroWithoutAHang) {
    const std::string dir = test::tempDir();
    // A render of several seconds.
    expectAKilledRankToEndTheJob(test::drtExecutable() + " render " + test::sourcePath("examples/soft_shadows.drt") +
                                 " -o " + dir + "/out.exr --width 200 --height 150 --spp 64 --threads 1");
    EXPECT_FALSE(fs::exists(dir + "/out.exr") && !fs::exists(dir + "/out.exr.drt-checkpoint"))
        << "no complete image can come from a job that lost a rank";
    fs::remove_all(dir);
}

TEST(Mpi, AnInterruptedJobResumesOnAnotherNumberOfRanks) {
    const std::string dir = test::tempDir();
    // Long enough that the job is still rendering when rank 0's first
    // checkpoint (written once the image module has loaded, up to a second on
    // a loaded machine) is seen and SIGTERM arrives: at 40 spp the job often
    // finished first (exit 0, no checkpoint), and did so more often once the
    // renderer got faster; at 400 spp (0.8 s alone) it still did, once, while
    // two other programs loaded the machine.
    const std::string options = " --width 64 --height 48 --spp 1600 --tile-size 8 --threads 1 -q";
    const std::string out = dir + "/out.exr";
    ASSERT_EQ(test::runDrt("render " + scene() + " -o '" + dir + "/full.exr'" + options).exitCode, 0);
    // Rank 0 is sent SIGTERM once its first periodic checkpoint is written.
    const std::string command =
        "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 0 ]; then " + test::drtExecutable() + " render " +
        test::sourcePath("examples/soft_shadows.drt") + " -o " + out + options + " --checkpoint-every 0.05 & pid=$!; " +
        "while [ ! -e " + out + ".drt-checkpoint ] && kill -0 $pid 2>/dev/null; do sleep 0.01; done; kill -TERM $pid; " +
        "wait $pid; else exec " + test::drtExecutable() + " render " + test::sourcePath("examples/soft_shadows.drt") +
        " -o " + out + options + "; fi'";
    const test::CommandResult interrupted = mpirun(2, command, 120);
    EXPECT_EQ(interrupted.exitCode, 143) << interrupted.err;
    EXPECT_NE(interrupted.err.find("add --resume"), std::string::npos) << interrupted.err;
    ASSERT_TRUE(fs::exists(out + ".drt-checkpoint"));
    const test::CommandResult resumed =
        mpirun(3, drt() + " render " + scene() + " -o '" + out + "'" + options + " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    expectSamePixels(out, dir + "/full.exr");
    fs::remove_all(dir);
}

// ---------------------------------------------------------------- animations: whole frames per rank

// A small scene that moves with the clock; frame 3 stops with #error when `broken`.
std::string animatedScene(const std::string& dir, bool broken = false) {
    return test::writeFile(dir + (broken ? "/broken_anim.drt" : "/anim.drt"),
                           std::string("render { width 24 height 18 samples 4 }\n"
                                       "camera { location <0, 1, -5> look_at <0, 0.5, 0> }\n"
                                       "light_source { <-3, 5, -3>, rgb 1 }\n"
                                       "sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } "
                                       "translate <clock * 2 - 1, 0, 0> }\n"
                                       "box { <-2, -0.1, -1>, <2, 0, 3> pigment { checker rgb 1, rgb 0.3 } "
                                       "rotate y * 90 * clock }\n") +
                               (broken ? "#if (frame_number = 3)\n#error \"frame three is broken\"\n#end\n" : ""));
}

std::string frameName(const std::string& prefix, int frame) {
    return prefix + (frame < 10 ? "_0" : "_") + std::to_string(frame) + ".exr";
}

// How often `text` holds `part`.
int occurrences(const std::string& text, const std::string& part) {
    int n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

TEST(Mpi, AnimationFramesGoWholeToRanksAndEqualOneProcessByteForByte) {
    const std::string dir = test::tempDir();
    const std::string scene = animatedScene(dir);
    const std::string frames = " --frames 0..4 --clock 0..1 --reproducible";
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + dir + "/one_%02d.exr' -q" + frames).exitCode, 0);
    // (ranks, threads per rank, --distribute): 5 frames on 3 ranks go whole (auto), or split into tiles when asked;
    // 5 frames on 6 ranks are split into tiles (auto).
    const struct {
        int ranks, threads;
        std::string distribute, expected;
    } runs[] = {{3, 1, "", "whole frames; frames per rank"},
                {2, 2, "frames", "whole frames; frames per rank"},
                {3, 1, "tiles", "drt: MPI: 3 ranks; tasks per rank"},
                {6, 1, "", "drt: MPI: 6 ranks; tasks per rank"}};
    for (const auto& run : runs) {
        const std::string prefix = dir + "/n" + std::to_string(run.ranks) + run.distribute;
        SCOPED_TRACE(prefix);
        const test::CommandResult r =
            mpirun(run.ranks, drt() + " render '" + scene + "' -o '" + prefix + "_%02d.exr' --threads " +
                                  std::to_string(run.threads) + frames +
                                  (run.distribute.empty() ? "" : " --distribute " + run.distribute));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find(run.expected), std::string::npos) << r.err;
        for (int frame = 0; frame <= 4; ++frame) {
            // The same file, byte for byte (--reproducible leaves the run's details out of the metadata).
            EXPECT_EQ(test::readFile(frameName(prefix, frame)), test::readFile(frameName(dir + "/one", frame)))
                << frame;
            if (run.expected.find("whole") != std::string::npos) { // rendered, and written, by exactly one rank
                EXPECT_EQ(occurrences(r.err, "frame " + std::to_string(frame) + " (clock "), 1) << r.err;
            }
        }
    }
    fs::remove_all(dir);
}

TEST(Mpi, ASceneErrorInOneFrameEndsAWholeFrameJobWithItsMessage) {
    const std::string dir = test::tempDir();
    const std::string scene = animatedScene(dir, true);
    const auto start = std::chrono::steady_clock::now();
    const test::CommandResult r =
        mpirun(3, drt() + " render '" + scene + "' -o '" + dir + "/f_%02d.exr' --frames 0..5 --threads 1", 120);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_LT(seconds, 100) << "the job ran into the test's time limit: it hung";
    EXPECT_NE(r.err.find("broken_anim.drt:7:1: error: #error: frame three is broken"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("frame 3 (clock 0.6) failed on rank "), std::string::npos) << r.err;
    EXPECT_EQ(occurrences(r.err, "frame three is broken\n"), 1) << r.err;
    EXPECT_FALSE(fs::exists(frameName(dir + "/f", 3)));
    EXPECT_FALSE(fs::exists(frameName(dir + "/f", 3) + ".drt-checkpoint"));
    fs::remove_all(dir);
}

TEST(Mpi, AnAnimationOneRankCannotReadStopsEveryRankWithItsMessage) {
    const std::string dir = test::tempDir();
    animatedScene(dir);
    const std::string ini = test::writeFile(dir + "/anim.ini", "Input_File_Name=" + dir +
                                                                   "/anim.drt\nInitial_Frame=0\nFinal_Frame=4\n");
    // Rank 2 is given an .ini file that is not there (as if its node lacked it).
    const std::string command = "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 2 ]; then i=" + dir +
                                "/missing.ini; else i=" + ini + "; fi; exec " + test::drtExecutable() +
                                " render \"$i\" -o " + dir + "/f_%02d.exr -q'";
    const test::CommandResult r = mpirun(3, command, 120);
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("drt (rank 2 of 3): "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.ini"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(frameName(dir + "/f", 0)));
    fs::remove_all(dir);
}

TEST(Mpi, ARankThatDiesEndsAWholeFrameJobNonZeroWithoutAHang) {
    const std::string dir = test::tempDir();
    expectAKilledRankToEndTheJob(test::drtExecutable() + " render " + test::sourcePath("examples/pendulum.drt") +
                                 " -o " + dir + "/f_%02d.exr --frames 0..5 --width 160 --height 120 --spp 64 " +
                                 "--threads 1");
    fs::remove_all(dir);
}

TEST(Mpi, AnInterruptedWholeFrameJobResumesOnAnotherNumberOfRanks) {
    const std::string dir = test::tempDir();
    // Enough samples that the other ranks are still inside a frame when the first one is written (at 40
    // spp they had sometimes finished every frame, or were between frames, with nothing to checkpoint).
    const std::string options = " --frames 0..9 --width 80 --height 60 --spp 200 --threads 1 -q";
    const std::string scene = test::sourcePath("examples/pendulum.drt");
    ASSERT_EQ(test::runDrt("render '" + scene + "' -o '" + dir + "/one_%02d.exr'" + options).exitCode, 0);
    // Every rank is sent SIGTERM once a first frame is written (as Slurm's --signal does). Any frame,
    // not frame 0: frames are handed out as ranks ask, and rank 0, which also answers the others, may
    // finish its first frame after the other ranks have rendered every other one.
    const std::string out = dir + "/f_%02d.exr";
    const std::string command = "sh -c '" + test::drtExecutable() + " render " + scene + " -o " + out + options +
                                " & pid=$!; while ! ls " + dir + "/f_*.exr >/dev/null 2>&1" +
                                " && kill -0 $pid 2>/dev/null; do sleep 0.01; done; kill -TERM $pid; wait $pid'";
    // A rank signalled while it reads its next frame's scene saves nothing for
    // that frame (it has no render to save). On a loaded machine every rank
    // but the one that wrote can be there at once: such a run has no
    // checkpoint to resume from, and is run again (at most three times).
    int missing = 0, checkpoints = 0;
    for (int attempt = 0; attempt < 3 && checkpoints == 0; ++attempt) {
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().filename().string().rfind("f_", 0) == 0) fs::remove(entry.path());
        const test::CommandResult interrupted = mpirun(3, command, 120);
        EXPECT_EQ(interrupted.exitCode, 143) << interrupted.err;
        missing = checkpoints = 0;
        for (int frame = 0; frame <= 9; ++frame) {
            missing += !fs::exists(frameName(dir + "/f", frame));
            checkpoints += fs::exists(frameName(dir + "/f", frame) + ".drt-checkpoint");
        }
        EXPECT_GT(missing, 0) << "frames were started after the interruption";
    }
    ASSERT_GT(checkpoints, 0) << "in three runs, the frames in progress saved no checkpoint";
    // Resumed on 2 ranks: the frames written whole are kept, the checkpointed ones continue, the rest are rendered.
    const test::CommandResult resumed =
        mpirun(2, drt() + " render '" + scene + "' -o '" + out + "'" + options + " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    for (int frame = 0; frame <= 9; ++frame) {
        expectSamePixels(frameName(dir + "/f", frame), frameName(dir + "/one", frame));
        EXPECT_FALSE(fs::exists(frameName(dir + "/f", frame) + ".drt-checkpoint")) << frame;
    }
    fs::remove_all(dir);
}

// A rank rendering whole frames is signalled while it reads its frame's
// scene (a long #while): it must not quit alone at once, as a lone render
// does, which would end the job before the other ranks saved their frames;
// it reads on and stops with the job, saying there was nothing to save.
// A job stopped before it started every frame ends 143, not 0.
TEST(Mpi, ARankSignalledWhileReadingItsFrameReadsOnAndStopsWithTheJob) {
    const std::string dir = test::tempDir();
    const std::string slow = test::writeFile(dir + "/slow.drt", "#declare I = 0;\n#while (I < 1000000)\n"
                                                                "  #declare I = I + 1;\n#end\n"
                                                                "camera { location <0, 0, -4> look_at 0 }\n"
                                                                "sphere { 0, 1 pigment { color rgb clock } }\n");
    // Each rank's drt is sent SIGTERM once it has begun loading its image
    // module (libdrt_oiio in /proc/PID/maps), which a rank rendering whole
    // frames does first, after its signal handler is in place and just before
    // it reads its first frame (several seconds), and a moment later. (Neither
    // the handlers nor CPU time tell from outside: the handler that removes
    // temporary files is there from the start, and MPI's start-up spins.)
    const std::string command =
        "sh -c '" + test::drtExecutable() + " render " + slow + " -o " + dir + "/f_%02d.exr" +
        " --frames 0..3 --width 16 --height 16 --spp 1 --threads 1 -q & pid=$!;" +
        " while kill -0 $pid 2>/dev/null && ! grep -q libdrt_oiio /proc/$pid/maps 2>/dev/null; do sleep 0.01; done;" +
        " sleep 0.3; kill -TERM $pid; wait $pid'";
    const test::CommandResult r = mpirun(2, command, 180);
    EXPECT_EQ(r.exitCode, 143) << r.err;
    EXPECT_EQ(r.err.find("quitting, nothing to save"), std::string::npos) << r.err;
    // The signal is taken as a request to stop (a rank that was already
    // reading says there was nothing to save; one signalled before its first
    // frame starts none): no frame is written, and the job ends 143 even so.
    EXPECT_NE(r.err.find("drt: interrupted: finishing the tiles in progress"), std::string::npos) << r.err;
    for (int frame = 0; frame <= 3; ++frame) EXPECT_FALSE(fs::exists(frameName(dir + "/f", frame)));
    fs::remove_all(dir);
}

} // namespace
} // namespace drt
