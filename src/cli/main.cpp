// The drt executable: a thin layer over the library (see cli/app.h).
#include "cli/app.h"
#include "core/temporary_files.h"
#include "image/image_process.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define DRT_NORMAL_EXIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define DRT_NORMAL_EXIT 1
#endif
#endif

int main(int argc, char** argv) {
    // SIGTERM / SIGINT while an output is being written leave no temporary file.
    drt::removeTemporaryFilesOnSignal();
    // drt render may do its image operations in a process of its own
    // (image/image_process.h); waited for before leaving, so that its CPU
    // time counts in drt's.
    drt::allowImageIoProcess();
    const int status = drt::cli::runCommandLine(argc, argv);
    drt::endImageIoProcess();
#if defined(DRT_NORMAL_EXIT)
    return status;
#else
    // Everything drt writes is closed by now (the command's objects, MPI
    // included, end inside runCommandLine): leave without the static
    // destructors of the ~260 libraries the image module brought in, about
    // 6 ms of a render's fixed time (docs/performance.md). A sanitizer's build
    // keeps the normal exit, whose handlers report.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(status);
#endif
}
