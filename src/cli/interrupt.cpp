#include "cli/interrupt.h"

#include "core/temporary_files.h"

#include <csignal>
#include <cstring>
#include <unistd.h>

namespace drt::cli {

namespace {

std::atomic<bool> stopRequested{false};
std::atomic<bool> quitAtOnce{false}; // InterruptHandler::NothingToSave
std::atomic<int> firstSignal{0};
struct sigaction previousInt, previousTerm;

void writeMessage(const char* text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

// Only async-signal-safe calls here: atomics, write, unlink, _exit.
extern "C" void onSignal(int number) {
    if (quitAtOnce.load()) {
        makeNoMoreTemporaryFiles();
        removeRegisteredTemporaryFiles();
        writeMessage("\ndrt: interrupted before the render started: quitting, nothing to save\n");
        ::_exit(128 + number);
    }
    int none = 0;
    if (firstSignal.compare_exchange_strong(none, number)) {
        stopRequested.store(true);
        writeMessage("\ndrt: interrupted: finishing the tiles in progress, then saving the finished ones and a "
                     "checkpoint (interrupt again to quit at once)\n");
        return;
    }
    makeNoMoreTemporaryFiles();
    removeRegisteredTemporaryFiles();
    writeMessage("drt: interrupted twice: quitting at once, nothing saved\n");
    ::_exit(128 + firstSignal.load());
}

} // namespace

InterruptHandler::InterruptHandler() {
    stopRequested.store(false);
    firstSignal.store(0);
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &previousInt);
    sigaction(SIGTERM, &action, &previousTerm);
}

InterruptHandler::~InterruptHandler() {
    sigaction(SIGINT, &previousInt, nullptr);
    sigaction(SIGTERM, &previousTerm, nullptr);
}

InterruptHandler::NothingToSave::NothingToSave() { quitAtOnce.store(true); }
InterruptHandler::NothingToSave::~NothingToSave() { quitAtOnce.store(false); }

const std::atomic<bool>* InterruptHandler::flag() const { return &stopRequested; }

int InterruptHandler::signal() const { return firstSignal.load(); }

} // namespace drt::cli
