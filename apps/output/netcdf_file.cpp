#include "apps/output/netcdf_file.hpp"

#include <H5public.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "apps/output/atomic_output.hpp"
#include "apps/output/record_chunks.hpp"

namespace flexmoor::app {

// NC_CLOBBER would truncate the file at `path` in place, under any reader holding it open,
// before HDF5 finds that file locked and fails; removing it first and creating with
// NC_NOCLOBBER (O_EXCL, which never follows a link) makes the new file a new one.
void turnOffHdf5ExitCleanup() {
  static const herr_t once = H5dont_atexit();  // fails, harmlessly, once HDF5 has started
  (void)once;
}

NetcdfFile::NetcdfFile(std::string path, std::chrono::steady_clock::duration flush_interval)
    : path_(std::move(path)), flush_interval_(flush_interval) {
  turnOffHdf5ExitCleanup();
  removeEntry(path_);
  check(nc_create(path_.c_str(), NC_NETCDF4 | NC_NOCLOBBER, &id_), "cannot create the file");
  writeback_.emplace(path_);
}

NetcdfFile::~NetcdfFile() {
  try {
    drainAll();
  } catch (const std::exception&) {
    // A destructor cannot report it: a writer that must know calls flush() first.
  }
  nc_close(id_);
}

void NetcdfFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR) fail(status, what);
}

void NetcdfFile::fail(int status, const std::string& what) const {
  // HDF5's error says only "HDF error"; the system's says why when the disk is full or the file
  // may grow no more (errno as the failed write left it: these values come from nothing else).
  const int cause = errno;
  const bool io = cause == ENOSPC || cause == EFBIG || cause == EDQUOT || cause == EIO;
  throw std::runtime_error(path_ + ": " + what + ": " + nc_strerror(status) +
                           (io ? std::string(" (") + std::strerror(cause) + ")" : ""));
}

int NetcdfFile::defineDimension(const std::string& name, size_t length) {
  int dim = -1;
  check(nc_def_dim(id_, name.c_str(), length, &dim), "defining dimension " + name);
  return dim;
}

int NetcdfFile::defineVariable(const std::string& name, nc_type type,
                               const std::vector<int>& dimensions, const std::string& long_name,
                               const std::string& units) {
  int var = -1;
  check(nc_def_var(id_, name.c_str(), type, static_cast<int>(dimensions.size()), dimensions.data(),
                   &var),
        "defining variable " + name);
  defineRecordLayout(var, dimensions, type);
  putAttribute(var, "long_name", long_name);
  if (!units.empty()) putAttribute(var, "units", units);
  return var;
}

void NetcdfFile::defineRecordLayout(int variable, const std::vector<int>& dimensions,
                                    nc_type type) {
  int unlimited_count = 0;
  check(nc_inq_unlimdims(id_, &unlimited_count, nullptr), "reading the record dimensions");
  std::vector<int> unlimited(unlimited_count);
  check(nc_inq_unlimdims(id_, &unlimited_count, unlimited.data()), "reading the record dimensions");
  if (dimensions.empty() ||
      std::find(unlimited.begin(), unlimited.end(), dimensions[0]) == unlimited.end())
    return;
  std::vector<size_t> extents(dimensions.size() - 1);
  for (size_t d = 1; d < dimensions.size(); ++d)
    check(nc_inq_dimlen(id_, dimensions[d], &extents[d - 1]), "reading a dimension's length");
  size_t value_bytes = 0;
  check(nc_inq_type(id_, type, nullptr, &value_bytes), "reading a type's size");
  const std::vector<size_t> chunks = recordChunks(extents, value_bytes);
  check(nc_def_var_chunking(id_, variable, NC_CHUNKED, chunks.data()),
        "chunking variable " + variableName(variable));
  if (!pending_.empty())  // a record's layout is fixed while it is filled
    throw std::logic_error(path_ + ": a variable defined while a record is being filled");
  if (buffers_.size() <= static_cast<size_t>(variable)) buffers_.resize(variable + 1);
  buffers_[variable].emplace(extents, chunks[0]);
}

