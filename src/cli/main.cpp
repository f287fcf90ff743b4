// The drt executable: a thin layer over the library (see cli/app.h).
#include "cli/app.h"

int main(int argc, char** argv) {
    return drt::cli::runCommandLine(argc, argv);
}
