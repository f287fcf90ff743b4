// The drt command line: CLI11 set-up and dispatch to the subcommands of
// cli/commands.h. main() only calls runCommandLine.
#pragma once

namespace drt::cli {

// Parses argv and runs the chosen subcommand; returns the process exit status.
int runCommandLine(int argc, char** argv);

} // namespace drt::cli
