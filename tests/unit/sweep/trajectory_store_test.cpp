// Trajectories of a sweep (sweep/trajectory_store.hpp): each run's whole table, read back from
// the HDF5 file (a dataset per run, its columns in an attribute) or the folder of CSV files.

#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/sweep/trajectory_store.hpp"
#include "momenta_test/scratch_dir.hpp"

#ifdef MOMENTA_TEST_HDF5
#include <hdf5.h>
#endif

namespace momenta::sweep {
namespace {

RunOutcome table_of(long run) {
  RunOutcome o;
  o.run = run;
  o.trajectory_columns = {"time", "x"};
  for (int k = 0; k < 4; ++k) {
    o.trajectory.push_back(0.5 * k);
    o.trajectory.push_back(0.1 * k * k + static_cast<double>(run));
  }
  return o;
}

using TrajectoryStoreTest = test::ScratchDirTest;

TEST_F(TrajectoryStoreTest, AFolderGetsACsvFilePerRunWithEveryDigit) {
  {
    const auto store = open_trajectory_store(dir_ / "runs", false, false);
    store->write(table_of(7));
    RunOutcome failed = table_of(8);
    failed.ok = false;
    store->write(failed);  // nothing: a failed run has no table
  }
  std::ifstream in(dir_ / "runs" / "run_000007.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,x\n0,7\n0.5,7.1\n1,7.4\n1.5,7.9\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "runs" / "run_000008.csv"));
  // A folder with files in it is not written into without --force (or --resume).
  EXPECT_THROW(open_trajectory_store(dir_ / "runs", false, false), FileError);
  EXPECT_NO_THROW(open_trajectory_store(dir_ / "runs", true, false));
}

// Under MPI a rank other than 0 formats its runs' tables as text (format_csv_trajectory) and rank
// 0 writes that text: the bytes a folder writes from the numbers, header quoting and the numbers'
// shortest round-trip forms (NaN, a subnormal, the largest double) included.
TEST_F(TrajectoryStoreTest, ATableFormattedWhereItRanIsTheFileAFolderWrites) {
  RunOutcome numbers = table_of(3);
  numbers.trajectory_columns = {"time", "f \"x\", N"};
  numbers.trajectory.insert(numbers.trajectory.end(),
                            {std::numeric_limits<double>::quiet_NaN(), 4.9e-324,
                             std::numeric_limits<double>::max(), -1e-5});
  RunOutcome text = numbers;
  format_csv_trajectory(text);
  EXPECT_TRUE(text.trajectory.empty());
  EXPECT_EQ(text.trajectory_columns, numbers.trajectory_columns);
  {
    const auto from_numbers = open_trajectory_store(dir_ / "numbers", false, false);
    from_numbers->write(numbers);
    const auto from_text = open_trajectory_store(dir_ / "text", false, false);
    from_text->write(text);
  }
  const auto slurp = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  };
  const std::string expected = slurp(dir_ / "numbers" / "run_000003.csv");
  EXPECT_EQ(expected,
            "time,\"f \"\"x\"\", N\"\n0,3\n0.5,3.1\n1,3.4\n1.5,3.9000000000000004\nnan,5e-324\n"
            "1.7976931348623157e+308,-1e-05\n");
  EXPECT_EQ(text.trajectory_csv, expected);
  EXPECT_EQ(slurp(dir_ / "text" / "run_000003.csv"), expected);
  // A failed run has no table: nothing to format, nothing written.
  RunOutcome failed = table_of(4);
  failed.ok = false;
  format_csv_trajectory(failed);
  EXPECT_TRUE(failed.trajectory_csv.empty());
  EXPECT_EQ(failed.trajectory.size(), 8U);
}

#ifdef MOMENTA_TEST_HDF5
TEST_F(TrajectoryStoreTest, AnHdf5FileGetsADatasetPerRunWithItsColumns) {
  ASSERT_TRUE(hdf5_available());
  const std::filesystem::path path = dir_ / "runs.h5";
  {
    const auto store = open_trajectory_store(path, false, false);
    store->write(table_of(3));
    store->write(table_of(4));
  }
  {
    // Resumed: run 4 stored again replaces its table.
    const auto store = open_trajectory_store(path, true, false);
    RunOutcome again = table_of(4);
    again.trajectory[1] = 99.0;
    store->write(again);
  }
  EXPECT_THROW(open_trajectory_store(path, false, false), FileError);
  const hid_t file = H5Fopen(path.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (long run : {3L, 4L}) {
    const std::string name = run == 3 ? "run_000003" : "run_000004";
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    ASSERT_GE(set, 0) << name;
    const hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    EXPECT_EQ(dims[0], 4U);
    EXPECT_EQ(dims[1], 2U);
    std::vector<double> values(8);
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    std::vector<double> expected = table_of(run).trajectory;
    if (run == 4) expected[1] = 99.0;
    EXPECT_EQ(values, expected);
    const hid_t attribute = H5Aopen(set, "columns", H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    std::string columns(H5Tget_size(type), '\0');
    H5Aread(attribute, type, columns.data());
    EXPECT_EQ(std::string(columns.c_str()), "time,x");
    H5Tclose(type);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(file);
}
#endif

}  // namespace
}  // namespace momenta::sweep
