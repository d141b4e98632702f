#pragma once
// A netCDF-4 file opened for writing through the netCDF C API, with every call's status checked:
// a failing call throws std::runtime_error "PATH: WHAT: <nc_strerror text>". Closes the file
// when destroyed.
#include <netcdf.h>

#include <string>
#include <vector>

namespace flexmoor::app {

class NetcdfFile {
 public:
  // Creates (or replaces) the file in netCDF-4 format, in define mode.
  explicit NetcdfFile(std::string path);
  ~NetcdfFile();
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  const std::string& path() const { return path_; }

  // Throws unless status is NC_NOERR.
  void check(int status, const std::string& what) const;

  // Define mode. length NC_UNLIMITED makes a record dimension.
  int defineDimension(const std::string& name, size_t length);
  // A variable with its `long_name` and, unless empty, `units` attribute.
  int defineVariable(const std::string& name, nc_type type, const std::vector<int>& dimensions,
                     const std::string& long_name, const std::string& units = "");
  // A text attribute of a variable, or of the file for NC_GLOBAL.
  void putAttribute(int variable, const std::string& name, const std::string& value);
  void putAttribute(int variable, const std::string& name, int value);
  void putAttribute(int variable, const std::string& name, double value);
  void endDefine();
  void redefine();

  // Data mode: the hyperslab at `start` of shape `count`, in C (row-major) order.
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const double* values);
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const int* values);
  void put(int variable, const std::vector<size_t>& start, const std::vector<size_t>& count,
           const char* values);
  // Flushes everything written so far to disk.
  void sync();

 private:
  [[noreturn]] void fail(int status, const std::string& what) const;
  std::string variableName(int variable) const;

  std::string path_;
  int id_ = -1;
};

}  // namespace flexmoor::app
