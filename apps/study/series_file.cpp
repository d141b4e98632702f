#include "apps/study/series_file.hpp"

#include <netcdf.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "apps/output/netcdf_file.hpp"

namespace flexmoor::app {
namespace {

void check(int status, const std::string& path, const std::string& what) {
  if (status != NC_NOERR) throw std::runtime_error(path + ": " + what + ": " + nc_strerror(status));
}

// A double attribute, or `fallback` when the variable has none.
double attribute(int file, int variable, const char* name, double fallback) {
  double value = fallback;
  return nc_get_att_double(file, variable, name, &value) == NC_NOERR ? value : fallback;
}

}  // namespace

void writeSeriesFile(const std::string& path, const SeriesRecorder& recorder,
                     const std::string& time_unit) {
  NetcdfFile file(path);
  const size_t n = recorder.time().size();
  const int time_dim = file.defineDimension("time", n);
  const int time = file.defineVariable("time", NC_DOUBLE, {time_dim}, "time", time_unit);
  file.putAttribute(time, "standard_name", std::string("time"));
  file.putAttribute(time, "axis", std::string("T"));
  file.putAttribute(NC_GLOBAL, "Conventions", std::string("CF-1.8"));
  std::vector<int> ids;
  for (const SummarySpec& spec : recorder.specs()) {
    const int id = file.defineVariable(spec.name, NC_DOUBLE, {time_dim}, spec.name, spec.unit);
    file.putAttribute(id, "_FillValue", NC_FILL_DOUBLE);
    if (std::isfinite(spec.from)) file.putAttribute(id, "window_from", spec.from);
    if (std::isfinite(spec.to)) file.putAttribute(id, "window_to", spec.to);
    ids.push_back(id);
  }
  file.endDefine();
  if (n == 0) return;
  file.put(time, {0}, {n}, recorder.time().data());
  for (size_t k = 0; k < ids.size(); ++k) {
    std::vector<double> values = recorder.values()[k];
    for (double& v : values)
      if (std::isnan(v)) v = NC_FILL_DOUBLE;
    file.put(ids[k], {0}, {n}, values.data());
  }
}

SeriesData readSeriesFile(const std::string& path, const std::vector<std::string>& names) {
  int file = -1;
  check(nc_open(path.c_str(), NC_NOWRITE, &file), path, "cannot open");
  SeriesData data;
  try {
    int dim = -1, var = -1;
    size_t n = 0;
    check(nc_inq_dimid(file, "time", &dim), path, "dimension time");
    check(nc_inq_dimlen(file, dim, &n), path, "dimension time");
    data.time.resize(n);
    check(nc_inq_varid(file, "time", &var), path, "variable time");
    if (n) check(nc_get_var_double(file, var, data.time.data()), path, "variable time");
    const double inf = std::numeric_limits<double>::infinity();
    for (const std::string& name : names) {
      SeriesData::Variable v;
      v.name = name;
      check(nc_inq_varid(file, name.c_str(), &var), path, "variable " + name);
      v.values.resize(n);
      if (n) check(nc_get_var_double(file, var, v.values.data()), path, "variable " + name);
      for (double& x : v.values)
        if (x == NC_FILL_DOUBLE) x = std::numeric_limits<double>::quiet_NaN();
      v.from = attribute(file, var, "window_from", -inf);
      v.to = attribute(file, var, "window_to", inf);
      size_t length = 0;
      if (nc_inq_attlen(file, var, "units", &length) == NC_NOERR) {
        v.units.resize(length);
        nc_get_att_text(file, var, "units", v.units.data());
      }
      data.variables.push_back(std::move(v));
    }
  } catch (...) {
    nc_close(file);
    throw;
  }
  nc_close(file);
  return data;
}

}  // namespace flexmoor::app
