#include "hdf5_in_memory.hpp"

#include <stdexcept>

namespace sph {

hid_t create_in_memory(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(access, 1 << 20, 0);  // grown in 1 MiB steps, no backing file
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
  H5Pclose(access);
  if (file < 0) throw std::runtime_error(path + ": cannot create HDF5 file in memory");
  return file;
}

std::string image_of(hid_t file, const std::string& path) {
  const ssize_t size =
      H5Fflush(file, H5F_SCOPE_GLOBAL) < 0 ? -1 : H5Fget_file_image(file, nullptr, 0);
  std::string image(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if (size < 0 || H5Fget_file_image(file, image.data(), image.size()) != size)
    throw std::runtime_error(path + ": cannot build HDF5 file");
  return image;
}

}  // namespace sph
