#include "tests/study/study_netcdf.hpp"

#include <netcdf.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace flexmoor::test {
namespace {

class Open {
 public:
  explicit Open(const std::filesystem::path& file) {
    if (nc_open(file.c_str(), NC_NOWRITE, &id) != NC_NOERR)
      throw std::runtime_error("cannot open " + file.string());
  }
  ~Open() { nc_close(id); }
  int var(const std::string& name) const {
    int v = -1;
    if (nc_inq_varid(id, name.c_str(), &v) != NC_NOERR)
      throw std::runtime_error("no variable " + name);
    return v;
  }
  size_t size(int var) const {
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    nc_inq_var(id, var, nullptr, nullptr, &ndims, dims, nullptr);
    size_t n = 1;
    for (int d = 0; d < ndims; ++d) {
      size_t len = 0;
      nc_inq_dimlen(id, dims[d], &len);
      n *= len;
    }
    return n;
  }
  int id = -1;
};

}  // namespace

std::vector<double> doubleVariable(const std::filesystem::path& file, const std::string& name) {
  const Open f(file);
  const int v = f.var(name);
  std::vector<double> values(f.size(v));
  nc_get_var_double(f.id, v, values.data());
  double fill = NC_FILL_DOUBLE;
  nc_get_att_double(f.id, v, "_FillValue", &fill);
  for (double& x : values)
    if (x == fill) x = std::nan("");
  return values;
}

std::vector<int> intVariable(const std::filesystem::path& file, const std::string& name) {
  const Open f(file);
  const int v = f.var(name);
  std::vector<int> values(f.size(v));
  nc_get_var_int(f.id, v, values.data());
  return values;
}

std::string textRow(const std::filesystem::path& file, const std::string& name, size_t row) {
  const Open f(file);
  const int v = f.var(name);
  int dims[2];
  nc_inq_vardimid(f.id, v, dims);
  size_t length = 0;
  nc_inq_dimlen(f.id, dims[1], &length);
  std::string text(length, '\0');
  const size_t start[2] = {row, 0}, count[2] = {1, length};
  nc_get_vara_text(f.id, v, start, count, text.data());
  return text.substr(0, text.find('\0'));
}

std::map<std::string, std::vector<double>> doubleVariables(const std::filesystem::path& file) {
  const Open f(file);
  int nvars = 0;
  nc_inq_nvars(f.id, &nvars);
  std::map<std::string, std::vector<double>> out;
  for (int v = 0; v < nvars; ++v) {
    nc_type type;
    char name[NC_MAX_NAME + 1];
    nc_inq_var(f.id, v, name, &type, nullptr, nullptr, nullptr);
    if (type != NC_DOUBLE) continue;
    std::vector<double> values(f.size(v));
    nc_get_var_double(f.id, v, values.data());
    out[name] = std::move(values);
  }
  return out;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace flexmoor::test
