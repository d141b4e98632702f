#pragma once
// A read-only view of a netCDF file for the output tests, failing the test on any netCDF error.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <string>
#include <vector>

namespace flexmoor::test {

class NetcdfReader {
 public:
  explicit NetcdfReader(const std::string& path) {
    expectOk(nc_open(path.c_str(), NC_NOWRITE, &id_));
  }
  ~NetcdfReader() { nc_close(id_); }

  size_t dimension(const char* name) const {
    int dim = -1;
    size_t length = 0;
    expectOk(nc_inq_dimid(id_, name, &dim));
    expectOk(nc_inq_dimlen(id_, dim, &length));
    return length;
  }
  int variable(const char* name) const {
    int var = NC_GLOBAL;
    expectOk(nc_inq_varid(id_, name, &var));
    return var;
  }
  std::string text(int var, const char* attribute) const {
    size_t length = 0;
    expectOk(nc_inq_attlen(id_, var, attribute, &length));
    std::string value(length, '\0');
    expectOk(nc_get_att_text(id_, var, attribute, value.data()));
    return value;
  }
  std::string units(const char* name) const { return text(variable(name), "units"); }
  std::vector<double> doubles(const char* name) const {
    std::vector<double> v(values(name));
    expectOk(nc_get_var_double(id_, variable(name), v.data()));
    return v;
  }
  std::vector<int> ints(const char* name) const {
    std::vector<int> v(values(name));
    expectOk(nc_get_var_int(id_, variable(name), v.data()));
    return v;
  }
  // Row `index` of a (record, name_strlen) character variable, without its padding.
  std::string row(const char* name, size_t index) const {
    const size_t length = dimension("name_strlen");
    std::string s(length, '\0');
    const size_t start[2] = {index, 0}, count[2] = {1, length};
    expectOk(nc_get_vara_text(id_, variable(name), start, count, s.data()));
    return s.c_str();
  }

 private:
  static void expectOk(int status) { EXPECT_EQ(status, NC_NOERR) << nc_strerror(status); }
  size_t values(const char* name) const {
    int dims[NC_MAX_VAR_DIMS], ndims = 0;
    expectOk(nc_inq_varndims(id_, variable(name), &ndims));
    expectOk(nc_inq_vardimid(id_, variable(name), dims));
    size_t total = 1;
    for (int d = 0; d < ndims; ++d) {
      size_t length = 0;
      expectOk(nc_inq_dimlen(id_, dims[d], &length));
      total *= length;
    }
    return total;
  }
  int id_ = -1;
};

}  // namespace flexmoor::test
