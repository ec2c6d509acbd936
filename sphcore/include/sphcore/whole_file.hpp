// Files that are written whole or not at all: a disk that fills, a file-size
// limit or a kill mid-write must leave the previous version (or none), never
// a torn one, and no temporary file behind.
#pragma once

#include <string>

namespace sph {

// Writes `text` to PATH.partial, flushes it to disk, checks every step, and
// renames it over `path`. On any failure removes PATH.partial, leaves `path`
// as it was, and throws std::runtime_error naming the file and the reason.
void write_whole_file(const std::string& path, const std::string& text);

// The reason of the last failed system call, for a message ("No space left on device").
std::string system_reason(int error_number);

}  // namespace sph
