#include "sphcore/solver_cli.hpp"

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>

#include "sphcore/case_file.hpp"

namespace sph {

SolverArgs parse_solver_args(int argc, char** argv, const std::string& program,
                             const std::string& summary) {
  const std::string usage =
      "usage: " + program +
      " --case FILE --out DIR [--set FIELD=VALUE ...] [--endpoint E] [--resume FILE]"
      " [--keys FILE] [--coupler-key FILE] [--allow-key FILE ...] [--bind-any]";
  SolverArgs args;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      std::cout
          << usage << "\n\n"
          << summary << "\n\n"
          << "  --case FILE          case file (protobuf text format, proto/case.proto)\n"
          << "  --out DIR            output folder (created if missing)\n"
          << "  --set FIELD=VALUE    override a case field, e.g. fluid.spacing=0.004\n"
          << "  --endpoint E         coupler endpoint (ipc:// or tcp://); none: run alone\n"
          << "  --resume FILE        continue from this checkpoint (docs/restart.md)\n"
          << "  --keys FILE          this process's CURVE key pair (cosph-keys), over tcp://\n"
          << "  --coupler-key FILE   a solver: the coupler's public key, over tcp://\n"
          << "  --allow-key FILE     the coupler: a solver's public key; one per solver\n"
          << "  --bind-any           the coupler: listen on a wildcard address such as\n"
          << "                       tcp://0.0.0.0:PORT (every network interface)\n"
          << "\nUsually started by the launcher: coupler/cosph run CASE --out DIR\n";
      std::exit(0);
    }
    if (option == "--bind-any") {
      args.bind_any = true;
      continue;
    }
    if (i + 1 >= argc) throw ConfigError(program + ": " + option + " needs a value\n" + usage);
    const std::string value = argv[++i];
    if (option == "--case")
      args.case_path = value;
    else if (option == "--out")
      args.out_dir = value;
    else if (option == "--set")
      args.overrides.push_back(value);
    else if (option == "--endpoint")
      args.endpoint = value;
    else if (option == "--resume")
      args.resume_from = value;
    else if (option == "--keys")
      args.key_file = value;
    else if (option == "--coupler-key")
      args.coupler_key_file = value;
    else if (option == "--allow-key")
      args.allowed_key_files.push_back(value);
    else
      throw ConfigError(program + ": unknown option " + option + "\n" + usage);
  }
  if (args.case_path.empty() || args.out_dir.empty())
    throw ConfigError(program + ": --case and --out are required\n" + usage);
  return args;
}

int run_guarded(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& error) {
    std::cerr << program << ": error: " << error.what() << std::endl;
    return 2;
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << std::endl;
    return 1;
  }
}

void make_output_dir(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw ConfigError(dir + ": cannot create output folder: " + error.message());
}

}  // namespace sph
