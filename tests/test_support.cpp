#include "test_support.h"

#include "assets/assets.h"
#include "lang/load.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt::test {

Scene withAssets(Scene scene) {
    Diagnostics diags;
    if (!resolveAssets(scene, diags)) ADD_FAILURE() << diags.formatAll();
    return scene;
}

std::string drtExecutable() { return DRT_EXECUTABLE; }

std::string sourcePath(const std::string& relative) { return (fs::path(DRT_SOURCE_DIR) / relative).string(); }

std::string tempDir() {
    static std::atomic<int> counter{0};
    fs::path dir = fs::temp_directory_path() /
                   ("drt-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

std::string writeFile(const std::string& path, const std::string& text) {
    fs::path p(path);
    if (p.has_parent_path()) fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return path;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

CommandResult runDrt(const std::string& arguments) {
    const std::string dir = tempDir();
    const std::string outPath = dir + "/stdout.txt", errPath = dir + "/stderr.txt";
    const std::string command =
        std::string("'") + DRT_EXECUTABLE + "' " + arguments + " >'" + outPath + "' 2>'" + errPath + "' </dev/null";
    const int status = std::system(command.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readFile(outPath);
    r.err = readFile(errPath);
    fs::remove_all(dir);
    return r;
}

std::string librariesDrtLoads(const std::string& arguments) {
    const std::string dir = tempDir();
    const std::string command = "env LD_DEBUG=libs LD_DEBUG_OUTPUT='" + dir + "/ld' '" + DRT_EXECUTABLE + "' " +
                                arguments + " >/dev/null 2>&1 </dev/null";
    (void)std::system(command.c_str());
    std::string listing;
    for (const auto& entry : fs::directory_iterator(dir)) listing += readFile(entry.path().string());
    fs::remove_all(dir);
    return listing;
}

std::unique_ptr<SceneRun> readSceneText(const std::string& text, bool pov, const PovOptions& options) {
    auto r = std::make_unique<SceneRun>();
    if (pov) r->scene = loadPovSceneText(text, "t.pov", r->diags, options);
    else r->scene = loadSceneText(text, "t.drt", r->diags);
    for (const Diagnostic& d : r->diags.all())
        if (d.message.rfind("#warning: ", 0) == 0) r->messages.push_back(d.message.substr(10));
    return r;
}

const Diagnostic* expectErrorAt(const Diagnostics& diags, const std::string& file, int line, int column,
                                const std::string& message) {
    const std::string text = diags.formatAll();
    const auto& all = diags.all();
    const auto error = std::find_if(all.begin(), all.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
    EXPECT_NE(error, all.end()) << "no error; diagnostics:\n" << text;
    if (error == all.end()) return nullptr;
    EXPECT_EQ(error->message, message) << file;
    EXPECT_EQ(error->loc.line, line) << file;
    EXPECT_EQ(error->loc.column, column) << file;
    const std::string where = file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: ";
    EXPECT_NE(text.find(where), std::string::npos) << text;
    EXPECT_NE(text.find("\n  " + std::string(size_t(std::max(column - 1, 0)), ' ') + "^\n"), std::string::npos) << text;
    return &*error;
}

} // namespace drt::test
