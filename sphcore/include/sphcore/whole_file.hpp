// Files that are written whole or not at all: a disk that fills, a file-size
// limit or a kill mid-write must leave the previous version (or none), never
// a torn one, and no temporary file behind.
#pragma once

#include <string>

namespace sph {

// Writes `text` to PATH.partial, checks every write and the close (where a
// full disk shows), and renames it over `path`. On any failure removes
// PATH.partial, leaves `path` as it was, and throws std::runtime_error naming
// the file and the reason. With Sync::to_disk the file is fsync'ed before
// the rename, so that a power cut cannot leave it empty under its name: for
// checkpoints, which a resume relies on; snapshots and indexes skip it (some
// 3 ms a file here, 5 % of a dam break that writes 41 snapshots).
enum class Sync { to_system, to_disk };
void write_whole_file(const std::string& path, const std::string& text,
                      Sync sync = Sync::to_system);

// The reason of the last failed system call, for a message ("No space left on device").
std::string system_reason(int error_number);

}  // namespace sph
