#pragma once
// Consecutive whole records of one netCDF record variable, held in memory until they are
// written as one hyperslab. A call to nc_put_vara costs about 10 us whatever its size (HDF5
// builds property lists and dataspaces and extends the dataset each time) and a result record
// takes some twenty calls, more than a time step of a small model; a buffer of records makes it
// one call per variable per chunk of records (record_chunks.hpp). A record is written in place:
// slot() is the room for it, which the caller fills and then commit()s.
#include <netcdf.h>

#include <cstddef>
#include <vector>

namespace flexmoor::app {

class RecordBuffer {
 public:
  // A variable whose dimensions after the record dimension have the lengths `extents`, held up
  // to `capacity` records at a time.
  RecordBuffer(std::vector<size_t> extents, size_t capacity);

  // True when the values of shape `count` at `start` are one whole record.
  bool isRecord(const std::vector<size_t>& start, const std::vector<size_t>& count) const;
  // True when record `record` of memory type `type` (NC_DOUBLE, NC_INT or NC_CHAR) may follow
  // the held ones (or be the first one held).
  bool follows(size_t record, nc_type type) const {
    return empty() || (type == type_ && record == first_ + records_);
  }
  // The room for record `record`, which follows(); its values count record_values(). Filling it
  // holds nothing until commit(); a slot not committed is overwritten by the next one.
  void* slot(size_t record, nc_type type) {
    if (empty()) {
      first_ = record;
      type_ = type;
    }
    filling_ = true;
    const size_t bytes = record_values_ * valueBytes(type);
    if (bytes_.size() < (records_ + 1) * bytes) reserve(type);
    return bytes_.data() + records_ * bytes;
  }
  void commit() {
    ++records_;
    filling_ = false;
  }
  void drop() { filling_ = false; }
  // A slot was taken and neither committed nor dropped.
  bool filling() const { return filling_; }
  size_t recordValues() const { return record_values_; }
  // Bytes of one value of memory type `type`.
  static size_t valueBytes(nc_type type) {
    return type == NC_DOUBLE ? sizeof(double) : type == NC_INT ? sizeof(int) : sizeof(char);
  }

  bool empty() const { return records_ == 0; }
  bool full() const { return records_ >= capacity_; }
  // The held records as a hyperslab: start, count, values and their memory type.
  std::vector<size_t> start() const;
  std::vector<size_t> count() const;
  const void* values() const { return bytes_.data(); }
  size_t bytes() const { return records_ * record_values_ * valueBytes(type_); }
  nc_type type() const { return type_; }
  void clear() { records_ = 0; }

 private:
  void reserve(nc_type type);  // room for `capacity` records

  std::vector<size_t> extents_;
  size_t record_values_ = 1;  // values in one record
  size_t capacity_;
  size_t first_ = 0, records_ = 0;
  nc_type type_ = NC_NAT;
  bool filling_ = false;
  std::vector<unsigned char> bytes_;  // room for `capacity` records once the first is taken
};

}  // namespace flexmoor::app
