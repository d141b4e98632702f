// NetcdfFile: how it creates, chunks, buffers and flushes a file, read back through the netCDF C
// API once the file is closed.
#include "apps/output/netcdf_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/output/record_chunks.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

class NetcdfFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexmoor-ncfile-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "file.nc").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  std::string path_;
};

std::vector<size_t> chunking(int file, const char* name, int& storage) {
  int var = -1, ndims = 0;
  EXPECT_EQ(nc_inq_varid(file, name, &var), NC_NOERR) << name;
  EXPECT_EQ(nc_inq_varndims(file, var, &ndims), NC_NOERR);
  std::vector<size_t> chunks(ndims);
  EXPECT_EQ(nc_inq_var_chunking(file, var, &storage, chunks.data()), NC_NOERR);
  return chunks;
}

// Reference: the rule of record_chunks.hpp, worked by hand for kChunkBytes = 128 KiB and
// kMaxRecords = 2048. Exact integers.
TEST(RecordChunks, ManyRecordsPerChunkAndTheWholeOfSmallDimensions) {
  ASSERT_EQ(kChunkBytes, 131072u);
  ASSERT_EQ(kMaxRecords, 2048u);
  // A scalar per record (time): capped at kMaxRecords.
  EXPECT_EQ(recordChunks({}, 8), (std::vector<size_t>{2048}));
  // 151 nodes of doubles, 1,208 bytes a record: floor(131072 / 1208) = 108 records.
  EXPECT_EQ(recordChunks({151}, 8), (std::vector<size_t>{108, 151}));
  // (element, end) of 150 elements: 2,400 bytes a record, 54 records.
  EXPECT_EQ(recordChunks({150, 2}, 8), (std::vector<size_t>{54, 150, 2}));
  // A record larger than a chunk: 100,000 nodes (800,000 bytes) split to 16,384 a chunk.
  EXPECT_EQ(recordChunks({100000}, 8), (std::vector<size_t>{1, 16384}));
  // (mode, node) 10 x 100,000: one mode of 16,384 nodes a chunk (the outermost split first).
  EXPECT_EQ(recordChunks({10, 100000}, 8), (std::vector<size_t>{1, 1, 16384}));
  // (mode, node) 10 x 5,000 (400,000 bytes): 3 modes of 40,000 bytes fit in 128 KiB.
  EXPECT_EQ(recordChunks({10, 5000}, 8), (std::vector<size_t>{1, 3, 5000}));
  // A second unlimited dimension (length 0 so far) counts as 1.
  EXPECT_EQ(recordChunks({0}, 8), (std::vector<size_t>{2048, 1}));
}

// The default of netCDF is one record per chunk for (step, node); the file must carry the
// chunking of recordChunks, and fixed-size variables stay contiguous.
TEST_F(NetcdfFileTest, RecordVariablesAreChunkedForLongSeries) {
  {
    NetcdfFile file(path_);
    const int step = file.defineDimension("step", NC_UNLIMITED);
    const int node = file.defineDimension("node", 151);
    file.defineVariable("time", NC_DOUBLE, {step}, "time", "s");
    file.defineVariable("displacement_x", NC_DOUBLE, {step, node}, "x displacement", "m");
    file.defineVariable("node_x", NC_DOUBLE, {node}, "x coordinate", "m");
    file.endDefine();
  }
  int id = -1, storage = -1;
  ASSERT_EQ(nc_open(path_.c_str(), NC_NOWRITE, &id), NC_NOERR);
  EXPECT_EQ(chunking(id, "time", storage), (std::vector<size_t>{2048}));
  EXPECT_EQ(storage, NC_CHUNKED);
  EXPECT_EQ(chunking(id, "displacement_x", storage), (std::vector<size_t>{108, 151}));
  EXPECT_EQ(storage, NC_CHUNKED);
  chunking(id, "node_x", storage);
  EXPECT_EQ(storage, NC_CONTIGUOUS);
  nc_close(id);
}

// Records go through the record buffer (held, then written a chunk of records at a time); a
// write that is not a whole record comes after everything held before it. Reference: the values
// put, exactly; 10,000 records cross four chunk boundaries of `time` (2,048 records a chunk).
TEST_F(NetcdfFileTest, BufferedRecordsReachTheFileWholeAndInOrder) {
  const size_t records = 10000;
  {
    NetcdfFile file(path_);
    const int step = file.defineDimension("step", NC_UNLIMITED);
    const int node = file.defineDimension("node", 3);
    const int name = file.defineDimension("name_strlen", 4);
    const int time = file.defineVariable("time", NC_DOUBLE, {step}, "time", "s");
    const int number = file.defineVariable("step_number", NC_INT, {step}, "step");
    const int label = file.defineVariable("step_name", NC_CHAR, {step, name}, "name");
    const int u = file.defineVariable("u", NC_DOUBLE, {step, node}, "u", "m");
    file.endDefine();
    for (size_t r = 0; r < records; ++r) {
      const double t = 0.5 * r, values[3] = {1.0 * r, 2.0 * r, 3.0 * r};
      const int n = static_cast<int>(r) + 1;
      const std::string text = std::to_string(r % 10000).substr(0, 4) + "    ";
      file.put(time, {r}, {1}, &t);
      file.put(number, {r}, {1}, &n);
      file.put(label, {r, 0}, {1, 4}, text.c_str());
      if (r == 5000) {  // part of a record: node 1 alone, then the other two
        file.put(u, {r, 1}, {1, 1}, &values[1]);
        file.put(u, {r, 0}, {1, 1}, &values[0]);
        file.put(u, {r, 2}, {1, 1}, &values[2]);
      } else {
        file.put(u, {r, 0}, {1, 3}, values);
      }
      file.sync();
    }
  }
  int id = -1, var = -1;
  ASSERT_EQ(nc_open(path_.c_str(), NC_NOWRITE, &id), NC_NOERR);
  std::vector<double> t(records), u(3 * records);
  std::vector<int> n(records);
  std::string labels(4 * records, '\0');
  ASSERT_EQ(nc_inq_varid(id, "time", &var), NC_NOERR);
  ASSERT_EQ(nc_get_var_double(id, var, t.data()), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(id, "step_number", &var), NC_NOERR);
  ASSERT_EQ(nc_get_var_int(id, var, n.data()), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(id, "step_name", &var), NC_NOERR);
  ASSERT_EQ(nc_get_var_text(id, var, labels.data()), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(id, "u", &var), NC_NOERR);
  ASSERT_EQ(nc_get_var_double(id, var, u.data()), NC_NOERR);
  nc_close(id);
  for (size_t r = 0; r < records; ++r) {
    ASSERT_EQ(t[r], 0.5 * r) << r;
    ASSERT_EQ(n[r], static_cast<int>(r) + 1) << r;
    ASSERT_EQ(labels.substr(4 * r, 4), (std::to_string(r) + "    ").substr(0, 4)) << r;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(u[3 * r + k], (k + 1.0) * r) << r << " " << k;
  }
}

