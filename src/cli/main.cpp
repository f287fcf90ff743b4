// The drt executable: a thin layer over the library (see cli/app.h).
#include "cli/app.h"
#include "core/temporary_files.h"

int main(int argc, char** argv) {
    // SIGTERM / SIGINT while an output is being written leave no temporary file.
    drt::removeTemporaryFilesOnSignal();
    return drt::cli::runCommandLine(argc, argv);
}
