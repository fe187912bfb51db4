#pragma once
// Runs the built momenta binary as a user runs it, for the CLI tests: MOMENTA_CLI_PATH (set by
// CMake on cli_tests) names the binary; each test gets its own scratch folder, and a run's exit
// code, stdout and stderr are captured apart.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "momenta_test/scratch_dir.hpp"

#ifndef MOMENTA_CLI_PATH
#error "MOMENTA_CLI_PATH must name the built momenta binary"
#endif

namespace momenta::test {

/// What one run of the binary gave: its exit code (-1 when it did not exit normally), stdout and
/// stderr.
struct CliRun {
  int code = -1;
  std::string out;
  std::string err;
};

/// The whole content of a file, bytes as they are ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `s` single-quoted for the shell, quotes inside it escaped.
inline std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// A fixture with a scratch folder `dir_` of its own (made empty before the test, removed after)
/// and `momenta(args)`, which runs the binary there.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_scratch_dir("cli"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Writes `text` to a file `name` in the test's folder, bytes as they are; returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// Runs `momenta <args>` (`args` as the shell reads them) with stdout and stderr captured apart.
  CliRun momenta(const std::string& args) const { return run_with("", args); }

  /// The same under `timeout 60`: a hang ends with exit 124 instead of holding the test.
  CliRun momenta_with_timeout(const std::string& args) const {
    return run_with("timeout 60 ", args);
  }

  CliRun run_with(const std::string& before, const std::string& args) const {
    const std::filesystem::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = before + quoted(MOMENTA_CLI_PATH) + " " + args + " >" +
                                quoted(out.string()) + " 2>" + quoted(err.string());
    const int status = std::system(command.c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  std::filesystem::path dir_;
};

}  // namespace momenta::test
