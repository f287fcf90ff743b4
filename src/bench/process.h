// Runs another program and measures it as a user would: the wall time of the
// whole process (start-up, parsing and writing included), its CPU time (user +
// system, over all its threads) and its peak resident memory, from wait4's
// rusage. The instruments of tests/benchmarks time drt and POV-Ray this way so
// that both pay the same costs.
#pragma once

#include <string>
#include <vector>

namespace drt::bench {

struct ProcessRun {
    bool started = false;   // false: fork or exec failed (`output` says why)
    int exitCode = -1;      // the exit status, or -1 if killed by a signal
    int signal = 0;         // the signal that ended it, if any
    double wallSeconds = 0; // from just before fork to the end of wait4
    double userSeconds = 0, systemSeconds = 0;
    double peakRssMiB = 0; // ru_maxrss of the child
    bool timedOut = false; // killed (SIGKILL) after the time limit
    std::string output;    // its stdout and stderr, interleaved
    double cpuSeconds() const { return userSeconds + systemSeconds; }
    bool succeeded() const { return started && exitCode == 0; }
};

// Runs argv[0] (looked up in PATH if it has no '/') with the arguments in
// `argv`, in `workingDir` ("" = the current folder), with stdin from /dev/null
// and stdout + stderr captured. `environment` entries "NAME=value" are added
// to the current environment. With `timeoutSeconds` > 0 the program is killed
// once it runs that long. Never throws for a failing program.
ProcessRun runProcess(const std::vector<std::string>& argv, const std::string& workingDir = "",
                      const std::vector<std::string>& environment = {}, double timeoutSeconds = 0);

// The absolute path of the running executable (/proc/self/exe), or "".
std::string currentExecutable();

} // namespace drt::bench
