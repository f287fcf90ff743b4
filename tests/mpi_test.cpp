// drt under mpirun (Open MPI, --oversubscribe: more ranks than cores): the
// image, its variance and samples-per-pixel images are bit-identical to a
// single-process render for several rank counts, thread counts and tile sizes,
// for fixed and adaptive sampling, crops and PNG output; a scene error or a
// different scene on one rank, and a rank that dies, end the job with a clear
// error and a non-zero exit, never a hang; an interrupted job resumes on
// another number of ranks. Built only with MPI (CMake DRT_MPI).
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
    const std::string line = "timeout -s KILL " + std::to_string(seconds) + " '" + DRT_MPIRUN +
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

TEST(Mpi, ARankThatDiesEndsTheJobNonZeroWithoutAHang) {
    const std::string dir = test::tempDir();
    // Rank 1 is killed (SIGKILL) half a second into a render of several seconds.
    const std::string command = "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then exec timeout -s KILL 0.5 " +
                                test::drtExecutable() + " render " + test::sourcePath("examples/soft_shadows.drt") +
                                " -o " + dir + "/out.exr --width 200 --height 150 --spp 64 --threads 1; else exec " +
                                test::drtExecutable() + " render " + test::sourcePath("examples/soft_shadows.drt") + " -o " +
                                dir + "/out.exr --width 200 --height 150 --spp 64 --threads 1; fi'";
    const auto start = std::chrono::steady_clock::now();
    const test::CommandResult r = mpirun(3, command, 120);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(seconds, 100) << "the job ran into the test's time limit: it hung";
    EXPECT_NE(r.err.find("rank 1"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out.exr") && !fs::exists(dir + "/out.exr.drt-checkpoint"))
        << "no complete image can come from a job that lost a rank";
    fs::remove_all(dir);
}

TEST(Mpi, AnInterruptedJobResumesOnAnotherNumberOfRanks) {
    const std::string dir = test::tempDir();
    const std::string options = " --width 64 --height 48 --spp 40 --tile-size 8 --threads 1 -q";
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

} // namespace
} // namespace drt
