#pragma once
// Consecutive whole records of one netCDF record variable, held in memory until they are
// written as one hyperslab. A call to nc_put_vara costs about 10 us whatever its size (HDF5
// builds property lists and dataspaces and extends the dataset each time) and a result record
// takes some twenty calls, more than a time step of a small model; a buffer of records makes it
// one call per variable per chunk of records (record_chunks.hpp).
#include <netcdf.h>

#include <cstddef>
#include <vector>

namespace flexmoor::app {

class RecordBuffer {
 public:
  // A variable whose dimensions after the record dimension have the lengths `extents`, held up
  // to `capacity` records at a time.
  RecordBuffer(std::vector<size_t> extents, size_t capacity);

  // True when the values of shape `count` at `start`, of memory type `type` (NC_DOUBLE, NC_INT
  // or NC_CHAR), are one whole record that follows the held ones (or the first one held).
  bool accepts(const std::vector<size_t>& start, const std::vector<size_t>& count,
               nc_type type) const;
  // Holds one record that accepts() took; `values` has the record's values of `type`.
  void append(const std::vector<size_t>& start, const void* values, nc_type type);

  bool empty() const { return records_ == 0; }
  bool full() const { return records_ >= capacity_; }
  // The held records as a hyperslab: start, count, values and their memory type.
  std::vector<size_t> start() const;
  std::vector<size_t> count() const;
  const void* values() const { return bytes_.data(); }
  nc_type type() const { return type_; }
  void clear();

 private:
  std::vector<size_t> extents_;
  size_t record_values_ = 1;  // values in one record
  size_t capacity_;
  size_t first_ = 0, records_ = 0;
  nc_type type_ = NC_NAT;
  std::vector<unsigned char> bytes_;
};

}  // namespace flexmoor::app
