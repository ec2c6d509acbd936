#include "sphcore/checkpoint.hpp"

#include <fcntl.h>
#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "hdf5_in_memory.hpp"
#include "sphcore/whole_file.hpp"

namespace sph {

namespace {

std::string hex64(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// FNV-1a, 64 bit: a fingerprint of the case, not a security measure.
std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string this_build() {
#ifdef NDEBUG
  const char* type = "optimised";
#else
  const char* type = "debug";
#endif
  return std::string("cosph checkpoint format ") + std::to_string(kCheckpointFormat) + ", " +
         __VERSION__ + ", " + type;
}

// Test hook (tests/case_runs/test_restart.py): with COSPH_TEST_KILL_IN_CHECKPOINT=N
// the process kills itself with SIGKILL halfway through writing its Nth
// checkpoint, as a power cut or the batch queue's kill -9 would.
bool killed_in_this_write() {
  static long writes = 0;
  const char* hook = std::getenv("COSPH_TEST_KILL_IN_CHECKPOINT");
  return hook != nullptr && ++writes == std::atol(hook);
}

void write_dataset(hid_t file, const std::string& name, const void* data, hid_t stored,
                   hid_t in_memory, std::size_t size, const std::string& path) {
  const hsize_t dims[1] = {size};
  const hid_t space = H5Screate_simple(1, dims, nullptr);
  const hid_t set =
      H5Dcreate2(file, name.c_str(), stored, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  static const double kNothing = 0.0;  // HDF5 wants a buffer even for no values
  const herr_t status = set < 0 ? -1
                                : H5Dwrite(set, in_memory, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                           size == 0 ? &kNothing : data);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (status < 0) throw std::runtime_error(path + ": cannot write checkpoint array " + name);
}

void sync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0 || ::fsync(fd) != 0) {
    if (fd >= 0) ::close(fd);
    throw std::runtime_error(path + ": cannot sync checkpoint to disk: " + std::strerror(errno));
  }
  ::close(fd);
}

template <class T>
void read_dataset(hid_t set, hid_t in_memory, std::vector<T>& values) {
  const hid_t space = H5Dget_space(set);
  hsize_t dims[1] = {0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  values.resize(dims[0]);
  T unused{};
  H5Dread(set, in_memory, H5S_ALL, H5S_ALL, H5P_DEFAULT,
          values.empty() ? &unused : static_cast<void*>(values.data()));
}

std::string sequence_text(long sequence) {
  char number[16];
  std::snprintf(number, sizeof number, "%09ld", sequence);
  return number;
}

}  // namespace

RunIdentity run_identity(const CaseFile& case_file) {
  cosph::config::Case config = case_file.config;
  config.mutable_run()->clear_end_time();
  std::string bytes;
  google::protobuf::io::StringOutputStream stream(&bytes);
  {
    google::protobuf::io::CodedOutputStream coded(&stream);
    coded.SetSerializationDeterministic(true);
    config.SerializeToCodedStream(&coded);
  }
  return {kCheckpointFormat, this_build(), hex64(fnv1a(bytes))};
}

std::string checkpoint_path(const std::string& out_dir, const std::string& name, long sequence) {
  return out_dir + "/checkpoints/" + name + "_" + sequence_text(sequence) + ".h5";
}

void Checkpoint::put(const std::string& name, std::span<const double> values) {
  reals_[name].assign(values.begin(), values.end());
}
void Checkpoint::put(const std::string& name, std::span<const Vec2> values) {
  const double* first = values.empty() ? nullptr : values.front().data();
  reals_[name].assign(first, first + 2 * values.size());
}
void Checkpoint::put(const std::string& name, std::span<const Mat2> values) {
  const double* first = values.empty() ? nullptr : values.front().data();
  reals_[name].assign(first, first + 4 * values.size());
}
void Checkpoint::put(const std::string& name, std::span<const int> values) {
  integers_[name].assign(values.begin(), values.end());
}
void Checkpoint::put(const std::string& name, std::span<const long> values) {
  integers_[name].assign(values.begin(), values.end());
}
void Checkpoint::put(const std::string& name, std::span<const std::uint8_t> values) {
  bytes_[name].assign(values.begin(), values.end());
}
void Checkpoint::put_text(const std::string& name, const std::string& text) {
  bytes_[name].assign(text.begin(), text.end());
}

const std::vector<double>& Checkpoint::reals(const std::string& name) const {
  const auto found = reals_.find(name);
  if (found == reals_.end())
    throw std::runtime_error(path_ + ": checkpoint has no float64 array " + name);
  return found->second;
}
const std::vector<std::int64_t>& Checkpoint::integers(const std::string& name) const {
  const auto found = integers_.find(name);
  if (found == integers_.end())
    throw std::runtime_error(path_ + ": checkpoint has no int64 array " + name);
  return found->second;
}
const std::vector<std::uint8_t>& Checkpoint::bytes(const std::string& name) const {
  const auto found = bytes_.find(name);
  if (found == bytes_.end())
    throw std::runtime_error(path_ + ": checkpoint has no uint8 array " + name);
  return found->second;
}

bool Checkpoint::has(const std::string& name) const {
  return reals_.count(name) || integers_.count(name) || bytes_.count(name);
}

void Checkpoint::get(const std::string& name, std::vector<double>& values) const {
  values = reals(name);
}
void Checkpoint::get(const std::string& name, std::vector<Vec2>& values) const {
  const std::vector<double>& all = reals(name);
  if (all.size() % 2 != 0) throw std::runtime_error(path_ + ": " + name + " is not 2-vectors");
  values.resize(all.size() / 2);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = Vec2(all[2 * k], all[2 * k + 1]);
}
void Checkpoint::get(const std::string& name, std::vector<Mat2>& values) const {
  const std::vector<double>& all = reals(name);
  if (all.size() % 4 != 0) throw std::runtime_error(path_ + ": " + name + " is not 2x2 tensors");
  values.resize(all.size() / 4);
  for (std::size_t k = 0; k < values.size(); ++k)
    std::memcpy(values[k].data(), all.data() + 4 * k, 4 * sizeof(double));
}
void Checkpoint::get(const std::string& name, std::vector<int>& values) const {
  const std::vector<std::int64_t>& all = integers(name);
  values.assign(all.begin(), all.end());
}
void Checkpoint::get(const std::string& name, std::vector<long>& values) const {
  const std::vector<std::int64_t>& all = integers(name);
  values.assign(all.begin(), all.end());
}
void Checkpoint::get(const std::string& name, std::vector<std::uint8_t>& values) const {
  values = bytes(name);
}

double Checkpoint::value(const std::string& name) const {
  const std::vector<double>& all = reals(name);
  if (all.size() != 1) throw std::runtime_error(path_ + ": " + name + " is not one value");
  return all.front();
}
long Checkpoint::count(const std::string& name) const {
  const std::vector<std::int64_t>& all = integers(name);
  if (all.size() != 1) throw std::runtime_error(path_ + ": " + name + " is not one value");
  return static_cast<long>(all.front());
}
std::string Checkpoint::text(const std::string& name) const {
  const std::vector<std::uint8_t>& all = bytes(name);
  return std::string(all.begin(), all.end());
}

std::string Checkpoint::write(const std::string& out_dir, const std::string& name, long sequence,
                              const RunIdentity& identity) const {
  namespace fs = std::filesystem;
  const std::string folder = out_dir + "/checkpoints";
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw std::runtime_error(folder + ": cannot create folder: " + error.message());
  const std::string path = checkpoint_path(out_dir, name, sequence);
  const std::string partial = path + ".partial";

  Checkpoint whole = *this;
  whole.put_count("format", identity.format);
  whole.put_text("build", identity.build);
  whole.put_text("case_hash", identity.case_hash);
  whole.put_count("sequence", sequence);
  const bool killed = killed_in_this_write();
  std::size_t written = 0;
  const std::size_t arrays = whole.reals_.size() + whole.integers_.size() + whole.bytes_.size();

  // Built in memory, written whole (hdf5_in_memory.hpp, whole_file.hpp).
  const hid_t file = create_in_memory(path);
  auto after_each = [&] {
    if (killed && ++written == arrays / 2) {
      // What a process killed halfway through the write leaves: a torn .partial.
      const std::string half = image_of(file, path);
      std::FILE* torn = std::fopen(partial.c_str(), "wb");
      if (torn != nullptr) {
        std::fwrite(half.data(), 1, half.size(), torn);
        std::fclose(torn);
      }
      std::raise(SIGKILL);
    }
  };
  std::string image;
  try {
    for (const auto& [key, values] : whole.reals_) {
      write_dataset(file, key, values.data(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.size(),
                    path);
      after_each();
    }
    for (const auto& [key, values] : whole.integers_) {
      write_dataset(file, key, values.data(), H5T_STD_I64LE, H5T_NATIVE_INT64, values.size(), path);
      after_each();
    }
    for (const auto& [key, values] : whole.bytes_) {
      write_dataset(file, key, values.data(), H5T_STD_U8LE, H5T_NATIVE_UINT8, values.size(), path);
      after_each();
    }
    image = image_of(file, path);
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  write_whole_file(path, image, Sync::to_disk);
  sync_path(folder, O_RDONLY | O_DIRECTORY);

  // Keep the newest two complete ones; a .partial is a write that never finished.
  std::vector<std::string> complete;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string file_name = entry.path().filename().string();
    if (file_name.rfind(name + "_", 0) != 0) continue;
    if (file_name.ends_with(".partial"))
      fs::remove(entry.path(), error);
    else if (file_name.ends_with(".h5"))
      complete.push_back(entry.path().string());
  }
  std::sort(complete.begin(), complete.end());
  for (std::size_t k = 0; k + 2 < complete.size(); ++k) fs::remove(complete[k], error);
  return path;
}

Checkpoint Checkpoint::read(const std::string& path, const RunIdentity& expected) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw ConfigError(path + ": cannot open checkpoint (missing or not HDF5)");
  Checkpoint checkpoint;
  checkpoint.path_ = path;
  H5G_info_t info;
  if (H5Gget_info(file, &info) < 0) {
    H5Fclose(file);
    throw ConfigError(path + ": cannot list the checkpoint's arrays");
  }
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    char name[256];
    if (H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name,
                           H5P_DEFAULT) < 0)
      continue;
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    if (set < 0) continue;
    const hid_t type = H5Dget_type(set);
    const H5T_class_t kind = H5Tget_class(type);
    const std::size_t size = H5Tget_size(type);
    if (kind == H5T_FLOAT)
      read_dataset(set, H5T_NATIVE_DOUBLE, checkpoint.reals_[name]);
    else if (kind == H5T_INTEGER && size == 8)
      read_dataset(set, H5T_NATIVE_INT64, checkpoint.integers_[name]);
    else if (kind == H5T_INTEGER && size == 1)
      read_dataset(set, H5T_NATIVE_UINT8, checkpoint.bytes_[name]);
    H5Tclose(type);
    H5Dclose(set);
  }
  H5Fclose(file);
  if (!checkpoint.has("format") || !checkpoint.has("build") || !checkpoint.has("case_hash"))
    throw ConfigError(path + ": not a cosph checkpoint (no format, build or case_hash)");
  if (checkpoint.count("format") != expected.format)
    throw ConfigError(path + ": checkpoint format " + std::to_string(checkpoint.count("format")) +
                      ", this build reads format " + std::to_string(expected.format));
  if (checkpoint.text("build") != expected.build)
    throw ConfigError(path + ": written by another build (" + checkpoint.text("build") +
                      "), this is " + expected.build + ": its bits would not continue the run");
  if (checkpoint.text("case_hash") != expected.case_hash)
    throw ConfigError(path + ": written for another case (hash " + checkpoint.text("case_hash") +
                      ", this case's is " + expected.case_hash +
                      "): only run.end_time may change on resume");
  return checkpoint;
}

}  // namespace sph