// A file that grows is written back to the disk as it grows (DiskWriteback): every 4 MiB of
// records the kernel is asked to start writing, so that the fsync that puts the finished file
// in place waits only for the rest. 10 MiB of records: at least two requests, and the file
// reads back whole.
TEST_F(NetcdfFileTest, AGrowingFileIsWrittenBackAsItGrows) {
  const size_t records = 10u << 20 >> 10;  // 1 KiB records
  {
    NetcdfFile file(path_);
    const int step = file.defineDimension("step", NC_UNLIMITED);
    const int node = file.defineDimension("value", 128);
    const int u = file.defineVariable("u", NC_DOUBLE, {step, node}, "u", "m");
    file.endDefine();
    std::vector<double> values(128);
    for (size_t r = 0; r < records; ++r) {
      values.assign(128, 1.0 * r);
      file.put(u, {r, 0}, {1, 128}, values.data());
    }
    file.flush();
#ifdef __linux__
    EXPECT_GE(file.writebacks(), 2);
#endif
  }
  int id = -1, var = -1;
  ASSERT_EQ(nc_open(path_.c_str(), NC_NOWRITE, &id), NC_NOERR);
  std::vector<double> u(128 * records);
  ASSERT_EQ(nc_inq_varid(id, "u", &var), NC_NOERR);
  ASSERT_EQ(nc_get_var_double(id, var, u.data()), NC_NOERR);
  nc_close(id);
  for (size_t r = 0; r < records; r += 97) ASSERT_EQ(u[128 * r + 127], 1.0 * r) << r;
}

// sync() after every record must not flush every time: a flush costs milliseconds, growing with
// the file. Within one flush interval (1 s), 1,000 syncs make one flush, the first; flush()
// always flushes; with an interval of zero every sync flushes (the behaviour before).
TEST_F(NetcdfFileTest, SyncFlushesAtMostOncePerInterval) {
  NetcdfFile file(path_);
  const int step = file.defineDimension("step", NC_UNLIMITED);
  const int time = file.defineVariable("time", NC_DOUBLE, {step}, "time", "s");
  file.endDefine();
  EXPECT_EQ(file.flushes(), 0);
  for (size_t r = 0; r < 1000; ++r) {
    const double t = r;
    file.put(time, {r}, {1}, &t);
    file.sync();
  }
  EXPECT_EQ(file.flushes(), 1);  // 1,000 tiny records take far less than a second
  file.flush();
  EXPECT_EQ(file.flushes(), 2);

  NetcdfFile every((dir_ / "every.nc").string(), std::chrono::seconds(0));
  every.endDefine();
  for (int k = 0; k < 5; ++k) every.sync();
  EXPECT_EQ(every.flushes(), 5);
}

std::string contentOf(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The file is made new: a symbolic link planted at the path is replaced, its target untouched
// (NC_CLOBBER opened the target and truncated it).
TEST_F(NetcdfFileTest, ASymbolicLinkAtThePathIsReplacedNotFollowed) {
  const fs::path target = dir_ / "precious.txt";
  std::ofstream(target) << "precious";
  fs::create_symlink(target, path_);
  { NetcdfFile(path_).endDefine(); }
  EXPECT_EQ(contentOf(target), "precious");
  EXPECT_FALSE(fs::is_symlink(path_));
  EXPECT_TRUE(fs::is_regular_file(path_));
}

// A reader that holds the earlier file open keeps it whole: the new file is a new inode.
TEST_F(NetcdfFileTest, AFileHeldOpenByAReaderIsReplacedByANewOne) {
  {
    NetcdfFile old(path_);
    old.putAttribute(NC_GLOBAL, "title", "old");
  }
  struct stat before {};
  ASSERT_EQ(::stat(path_.c_str(), &before), 0);
  int reader = -1;
  ASSERT_EQ(nc_open(path_.c_str(), NC_NOWRITE, &reader), NC_NOERR);
  {
    NetcdfFile replacement(path_);
    replacement.putAttribute(NC_GLOBAL, "title", "new");
  }
  struct stat after {};
  ASSERT_EQ(::stat(path_.c_str(), &after), 0);
  EXPECT_NE(before.st_ino, after.st_ino);
  char title[4] = "";
  EXPECT_EQ(nc_get_att_text(reader, NC_GLOBAL, "title", title), NC_NOERR);
  EXPECT_EQ(std::string(title, 3), "old");
  nc_close(reader);
}

}  // namespace
}  // namespace flexmoor::app
