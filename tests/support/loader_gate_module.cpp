// A module whose constructor blocks until released, for
// tests/thread_scratch_test.cpp. glibc runs a library's constructors inside
// dlopen with the dynamic loader's lock held, so while this one waits the lock
// is held, as it is during drt's background load of its image module.
// DRT_TEST_LOADER_GATE_FDS="E,R": the constructor writes a byte to E (it runs
// now) and then reads one from R (released). Without it, it returns at once.
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace {

[[gnu::constructor]] void holdTheLoaderLock() {
    const char* fds = std::getenv("DRT_TEST_LOADER_GATE_FDS");
    const char* comma = fds ? std::strchr(fds, ',') : nullptr;
    if (!comma) return;
    const int entered = std::atoi(fds), release = std::atoi(comma + 1);
    char byte = 1;
    if (write(entered, &byte, 1) != 1) return;
    while (read(release, &byte, 1) < 0) {
    }
}

} // namespace
