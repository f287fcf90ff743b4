// The limits that keep every stage bounded on any input: a scene from the
// internet, a fuzzer's garbage or a mistake must end in a located error that
// names the limit, never in a hang, a crash or all of the machine's memory.
// Each limit has a name, a default and a ceiling; `--limit NAME=VALUE` on the
// command line raises or lowers it (docs/limits.md lists them all).
//
// The front ends reach the limits through Diagnostics::limits(), the renderer
// and the command line through defaultLimits(); each breach is reported with
// limitExceeded(), which names the limit and how to raise it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace drt {

struct Limits {
    // ---- front ends
    int64_t includeDepth = 64;             // #include files open at once
    int64_t includeBytes = 64 << 20;       // bytes of one #include'd file
    int64_t callDepth = 400;               // POV-Ray macro calls and includes nested at once
    int64_t nestingDepth = 200;            // blocks and expressions nested in each other
    int64_t loopIterations = 10'000'000;   // passes of one #while / #for loop
    int64_t passesAndCalls = 10'000'000;   // passes of all loops and macro calls, in the whole read
    int64_t objects = 4'000'000;           // objects in a scene, CSG members and copies counted
    int64_t memoryMB = 8192;               // resident memory while a scene is read
    int64_t stringLength = 1 << 20;        // characters of one string value
    int64_t arrayElements = 10'000'000;    // elements of one array (POV-Ray)
    int64_t meshTriangles = 50'000'000;    // triangles of one mesh (POV-Ray mesh2, height fields)
    int64_t errors = 50;                   // errors printed per run, then "N more errors"
    int64_t quotedLine = 160;              // characters of a source line quoted under an error
    // ---- scene values that become counts
    int64_t areaLightSamples = 65'536;     // samples of one area light's grid (n1 * n2)
    int64_t traceLevel = 256;              // max_trace_level (recursion of reflection and refraction)
    int64_t mediaIntervals = 4096;         // intervals, samples of one media
    // ---- command line and renderer
    int64_t imageMemoryMB = 16'384;        // memory the film and the written image may take
    int64_t threads = 1024;                // worker threads
};

// The limits every Diagnostics (so every front end) and every render starts
// with: the defaults above, or what the command line's --limit set.
const Limits& defaultLimits();
void setDefaultLimits(const Limits& limits);

// One row of the limits table: its command-line name, where it lives, the
// ceiling that keeps even a raised value safe (a stack or a 32-bit count), and
// what it bounds.
struct LimitInfo {
    const char* name;
    int64_t Limits::*field;
    int64_t ceiling;
    const char* what;
};
const std::vector<LimitInfo>& limitTable();
const LimitInfo& limitInfo(int64_t Limits::*field);

// Parses "NAME=VALUE" (VALUE an integer, optionally with a k, M or G suffix)
// into `limits`. Returns "" or the reason it is refused.
std::string setLimit(Limits& limits, std::string_view assignment);

// The tail of every limit error: "(limit NAME = VALUE; raise it with --limit NAME=N)".
std::string limitHint(const Limits& limits, int64_t Limits::*field);

// The whole message for a value over a limit: "<what> <value> is over the limit ...".
std::string limitExceeded(const Limits& limits, int64_t Limits::*field, std::string_view what, double value);

// A float that a scene gives as a count or an index, checked before it is
// converted to an int by truncation toward zero: it must be finite and its
// whole part in [lowest, highest]. Returns "" or the message for a located error, e.g.
// "polygon point count 1e+10 is out of range (3 to 10000000)".
std::string checkCount(std::string_view what, double value, double lowest, double highest);

// Bytes of memory the process has resident now (/proc/self/statm; 0 if unknown).
uint64_t residentBytes();

// "" while the process's resident memory is within Limits::memoryMB, else the message for a located
// error ("the scene takes 8200 MB while it is read, over the limit ...").
std::string checkMemory(const Limits& limits);

// A float as a 64-bit integer where converting it directly would be undefined
// behaviour: NaN gives 0 and values beyond +-2^62 saturate there (used by the
// patterns, whose lattice cells a 1e-20 scale sends out of any integer's range;
// so far out a double has no fraction left, so the cell is the value itself).
inline long long saturatingInteger(double value) {
    constexpr double kLargest = 4611686018427387904.0; // 2^62
    if (!(value == value)) return 0;
    return static_cast<long long>(value < -kLargest ? -kLargest : value > kLargest ? kLargest : value);
}

// The number of bytes `count` elements of `size` bytes take, saturating
// instead of overflowing.
uint64_t saturatingBytes(uint64_t count, uint64_t size);

} // namespace drt
