// The output folder's lock, DIR/.cosph.lock, the one coupler/cosph takes
// (coupler/cosph_launcher/output_dir.py): one run writes into a folder at a
// time, and whichever run comes second is refused with a message naming the
// first (docs/restart.md, "What is guaranteed about the output folder").
#pragma once

#include <string>

namespace sph {

// The environment variable by which the launcher hands its children its open
// lock: the number of the inherited file descriptor.
inline constexpr const char* kOutputLockFdVariable = "COSPH_OUT_LOCK_FD";

// Takes DIR/.cosph.lock (flock) for as long as this process lives; throws
// ConfigError naming the run that holds it ("pid N, started T: COMMAND").
//
// - Started by the launcher: it passed its own lock (kOutputLockFdVariable).
//   The folder is this run's already; the inherited descriptor keeps the lock
//   while any process of the run lives, the launcher or one of its children.
// - A coupled process started by hand (endpoint given; docs/coupling.md,
//   "Two hosts"): the coupler and a solver of one run may share a folder, so
//   the processes of one run hold the lock shared, and know each other by
//   their endpoint, which the first of them writes into the file.
// - A solver alone started by hand holds it exclusively, as the launcher does.
// `command`: this process's command line, for the message another run gets.
void lock_output_dir(const std::string& dir, const std::string& endpoint,
                     const std::string& command);

// argv joined with spaces, an argument with a space or quote in single quotes.
std::string command_line(int argc, char** argv);

}  // namespace sph
