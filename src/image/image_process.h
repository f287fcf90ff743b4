// drt render's image process: the OpenImageIO module loaded in a process of
// its own, forked when the render starts, which does the render's image
// operations (image/image_io_module.h's table, each call sent over a socket
// pair and answered: image/image_wire.h). The forked process runs the program
// drt_image_process (found beside drt, in ../lib/drt, or in the build tree;
// $DRT_IMAGE_PROCESS_PROGRAM names it), whose own libraries are only the C
// and C++ runtimes, so the module's symbols are looked up faster; where it is
// not found, the forked copy of drt serves itself, with the same code.
//
// Why a process: loading Debian's OpenImageIO is most of a short render's
// fixed cost (about 0.14 s of CPU, ~260 libraries). Loaded in the rendering
// process, on a thread beside the render, it cost more (0.18 s): each of the
// loader's mprotect and munmap calls interrupts the rendering cores to flush
// their TLBs, and it could start only once the render's threads had (dlopen
// holds the loader's lock, which starting a thread waits for). In a process of
// its own it starts at once, while the scene is parsed, and disturbs nothing.
// The images are the same bytes; only where the module runs changes.
//
// The process is used only where it is safe and pays: started by the drt
// executable (allowImageIoProcess) from a process that still has one thread,
// never under an MPI launcher (Open MPI does not support fork), and not when
// DRT_IMAGE_PROCESS is 0. Otherwise everything runs in this process as
// before. If the process ends early (killed, crashed in a decoder), every
// later image operation fails with a message saying so: nothing is written
// half, and nothing falls back silently.
#pragma once

#include "core/modules.h"
#include "image/image_io_module.h"

#include <string>

namespace drt {

// Lets this process start an image process (the drt executable calls it).
void allowImageIoProcess();

// Starts the image process if allowed, this process has one thread, and
// DRT_IMAGE_PROCESS is not 0; it begins loading the module at once. Returns
// true if one runs (started now or before).
bool startImageIoProcess();

// Whether an image process was started.
bool imageIoProcessStarted();

// The module as the image process offers it: its load's outcome (waiting for
// it) with a table whose calls go to the process. nullptr if none was started.
const LoadedModule<ImageIoModule>* imageIoProcessModule();

// True until the image process has said its load ended (never waits).
bool imageIoProcessLoading();

// Says that this process's last image operation is done: the image process
// leaves now, while this one still tidies up (endImageIoProcess waits for
// it). An image operation after it fails, saying the process has ended.
// Nothing if none runs or its load has not ended (endImageIoProcess stops
// such a load).
void releaseImageIoProcess();

// Ends the image process and waits for it, so that its CPU time counts in
// this process's (what `time` and the benchmarks read). Nothing if none runs.
void endImageIoProcess();

} // namespace drt
