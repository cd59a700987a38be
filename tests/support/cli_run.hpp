// Runs the `plumbago` program (PLUMBAGO_CLI) as a user would, capturing its exit code,
// stdout and stderr through files in a test's TempDir.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace plumbago::testing {

struct CliRun {
  int code;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `wrapper`, when given, runs the program (e.g. "xvfb-run -a ", "env -u DISPLAY ").
inline CliRun run_cli(const std::string& args, const TempDir& dir, const std::string& wrapper = "") {
  std::string cmd = wrapper + PLUMBAGO_CLI + " " + args + " >" + dir.path("stdout") + " 2>" + dir.path("stderr");
  int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir.path("stdout")), slurp(dir.path("stderr"))};
}

}  // namespace plumbago::testing
