#pragma once
// A scratch folder of a test's own. CTest runs every test case as its own process, two at a time
// in CI, so a folder shared by the cases of one fixture is emptied by one case while another
// writes in it. The name here carries the process id, the suite and the test, so no two running
// cases ever share one.

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace momenta::test {

/// `<temp>/momenta_<label>_<pid>_<suite>_<test>` for the running test, created empty.
inline std::filesystem::path make_scratch_dir(const std::string& label) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = "momenta_" + label + "_" + std::to_string(::getpid()) + "_" +
                           info->test_suite_name() + "_" + info->name();
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A fixture with `dir_`, a scratch folder made empty before each test and removed after.
class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_scratch_dir("test"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

}  // namespace momenta::test
