// An HDF5 file built in memory and taken out as bytes, for the files that are
// written whole or not at all (whole_file.hpp). HDF5 writing to a full disk
// itself left a file it could not close, and the library crashed at exit
// (in H5F__close_cb) closing it again.
#pragma once

#include <hdf5.h>

#include <string>

namespace sph {

// A new HDF5 file in memory (the core driver, no backing file); `path` names
// it in errors. Throws std::runtime_error if it cannot be made.
hid_t create_in_memory(const std::string& path);

// The bytes of the file as it is now, to be written to disk.
std::string image_of(hid_t file, const std::string& path);

}  // namespace sph
