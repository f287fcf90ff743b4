// drt_image_process: the program drt render runs as its image process
// (image/image_process.h), with the protocol's argument and the number of the
// socket it answers on (image/image_wire.h). It loads the OpenImageIO module,
// sends the notice of that load and answers requests until drt closes the
// socket. Run by hand, or by a drt of another build, it refuses (status 2).
//
// Why a program and not the forked copy of drt that serves otherwise: the
// dynamic loader looks each of the module's ~170,000 symbols up in the
// program's own libraries first; drt has a score of them, this program only
// the C and C++ runtimes (docs/performance.md, "The image process as a
// program of its own").
#include "image/image_wire.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>

int main(int argc, char** argv) {
    const char* const name = "drt_image_process";
    if (argc != 3 || std::strcmp(argv[1], drt::image_wire::kProtocol) != 0) {
        std::fprintf(stderr, "%s: drt render runs this program itself (expected %s and a socket)\n", name,
                     drt::image_wire::kProtocol);
        return 2;
    }
    char* end = nullptr;
    const long fd = std::strtol(argv[2], &end, 10);
    if (end == argv[2] || *end != '\0' || fd < 0 || fd > 1 << 20 || ::fcntl(int(fd), F_GETFD) < 0) {
        std::fprintf(stderr, "%s: '%s' is not an open socket\n", name, argv[2]);
        return 2;
    }
    ::fcntl(int(fd), F_SETFD, FD_CLOEXEC); // not passed on to anything the module starts
    drt::image_wire::serve(int(fd), drt::imageIoInThisProcess());
}
