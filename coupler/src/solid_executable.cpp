#include "solid_executable.hpp"

#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "solid_parameters.hpp"

namespace cosph::coupler {

namespace fs = std::filesystem;

namespace {

const char* kField = "solid.executable";

bool is_executable_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

// Why `path` cannot be started, or "" if it can.
std::string why_not_runnable(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error)) return path.string() + " does not exist";
  if (fs::is_directory(path, error)) return path.string() + " is a folder, not a program";
  if (!fs::is_regular_file(path, error)) return path.string() + " is not a regular file";
  if (::access(path.c_str(), X_OK) != 0) return path.string() + " is not executable (chmod +x it)";
  return "";
}

fs::path case_folder(const sph::CaseFile& case_file) {
  return fs::absolute(fs::path(case_file.path)).parent_path();
}

std::string by_path(const sph::CaseFile& case_file, const std::string& name) {
  const fs::path path = (case_folder(case_file) / fs::path(name)).lexically_normal();
  const std::string reason = why_not_runnable(path);
  sph::require(reason.empty(), case_file, kField,
               "'" + name + "' (relative to the case file's folder): " + reason);
  return path.string();
}

std::string by_name(const sph::CaseFile& case_file, const std::string& name,
                    const ExecutableSearch& search) {
  std::vector<fs::path> folders;
  if (!search.bin_dir.empty()) folders.emplace_back(search.bin_dir);
  folders.push_back(case_folder(case_file));
  for (const std::string& folder : search.path_dirs) folders.emplace_back(folder);
  std::string not_executable;
  for (const fs::path& folder : folders) {
    const fs::path candidate = fs::absolute(folder / name).lexically_normal();
    if (is_executable_file(candidate)) return candidate.string();
    std::error_code error;
    if (not_executable.empty() && fs::exists(candidate, error))
      not_executable = "; found " + why_not_runnable(candidate);
  }
  std::ostringstream reason;
  reason << "no executable program '" << name << "' in the executable folder ("
         << (search.bin_dir.empty() ? std::string("none") : search.bin_dir)
         << ", COSPH_BIN), the case file's folder (" << case_folder(case_file).string()
         << ") or PATH" << not_executable;
  sph::require(false, case_file, kField, reason.str());
  return "";
}

}  // namespace

std::vector<std::string> split_search_path(const std::string& path) {
  std::vector<std::string> folders;
  std::stringstream stream(path);
  std::string folder;
  while (std::getline(stream, folder, ':'))
    if (!folder.empty()) folders.push_back(folder);
  return folders;
}

std::string solid_program(const sph::CaseFile& case_file, const ExecutableSearch& search) {
  const std::string& name = case_file.config.solid().executable();
  if (name.empty())
    return cosph::solid::model_executable(cosph::solid::read_solid_parameters(case_file).model);
  // The plan names one program per line.
  sph::require(name.find('\n') == std::string::npos, case_file, kField,
               "must not contain a line break");
  return name.find('/') != std::string::npos ? by_path(case_file, name)
                                             : by_name(case_file, name, search);
}

}  // namespace cosph::coupler
