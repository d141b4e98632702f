// The installed headers that include other libraries' headers (Eigen's CHOLMOD and UMFPACK
// wrappers, netCDF) compile with the flags that find_package(flexmoor) or pkg-config give.
#include "apps/output/netcdf_file.hpp"
#include "libstruct/solve/linear_solver.hpp"
