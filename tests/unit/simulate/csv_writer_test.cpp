// CsvWriter: never replaces a file unless told to, quotes what needs quoting, and writes numbers
// that read back to the same double.

#include "momenta/simulate/csv_writer.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/scratch_dir.hpp"

namespace momenta::simulate {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class CsvWriterTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_scratch_dir("csv"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CsvWriterTest, WritesHeaderAndRoundTripNumbers) {
  const fs::path path = dir_ / "out.csv";
  const std::vector<double> row = {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 0.0};
  {
    CsvWriter writer(path, false);
    const std::vector<std::string> columns = {"time", "a,b", "say \"hi\"", "d", "e"};
    writer.begin(columns);
    writer.row(row);
  }
  std::istringstream in(slurp(path));
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header, "time,\"a,b\",\"say \"\"hi\"\"\",d,e");
  std::istringstream fields(line);
  std::string field;
  for (double x : row) {
    ASSERT_TRUE(std::getline(fields, field, ','));
    EXPECT_EQ(std::strtod(field.c_str(), nullptr), x) << field;
  }
  EXPECT_EQ(line.substr(0, 4), "0.1,");  // the shortest form, not 0.10000000000000001
}

TEST_F(CsvWriterTest, NeverReplacesAnExistingFileUnlessAsked) {
  const fs::path path = dir_ / "keep.csv";
  std::ofstream(path) << "precious\n";
  try {
    CsvWriter writer(path, false);
    ADD_FAILURE() << "no exception";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("keep.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), "precious\n");
  {
    CsvWriter writer(path, true);
    const std::vector<std::string> columns = {"time"};
    writer.begin(columns);
  }
  EXPECT_EQ(slurp(path), "time\n");
}

TEST_F(CsvWriterTest, MissingFolderIsAFileError) {
  EXPECT_THROW(CsvWriter(dir_ / "no" / "such" / "folder.csv", false), FileError);
}

}  // namespace
}  // namespace momenta::simulate
