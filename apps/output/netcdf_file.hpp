#pragma once
// A netCDF-4 file opened for writing through the netCDF C API, with every call's status checked:
// a failing call throws std::runtime_error "PATH: WHAT: <nc_strerror text>". Closes the file
// when destroyed (which flushes it).
//
// Flushing (nc_sync: HDF5 writes its metadata cache) is what makes the file readable after a
// crash, and it costs milliseconds, growing with the file: sync() flushes at most once per
// flush interval, so a writer that syncs after every record and is killed loses at most the
// records of the last interval, at a cost that no longer grows with the records written.
#include <netcdf.h>

#include <chrono>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "apps/output/disk_writeback.hpp"
#include "apps/output/record_buffer.hpp"

namespace flexmoor::app {

// HDF5 closes at exit the files still open; after a write that failed (a full disk, a file size
// limit) nc_close leaves HDF5's file open, and that close at exit crashes (SIGSEGV in
// H5F__close_cb), turning a clear "exit 4" into a segmentation fault. Every file here is closed
// by its NetcdfFile or its reader, so the cleanup is turned off: first thing in main, and by
// every NetcdfFile (for programs that start HDF5 by writing). Once HDF5 has started, it is too
// late and changes nothing.
void turnOffHdf5ExitCleanup();

class NetcdfFile {
 public:
  static constexpr std::chrono::milliseconds kFlushInterval{1000};

  // Creates the file in netCDF-4 format, in define mode. Whatever was at `path` is removed first
  // (a symbolic link itself, not its target), so a reader that holds an earlier file there open
  // keeps it whole and the new file is a new one.
  explicit NetcdfFile(std::string path,
                      std::chrono::steady_clock::duration flush_interval = kFlushInterval);
  ~NetcdfFile();
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  const std::string& path() const { return path_; }

  // Throws unless status is NC_NOERR.
  void check(int status, const std::string& what) const;

  // Define mode. length NC_UNLIMITED makes a record dimension.
  int defineDimension(const std::string& name, size_t length);
  // A variable with its `long_name` and, unless empty, `units` attribute. A variable whose first
  // dimension is unlimited (a record variable) is chunked for long series (record_chunks.hpp).
  int defineVariable(const std::string& name, nc_type type, const std::vector<int>& dimensions,
                     const std::string& long_name, const std::string& units = "");
  // A text attribute of a variable, or of the file for NC_GLOBAL.
  void putAttribute(int variable, const std::string& name, const std::string& value);
  void putAttribute(int variable, const std::string& name, int value);
  void putAttribute(int variable, const std::string& name, const std::vector<int>& values);
  void putAttribute(int variable, const std::string& name, double value);
  void putAttribute(int variable, const std::string& name, const std::vector<double>& values);
  // Define mode: the variable is written whole in every record, so HDF5 need not fill its
  // chunks with the fill value before writing them (most of a record's cost on small models).
  void writtenInFull(int variable);
  void endDefine();
  void redefine();

  // Data mode: the hyperslab at `start` of shape `count`, in C (row-major) order. Whole records
  // of a record variable, one after the other, are held in memory (record_buffer.hpp) and written
  // a chunk of records at a time, and at every flush; an error writing them is thrown then.
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const double* values);
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const int* values);
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const char* values);
  // Data mode, one whole record of a record variable written in place: the room for the
  // values of record `record` of `variable` (its record_values, in C order), for the caller to
  // fill. commit() adds every slot taken since the last commit or drop to what is written;
  // drop() forgets them (so a record found wrong is never written in part).
  template <class T>
  T* slot(int variable, size_t record) {
    return static_cast<T*>(slot(variable, record, typeOf<T>()));
  }
  void commit();
  void drop();

  // Flushes everything put so far to disk when the last flush is at least the flush interval
  // old; the first call always flushes.
  void sync();
  // Flushes everything put so far to disk now.
  void flush();
  // How many times the file was flushed so far.
  int flushes() const { return flushes_; }
  // How many times the kernel was asked to start writing the file to disk (disk_writeback.hpp).
  int writebacks() const { return writeback_ ? writeback_->started() : 0; }

 private:
  [[noreturn]] void fail(int status, const std::string& what) const;
  std::string variableName(int variable) const;
  void defineRecordLayout(int variable, const std::vector<int>& dimensions, nc_type type);
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const void* values, nc_type type);
  void* slot(int variable, size_t record, nc_type type);
  template <class T>
  static constexpr nc_type typeOf() {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, int> || std::is_same_v<T, char>);
    return std::is_same_v<T, double> ? NC_DOUBLE : std::is_same_v<T, int> ? NC_INT : NC_CHAR;
  }
  void write(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
             const void* values, nc_type type);
  void drain(int variable, RecordBuffer& buffer);
  void drainAll();

  std::string path_;
  int id_ = -1;
  std::chrono::steady_clock::duration flush_interval_;
  std::chrono::steady_clock::time_point last_flush_;
  int flushes_ = 0;
  // The buffer of a record variable, else null.
  RecordBuffer* recordBuffer(int variable);
  std::vector<std::optional<RecordBuffer>> buffers_;  // by variable id: of every record variable
  std::vector<int> pending_;  // variables whose slot was taken since the last commit or drop
  std::optional<DiskWriteback> writeback_;  // told of every buffer of records written
};

}  // namespace flexmoor::app