void NetcdfFile::putAttribute(int variable, const std::string& name, const std::string& value) {
  check(nc_put_att_text(id_, variable, name.c_str(), value.size(), value.c_str()),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name, int value) {
  check(nc_put_att_int(id_, variable, name.c_str(), NC_INT, 1, &value),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name,
                              const std::vector<int>& values) {
  check(nc_put_att_int(id_, variable, name.c_str(), NC_INT, values.size(), values.data()),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name, double value) {
  check(nc_put_att_double(id_, variable, name.c_str(), NC_DOUBLE, 1, &value),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name,
                              const std::vector<double>& values) {
  check(nc_put_att_double(id_, variable, name.c_str(), NC_DOUBLE, values.size(), values.data()),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::writtenInFull(int variable) {
  check(nc_def_var_fill(id_, variable, NC_NOFILL, nullptr),
        "defining variable " + variableName(variable) + " without fill");
}

// Record variables reach HDF5 a chunk of records at a time from their buffers, so its chunk
// cache would only copy them and, keeping every chunk it saw, grow with the file (49 of the
// 50 MB written for the demo case recorded every step): it is turned off for them. Set in data
// mode, where netCDF reopens the dataset with the setting.
void NetcdfFile::endDefine() {
  check(nc_enddef(id_), "leaving define mode");
  for (size_t variable = 0; variable < buffers_.size(); ++variable)
    if (buffers_[variable])
      check(nc_set_var_chunk_cache(id_, static_cast<int>(variable), 0, 0, 0.75f),
            "turning off the chunk cache of " + variableName(static_cast<int>(variable)));
}

void NetcdfFile::redefine() {
  drainAll();
  check(nc_redef(id_), "entering define mode");
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const double* values) {
  put(variable, start, count, values, NC_DOUBLE);
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const int* values) {
  put(variable, start, count, values, NC_INT);
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const char* values) {
  put(variable, start, count, values, NC_CHAR);
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const void* values, nc_type type) {
  RecordBuffer* buffer = recordBuffer(variable);
  if (!buffer || !buffer->isRecord(start, count)) {
    if (buffer) drain(variable, *buffer);  // what is held comes first
    return write(variable, start, count, values, type);
  }
  RecordBuffer& b = *buffer;
  if (!b.follows(start[0], type)) drain(variable, b);
  std::memcpy(b.slot(start[0], type), values, b.recordValues() * RecordBuffer::valueBytes(type));
  b.commit();
  if (b.full()) drain(variable, b);
}

RecordBuffer* NetcdfFile::recordBuffer(int variable) {
  const bool held = variable >= 0 && static_cast<size_t>(variable) < buffers_.size() &&
                    buffers_[variable].has_value();
  return held ? &*buffers_[variable] : nullptr;
}

void* NetcdfFile::slot(int variable, size_t record, nc_type type) {
  RecordBuffer* buffer = recordBuffer(variable);
  if (!buffer)
    throw std::logic_error(path_ + ": " + variableName(variable) + " is not a record variable");
  RecordBuffer& b = *buffer;
  if (!b.follows(record, type)) drain(variable, b);
  pending_.push_back(variable);
  return b.slot(record, type);
}

void NetcdfFile::drop() {
  for (const int variable : pending_) buffers_[variable]->drop();
  pending_.clear();
}

void NetcdfFile::commit() {
  for (const int variable : pending_) {
    RecordBuffer& b = *buffers_[variable];
    b.commit();
    if (b.full()) drain(variable, b);
  }
  pending_.clear();
}

void NetcdfFile::write(int variable, const std::vector<size_t>& start,
                       const std::vector<size_t>& count, const void* values, nc_type type) {
  int status = NC_NOERR;
  switch (type) {
    case NC_DOUBLE:
      status = nc_put_vara_double(id_, variable, start.data(), count.data(),
                                  static_cast<const double*>(values));
      break;
    case NC_INT:
      status = nc_put_vara_int(id_, variable, start.data(), count.data(),
                               static_cast<const int*>(values));
      break;
    default:
      status = nc_put_vara_text(id_, variable, start.data(), count.data(),
                                static_cast<const char*>(values));
  }
  if (status != NC_NOERR) fail(status, "writing " + variableName(variable));
}

void NetcdfFile::drain(int variable, RecordBuffer& buffer) {
  if (buffer.empty()) return;
  if (buffer.filling())
    throw std::logic_error(path_ + ": " + variableName(variable) +
                           " written out while a record of it is being filled");
  write(variable, buffer.start(), buffer.count(), buffer.values(), buffer.type());
  writeback_->written(buffer.bytes());
  buffer.clear();
}

void NetcdfFile::drainAll() {
  for (size_t variable = 0; variable < buffers_.size(); ++variable)
    if (buffers_[variable]) drain(static_cast<int>(variable), *buffers_[variable]);
}

void NetcdfFile::sync() {
  if (flushes_ == 0 || std::chrono::steady_clock::now() - last_flush_ >= flush_interval_) flush();
}

void NetcdfFile::flush() {
  drainAll();
  check(nc_sync(id_), "flushing to disk");
  last_flush_ = std::chrono::steady_clock::now();
  ++flushes_;
}

std::string NetcdfFile::variableName(int variable) const {
  if (variable == NC_GLOBAL) return "";
  char name[NC_MAX_NAME + 1] = "";
  nc_inq_varname(id_, variable, name);  // only used to word an error message
  return name;
}

}  // namespace flexmoor::app
