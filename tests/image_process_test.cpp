// drt render's image process (image/image_process.h): OpenImageIO loaded in a
// process of its own that does the render's image reads and writes. The
// images must be the bytes an in-process render gives, the work must really
// happen in the other process, and its end must be a clear error that leaves
// no file behind.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sys/wait.h>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace drt {
namespace {

using test::runDrt;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// A scene that reads an image (a texture) and is written as an image.
std::string texturedScene(const std::string& dir) {
    return test::writeFile(dir + "/textured.drt", R"(render { width 40 height 30 samples 4 seed 2 }
camera { location <0, 1.6, -5> look_at <0, 0.9, 0> angle 60 }
light_source { <-4, 7, -6>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { 0, 1 pigment { image_map { ")" + test::sourcePath("examples/textures/tile.png") +
                                                 R"(" map_type 1 } } translate <0, 1, 0> }
)");
}

// Sets an environment variable for the drt processes a test starts.
struct EnvironmentSetting {
    EnvironmentSetting(const char* name, const char* value) : name_(name) { setenv(name, value, 1); }
    ~EnvironmentSetting() { unsetenv(name_); }
    const char* name_;
};

// What the dynamic loader's log says of a drt run: the id of drt's own
// process, the ids of the processes that loaded OpenImageIO, and the program
// each process started as (exec; a forked copy has none of its own).
struct Loads {
    std::string drt;
    std::set<std::string> openImageIo;
    std::map<std::string, std::string> programs;
};

Loads openImageIoLoads(const std::string& arguments) {
    Loads loads;
    std::istringstream lines(test::librariesDrtLoads(arguments));
    for (std::string line; std::getline(lines, line);) {
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string pid = line.substr(0, colon);
        pid.erase(0, pid.find_first_not_of(' '));
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        if (const size_t at = line.find("initialize program: "); at != std::string::npos) {
            const std::string program = fs::path(line.substr(at + 20)).filename().string();
            loads.programs[pid] = program;
            if (program == "drt") loads.drt = pid;
        }
        if (line.find("calling init:") != std::string::npos && line.find("/libOpenImageIO.so") != std::string::npos)
            loads.openImageIo.insert(pid);
    }
    return loads;
}

TEST(ImageProcess, ARenderReadsAndWritesTheSameBytesAsInItsOwnProcess) {
    const std::string dir = test::tempDir();
    const std::string scene = texturedScene(dir);
    for (const char* format : {"exr", "png"}) {
        const std::string viaProcess = dir + "/process." + format, inProcess = dir + "/inprocess." + format;
        const auto first = runDrt("render " + quoted(scene) + " --reproducible -q -o " + quoted(viaProcess));
        ASSERT_EQ(first.exitCode, 0) << first.err;
        {
            const EnvironmentSetting off("DRT_IMAGE_PROCESS", "0");
            const auto second = runDrt("render " + quoted(scene) + " --reproducible -q -o " + quoted(inProcess));
            ASSERT_EQ(second.exitCode, 0) << second.err;
        }
        const std::string a = test::readFile(viaProcess), b = test::readFile(inProcess);
        EXPECT_GT(a.size(), 100u);
        EXPECT_TRUE(a == b) << format << ": the files differ";
    }
}

TEST(ImageProcess, OpenImageIoLoadsInAnotherProcessUnlessSwitchedOff) {
    const std::string dir = test::tempDir();
    const std::string scene = texturedScene(dir);
    const std::string render = "render " + quoted(scene) + " -q -o " + quoted(dir + "/out.exr");
    // The image process runs the program drt_image_process (image/image_wire.h).
    const Loads separate = openImageIoLoads(render);
    ASSERT_FALSE(separate.drt.empty());
    ASSERT_EQ(separate.openImageIo.size(), 1u);
    const std::string loader = *separate.openImageIo.begin();
    EXPECT_NE(loader, separate.drt) << "OpenImageIO was loaded in drt's own process";
    EXPECT_EQ(separate.programs.count(loader) ? separate.programs.at(loader) : "(a copy of drt)", "drt_image_process");
    EXPECT_TRUE(fs::exists(dir + "/out.exr"));
    {
        // Where the program is not found, a forked copy of drt serves (the
        // same answers: the first test's bytes, and this image).
        const EnvironmentSetting missing("DRT_IMAGE_PROCESS_PROGRAM", (dir + "/no-such-program").c_str());
        fs::remove(dir + "/out.exr");
        const Loads forked = openImageIoLoads(render);
        ASSERT_EQ(forked.openImageIo.size(), 1u);
        const std::string copy = *forked.openImageIo.begin();
        EXPECT_NE(copy, forked.drt);
        EXPECT_EQ(forked.programs.count(copy), 0u) << "the copy of drt ran " << forked.programs.at(copy);
        EXPECT_TRUE(fs::exists(dir + "/out.exr"));
    }
    const EnvironmentSetting off("DRT_IMAGE_PROCESS", "0");
    const Loads same = openImageIoLoads(render);
    ASSERT_EQ(same.openImageIo.size(), 1u);
    EXPECT_EQ(same.openImageIo.count(same.drt), 1u) << "with DRT_IMAGE_PROCESS=0 drt loads it itself";
}

// The program serves only drt render: run by hand (or by a drt of another
// build, whose protocol argument differs) it refuses with status 2.
TEST(ImageProcess, TheProgramRefusesToRunByHand) {
    const std::string program = (fs::path(test::drtExecutable()).parent_path() / "drt_image_process").string();
    ASSERT_TRUE(fs::exists(program));
    for (const std::string arguments : {"", "--drt-image-process-protocol=0 3", "--drt-image-process-protocol=1 x",
                                        "--drt-image-process-protocol=1 999"}) {
        const std::string command = quoted(program) + " " + arguments + " >/dev/null 2>&1 </dev/null";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << arguments;
        EXPECT_EQ(WEXITSTATUS(status), 2) << arguments;
    }
}

// The process ending before the image is written (here on purpose, right after
// its load; a decoder's crash alike) is an I/O error naming it: no image, no
// temporary file, no silent fallback to loading the module here.
TEST(ImageProcess, ItsEndIsAnErrorThatLeavesNoFile) {
    const std::string dir = test::tempDir();
    const std::string plain = test::writeFile(dir + "/plain.drt", R"(render { width 24 height 16 samples 1 seed 3 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4>, color rgb 1 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.1> } }
)");
    const EnvironmentSetting ends("DRT_TEST_IMAGE_PROCESS_ENDS", "1");
    const auto render = runDrt("render " + quoted(plain) + " -o " + quoted(dir + "/out.png"));
    EXPECT_EQ(render.exitCode, 3) << render.err;
    EXPECT_NE(render.err.find("cannot write '" + dir + "/out.png': drt's image process (OpenImageIO) is gone: it "
                              "exited with status 3"),
              std::string::npos)
        << render.err;
    // A texture read fails the same way, before anything is rendered.
    const auto textured = runDrt("render " + quoted(texturedScene(dir)) + " -o " + quoted(dir + "/textured.png"));
    EXPECT_NE(textured.exitCode, 0);
    EXPECT_NE(textured.err.find("drt's image process (OpenImageIO) is gone"), std::string::npos) << textured.err;
    EXPECT_EQ(textured.err.find("Mrays/s"), std::string::npos) << textured.err;
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().extension(), ".drt") << entry.path() << " was left behind";
}

} // namespace
} // namespace drt
