#include "bench/process.h"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <mutex>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace drt::bench {

namespace {

double seconds(const timeval& t) {
    return double(t.tv_sec) + double(t.tv_usec) * 1e-6;
}

// Reads what the child wrote to the (unlinked) capture file.
std::string readAll(int fd) {
    std::string text;
    if (lseek(fd, 0, SEEK_SET) < 0)
        return text;
    char buffer[65536];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;)
        text.append(buffer, size_t(n));
    return text;
}

} // namespace

ProcessRun runProcess(const std::vector<std::string>& argv, const std::string& workingDir,
                      const std::vector<std::string>& environment, double timeoutSeconds) {
    ProcessRun run;
    if (argv.empty()) {
        run.output = "no program given";
        return run;
    }
    // The output goes to an anonymous temporary file rather than a pipe, so a
    // chatty child never blocks and the parent needs no reader thread.
    char capturePath[] = "/tmp/drt-process-XXXXXX";
    const int capture = mkstemp(capturePath);
    if (capture < 0) {
        run.output = std::string("cannot create a capture file: ") + std::strerror(errno);
        return run;
    }
    unlink(capturePath);

    std::vector<char*> args;
    for (const std::string& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    // The child's environment is built here: between fork and exec only
    // async-signal-safe calls are allowed, and putenv may allocate.
    std::vector<std::string> environmentText;
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        const std::string name = entry.substr(0, entry.find('='));
        bool overridden = false;
        for (const std::string& added : environment)
            overridden |= added.substr(0, added.find('=')) == name;
        if (!overridden)
            environmentText.push_back(entry);
    }
    environmentText.insert(environmentText.end(), environment.begin(), environment.end());
    std::vector<char*> envp;
    for (std::string& entry : environmentText)
        envp.push_back(entry.data());
    envp.push_back(nullptr);

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        run.output = std::string("fork failed: ") + std::strerror(errno);
        close(capture);
        return run;
    }
    if (pid == 0) {
        // Child: only async-signal-safe calls until exec.
        const int devNull = open("/dev/null", O_RDONLY);
        if (devNull >= 0)
            dup2(devNull, 0);
        dup2(capture, 1);
        dup2(capture, 2);
        if (!workingDir.empty() && chdir(workingDir.c_str()) != 0) {
            const char message[] = "cannot enter the working folder\n";
            (void)!write(2, message, sizeof message - 1);
            _exit(127);
        }
        execvpe(args[0], args.data(), envp.data());
        const char message[] = "cannot execute the program\n";
        (void)!write(2, message, sizeof message - 1);
        _exit(127);
    }
    // The watchdog kills the child at the deadline unless it ended first.
    std::mutex mutex;
    std::condition_variable ended;
    bool done = false, killed = false;
    std::thread watchdog;
    if (timeoutSeconds > 0)
        watchdog = std::thread([&] {
            std::unique_lock lock(mutex);
            if (!ended.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [&] { return done; })) {
                kill(pid, SIGKILL);
                killed = true;
            }
        });
    // Wait for the end without reaping, so the pid cannot be reused while the
    // watchdog may still send its signal; then stop the watchdog and reap.
    siginfo_t info{};
    while (waitid(P_PID, id_t(pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
    }
    if (watchdog.joinable()) {
        {
            std::lock_guard lock(mutex);
            done = true;
        }
        ended.notify_one();
        watchdog.join();
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR)
            break;
    }
    run.timedOut = killed;
    run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.started = true;
    run.userSeconds = seconds(usage.ru_utime);
    run.systemSeconds = seconds(usage.ru_stime);
    run.peakRssMiB = double(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
    if (WIFEXITED(status)) {
        run.exitCode = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        run.signal = WTERMSIG(status);
    }
    run.output = readAll(capture);
    close(capture);
    if (run.exitCode == 127 && run.output.find("cannot execute the program") != std::string::npos)
        run.started = false;
    return run;
}

std::string currentExecutable() {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : self.string();
}

} // namespace drt::bench
