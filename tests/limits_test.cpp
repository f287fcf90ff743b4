// The limits of core/limits.h and the bounded diagnostics and file reading
// built on them: every bad input ends in a clear error, never a hang.
#include "core/diagnostics.h"
#include "core/limits.h"
#include "core/source_file.h"
#include "core/temporary_files.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sys/stat.h>
#include <unistd.h>

namespace drt {
namespace {

namespace fs = std::filesystem;

TEST(Limits, SetLimitParsesNamesValuesAndSuffixes) {
    Limits limits;
    EXPECT_EQ(setLimit(limits, "objects=12"), "");
    EXPECT_EQ(limits.objects, 12);
    EXPECT_EQ(setLimit(limits, "loop_iterations=3k"), "");
    EXPECT_EQ(limits.loopIterations, 3000);
    EXPECT_EQ(setLimit(limits, "passes_and_calls=2G"), "");
    EXPECT_EQ(limits.passesAndCalls, 2'000'000'000);
    EXPECT_EQ(setLimit(limits, "memory_mb=2k"), "");
    EXPECT_EQ(limits.memoryMB, 2000);
    EXPECT_EQ(setLimit(limits, "objects=1G"), "");
    EXPECT_EQ(limits.objects, 1'000'000'000);
    EXPECT_NE(setLimit(limits, "memory_mb=2G").find("not a whole number from 1 to"), std::string::npos);
    EXPECT_EQ(setLimit(limits, "objects=12"), "");
    EXPECT_NE(setLimit(limits, "objects").find("NAME=VALUE"), std::string::npos);
    EXPECT_NE(setLimit(limits, "objects=0").find("not a whole number from 1 to"), std::string::npos);
    EXPECT_NE(setLimit(limits, "objects=-5").find("not a whole number"), std::string::npos);
    EXPECT_NE(setLimit(limits, "objects=1.5").find("not a whole number"), std::string::npos);
    EXPECT_NE(setLimit(limits, "trace_level=257").find("from 1 to 256"), std::string::npos);
    const std::string unknown = setLimit(limits, "objcts=5");
    EXPECT_NE(unknown.find("no limit is called 'objcts'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("objects"), std::string::npos) << unknown; // lists the real names
    EXPECT_EQ(limits.objects, 12); // a refused value changes nothing
}

TEST(Limits, EveryLimitHasADistinctNameAndADefaultWithinItsCeiling) {
    const Limits defaults;
    std::vector<std::string> names;
    for (const LimitInfo& info : limitTable()) {
        EXPECT_GE(defaults.*info.field, 1) << info.name;
        EXPECT_LE(defaults.*info.field, info.ceiling) << info.name;
        EXPECT_EQ(std::count(names.begin(), names.end(), info.name), 0) << info.name;
        names.push_back(info.name);
    }
    EXPECT_EQ(names.size(), sizeof(Limits) / sizeof(int64_t)); // every field is in the table
}

TEST(Limits, MessagesNameTheLimitAndHowToRaiseIt) {
    Limits limits;
    limits.objects = 10;
    EXPECT_EQ(limitExceeded(limits, &Limits::objects, "the object count", 11),
              "the object count 11 is over the limit of 10 (limit objects = 10; raise it with --limit objects=N)");
    EXPECT_EQ(checkCount("array index", 1e10, 0, 2), "array index 10000000000 is out of range (0 to 2)");
    EXPECT_EQ(checkCount("seed", 1e30, 0, 2), "seed 1e+30 is out of range (0 to 2)");
    EXPECT_EQ(checkCount("array index", 2.9, 0, 2), ""); // truncated toward zero, as POV-Ray does
    EXPECT_NE(checkCount("count", std::nan(""), 0, 2), "");
    EXPECT_NE(checkCount("count", -std::numeric_limits<double>::infinity(), 0, 2), "");
}

TEST(Limits, SaturatingConversionsNeverOverflow) {
    EXPECT_EQ(saturatingInteger(1e300), 4611686018427387904LL);
    EXPECT_EQ(saturatingInteger(-1e300), -4611686018427387904LL);
    EXPECT_EQ(saturatingInteger(std::nan("")), 0);
    EXPECT_EQ(saturatingInteger(-3.0), -3);
    EXPECT_EQ(saturatingBytes(uint64_t(1) << 40, uint64_t(1) << 40), std::numeric_limits<uint64_t>::max());
    EXPECT_EQ(saturatingBytes(1000, 28), 28000u);
}

TEST(Limits, MemoryCheckNamesTheLimit) {
    Limits limits;
    EXPECT_EQ(checkMemory(limits), ""); // a test process is far below 8 GB
    limits.memoryMB = 1;
    const std::string problem = checkMemory(limits);
    EXPECT_NE(problem.find("over the limit of 1 MB"), std::string::npos) << problem;
    EXPECT_NE(problem.find("--limit memory_mb=N"), std::string::npos) << problem;
}

TEST(Diagnostics, ErrorsPastTheLimitAreCountedNotPrinted) {
    Diagnostics diags;
    Limits limits;
    limits.errors = 3;
    diags.setLimits(limits);
    const int file = diags.files().add("x.drt", "a\n");
    for (int i = 0; i < 10; ++i) {
        diags.error({file, 1, 1}, "bad " + std::to_string(i));
        diags.note({file, 1, 1}, "about " + std::to_string(i));
    }
    EXPECT_EQ(diags.errorCount(), 10);
    const std::string text = diags.formatAll();
    EXPECT_NE(text.find("bad 2"), std::string::npos);
    EXPECT_EQ(text.find("bad 3"), std::string::npos);
    EXPECT_EQ(text.find("about 3"), std::string::npos); // a dropped error's note goes with it
    EXPECT_NE(text.find("drt: 7 more errors not shown (limit errors = 3; raise it with --limit errors=N)"),
              std::string::npos)
        << text;
}

TEST(Diagnostics, ALongLineIsQuotedAsAWindowAroundTheColumn) {
    Diagnostics diags;
    std::string line(2'000'000, 'a');
    line.replace(1'000'000, 5, "WRONG");
    const int file = diags.files().add("long.drt", line + "\n");
    diags.error({file, 1, 1'000'001}, "unexpected 'WRONG'");
    const std::string text = diags.formatAll();
    EXPECT_LT(text.size(), 600u);
    EXPECT_NE(text.find("long.drt:1:1000001: error: unexpected 'WRONG'"), std::string::npos) << text;
    // The caret sits under the W of the quoted window.
    const size_t quoted = text.find("  ...");
    ASSERT_NE(quoted, std::string::npos) << text;
    const size_t lineEnd = text.find('\n', quoted);
    const size_t caret = text.find('^', lineEnd);
    ASSERT_NE(caret, std::string::npos);
    EXPECT_EQ(text[quoted + (caret - lineEnd - 1)], 'W') << text;
}

TEST(Diagnostics, LinesOfAFileThatIsNoSceneAreNeverQuoted) {
    Diagnostics diags;
    const int file = diags.files().add("/etc/passwd", "root:x:0:0:root:/root:/bin/bash\n", false);
    diags.error({file, 1, 1}, "expected a statement");
    const std::string text = diags.formatAll();
    EXPECT_NE(text.find("/etc/passwd:1:1: error: expected a statement"), std::string::npos);
    EXPECT_EQ(text.find("/bin/bash"), std::string::npos) << text;
}

TEST(SourceFile, ReadsOnlyRegularFilesWithinTheSizeLimit) {
    std::string text;
    EXPECT_NE(readSourceFile("/dev/zero", 1 << 20, text).find("not a regular file (a device)"), std::string::npos);
    const std::string dir = test::tempDir();
    EXPECT_NE(readSourceFile(dir, 1 << 20, text).find("not a regular file (a folder)"), std::string::npos);
    const std::string fifo = dir + "/pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(readSourceFile(fifo, 1 << 20, text).find("not a regular file (a pipe)"), std::string::npos);
    const std::string big = test::writeFile(dir + "/big.inc", std::string(5000, ' '));
    const std::string tooBig = readSourceFile(big, 4096, text);
    EXPECT_NE(tooBig.find("is 5000 bytes, over the limit of 4096"), std::string::npos) << tooBig;
    EXPECT_NE(tooBig.find("--limit include_bytes=N"), std::string::npos) << tooBig;
    EXPECT_EQ(readSourceFile(big, -1, text), "");
    EXPECT_EQ(text.size(), 5000u);
    EXPECT_NE(readSourceFile(dir + "/none", -1, text).find("No such file"), std::string::npos);
    fs::remove_all(dir);
}

TEST(SourceFile, AByteOrderMarkIsDropped) {
    const std::string dir = test::tempDir();
    std::string text;
    EXPECT_EQ(readSourceFile(test::writeFile(dir + "/bom.drt", "\xEF\xBB\xBFsphere"), -1, text), "");
    EXPECT_EQ(text, "sphere");
    EXPECT_TRUE(hasSceneExtension("a/b.DRT"));
    EXPECT_TRUE(hasSceneExtension("colors.inc"));
    EXPECT_FALSE(hasSceneExtension("/etc/passwd"));
    EXPECT_FALSE(hasSceneExtension("x.inc/passwd"));
    fs::remove_all(dir);
}

TEST(TemporaryFiles, RegisteredFilesAreRemovedAndUnregisteredOnesKept) {
    const std::string dir = test::tempDir();
    const std::string kept = test::writeFile(dir + "/kept", "x");
    {
        const TemporaryFile done(dir + "/done");
    } // unregistered: a later signal must not touch a name that may be reused
    test::writeFile(dir + "/done", "x");
    const std::string writing = test::writeFile(dir + "/.out.png.tmp", "partial");
    {
        const TemporaryFile registered(writing);
        removeRegisteredTemporaryFiles(); // what the signal handler does first
        EXPECT_FALSE(fs::exists(writing));
    }
    EXPECT_TRUE(fs::exists(kept));
    EXPECT_TRUE(fs::exists(dir + "/done"));
    fs::remove_all(dir);
}

// A signal handled on one thread while another writes an output: the writer may
// make its temporary file after the handler's first unlink. The removal waits
// for the writer to finish (rename or give up) before it returns, so nothing
// is left behind. With no wait, the file made after the unlink stays.
TEST(TemporaryFiles, RemovalWaitsForAWriterOnAnotherThread) {
    const std::string dir = test::tempDir();
    const std::string temporary = dir + "/.out.png.tmp", final = dir + "/out.png";
    std::atomic<bool> registered{false}, removalStarted{false}, writerDone{false};
    std::thread writer([&] {
        {
            const TemporaryFile file(temporary);
            registered.store(true);
            while (!removalStarted.load()) std::this_thread::yield();
            std::this_thread::sleep_for(std::chrono::milliseconds(100)); // the handler's unlink comes first
            test::writeFile(temporary, "whole image");
            fs::rename(temporary, final);
        }
        writerDone.store(true);
    });
    while (!registered.load()) std::this_thread::yield();
    removalStarted.store(true);
    removeRegisteredTemporaryFiles();
    EXPECT_TRUE(writerDone.load()) << "the removal returned while another thread was still writing";
    writer.join();
    EXPECT_FALSE(fs::exists(temporary));
    EXPECT_TRUE(fs::exists(final));
    fs::remove_all(dir);
}

} // namespace
} // namespace drt
