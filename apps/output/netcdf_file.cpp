#include "apps/output/netcdf_file.hpp"

#include <stdexcept>

namespace flexmoor::app {

NetcdfFile::NetcdfFile(std::string path) : path_(std::move(path)) {
  check(nc_create(path_.c_str(), NC_NETCDF4 | NC_CLOBBER, &id_), "cannot create the file");
}

NetcdfFile::~NetcdfFile() { nc_close(id_); }  // everything written is already synced

void NetcdfFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR) fail(status, what);
}

void NetcdfFile::fail(int status, const std::string& what) const {
  throw std::runtime_error(path_ + ": " + what + ": " + nc_strerror(status));
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
  putAttribute(var, "long_name", long_name);
  if (!units.empty()) putAttribute(var, "units", units);
  return var;
}

void NetcdfFile::putAttribute(int variable, const std::string& name, const std::string& value) {
  check(nc_put_att_text(id_, variable, name.c_str(), value.size(), value.c_str()),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name, int value) {
  check(nc_put_att_int(id_, variable, name.c_str(), NC_INT, 1, &value),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::putAttribute(int variable, const std::string& name, double value) {
  check(nc_put_att_double(id_, variable, name.c_str(), NC_DOUBLE, 1, &value),
        "writing attribute " + variableName(variable) + ":" + name);
}

void NetcdfFile::endDefine() { check(nc_enddef(id_), "leaving define mode"); }

void NetcdfFile::redefine() { check(nc_redef(id_), "entering define mode"); }

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const double* values) {
  const int status = nc_put_vara_double(id_, variable, start.data(), count.data(), values);
  if (status != NC_NOERR) fail(status, "writing " + variableName(variable));
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const int* values) {
  const int status = nc_put_vara_int(id_, variable, start.data(), count.data(), values);
  if (status != NC_NOERR) fail(status, "writing " + variableName(variable));
}

void NetcdfFile::put(int variable, const std::vector<size_t>& start,
                     const std::vector<size_t>& count, const char* values) {
  const int status = nc_put_vara_text(id_, variable, start.data(), count.data(), values);
  if (status != NC_NOERR) fail(status, "writing " + variableName(variable));
}

void NetcdfFile::sync() { check(nc_sync(id_), "flushing to disk"); }

std::string NetcdfFile::variableName(int variable) const {
  if (variable == NC_GLOBAL) return "";
  char name[NC_MAX_NAME + 1] = "";
  nc_inq_varname(id_, variable, name);  // only used to word an error message
  return name;
}

}  // namespace flexmoor::app
