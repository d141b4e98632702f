// A run that does not converge: exit code 3, a message, and the last converged state on disk.
//
// The case is Example 1 (8 x L2, viscous relaxation) allowed a single relaxation step: the step
// converges (its Newton iterations do), the relaxation does not reach equilibrium. The last
// converged state is therefore the state after one relaxation step. Reference: the same model
// built in code (tests/support/cable_models.*, Example 1's relaxation parameters, max_steps 1)
// and relaxed by libstruct directly, stopped by the same ConvergenceError. The netCDF file is
// read with the netCDF C API: its last record must be that state (displacements node by node,
// matched by reference position, within 1e-12 of the largest displacement: the same arithmetic,
// round-off only), carry the step name "... (last converged)", and hold only finite numbers.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "tests/support/cable_models.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using flexmoor::test::CliRun;
using flexmoor::test::readFile;

// One record (the last) of a variable of dimensions (record, n).
std::vector<double> lastRecord(int file, const char* name, size_t record, size_t n) {
  int var = -1;
  EXPECT_EQ(nc_inq_varid(file, name, &var), NC_NOERR) << name;
  std::vector<double> values(n, std::nan(""));
  const size_t start[2] = {record, 0}, count[2] = {1, n};
  EXPECT_EQ(nc_get_vara_double(file, var, start, count, values.data()), NC_NOERR) << name;
  return values;
}

// Every numeric variable along the record dimension holds finite numbers in its last record.
void expectLastRecordFinite(int file, int record_dim, size_t record) {
  int variables = 0;
  ASSERT_EQ(nc_inq_nvars(file, &variables), NC_NOERR);
  int checked = 0;
  for (int v = 0; v < variables; ++v) {
    char name[NC_MAX_NAME + 1];
    nc_type type;
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    ASSERT_EQ(nc_inq_var(file, v, name, &type, &ndims, dims, nullptr), NC_NOERR);
    if (type != NC_DOUBLE || ndims == 0 || dims[0] != record_dim) continue;
    std::vector<size_t> start(ndims, 0), count(ndims, 1);
    start[0] = record;
    size_t n = 1;
    for (int d = 1; d < ndims; ++d) {
      ASSERT_EQ(nc_inq_dimlen(file, dims[d], &count[d]), NC_NOERR);
      n *= count[d];
    }
    std::vector<double> values(n);
    ASSERT_EQ(nc_get_vara_double(file, v, start.data(), count.data(), values.data()), NC_NOERR);
    for (size_t k = 0; k < n; ++k) EXPECT_TRUE(std::isfinite(values[k])) << name << "[" << k << "]";
    ++checked;
  }
  EXPECT_GE(checked, 4);  // at least time, load factor, displacements and positions
}

TEST(Cli, NonConvergenceExitsWith3AndKeepsTheLastConvergedState) {
  // A directory of this process: other test processes may run the same test side by side.
  const fs::path dir = flexmoor::test::scratch("diverge-" + std::to_string(getpid()));
  const fs::path file = dir / "diverge.yaml";
  std::string text =
      readFile(fs::path(FLEXMOOR_SOURCE_DIR) / "cases/seed/ex1-suspended-cable-8xL2.yaml");
  // One relaxation step cannot reach equilibrium.
  const std::string before = text;
  text = std::regex_replace(text, std::regex("damping: 10000\\}"), "damping: 10000, max_steps: 1}");
  text = std::regex_replace(text, std::regex("name: ex1-suspended-cable-8xL2"), "name: diverge");
  ASSERT_NE(text, before);
  std::ofstream(file) << text;
  const CliRun r = flexmoor::test::flexmoor("run " + file.string() + " -o " + dir.string());
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("did not converge"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(dir / "diverge.nc")) << r.output;

  // The reference: one relaxation step of the same model, in code.
  const flexmoor::test::SuspendedCable cable = flexmoor::test::makeSuspendedCable(
      flexmoor::test::SuspendedCableInputs{}, 8, 2, flexmoor::material::Compression::Carry);
  const flexmoor::model::Assembler assembler(*cable.model);
  flexmoor::model::State state = cable.model->initialState();
  flexmoor::solve::RelaxationOptions options = flexmoor::test::exampleOneRelaxation();
  options.max_steps = 1;
  EXPECT_THROW(flexmoor::solve::relax(assembler, state, options),
               flexmoor::solve::ConvergenceError);
  const double largest = state.displacement.cwiseAbs().maxCoeff();
  // The step moved the cable (by 4.4e-4 ft: the damping of the first step is heavy), so the
  // comparison means something.
  ASSERT_GT(largest, 1e-5);

  int nc = -1;
  ASSERT_EQ(nc_open((dir / "diverge.nc").c_str(), NC_NOWRITE, &nc), NC_NOERR);
  int record_dim = -1, node_dim = -1;
  size_t records = 0, nodes = 0;
  // The last converged state is the stage record of the step that did not converge.
  ASSERT_EQ(nc_inq_dimid(nc, "stage", &record_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, record_dim, &records), NC_NOERR);
  ASSERT_EQ(nc_inq_dimid(nc, "node", &node_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, node_dim, &nodes), NC_NOERR);
  ASSERT_GE(records, 1u);
  ASSERT_EQ(nodes, static_cast<size_t>(cable.model->nodeCount()));
  const size_t last = records - 1;

  int name_var = -1, name_dims[2];
  size_t name_length = 0;
  ASSERT_EQ(nc_inq_varid(nc, "stage_step", &name_var), NC_NOERR);
  ASSERT_EQ(nc_inq_vardimid(nc, name_var, name_dims), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, name_dims[1], &name_length), NC_NOERR);
  std::string step_name(name_length, '\0');
  const size_t name_start[2] = {last, 0}, name_count[2] = {1, name_length};
  ASSERT_EQ(nc_get_vara_text(nc, name_var, name_start, name_count, step_name.data()), NC_NOERR);
  EXPECT_NE(step_name.find("(last converged)"), std::string::npos) << step_name;

  std::vector<double> x(nodes);
  int x_var = -1;
  ASSERT_EQ(nc_inq_varid(nc, "node_x", &x_var), NC_NOERR);
  ASSERT_EQ(nc_get_var_double(nc, x_var, x.data()), NC_NOERR);
  const std::vector<double> ux = lastRecord(nc, "stage_displacement_x", last, nodes);
  const std::vector<double> uz = lastRecord(nc, "stage_displacement_z", last, nodes);
  const flexmoor::model::NodalField& X = cable.model->reference();
  double worst = 0.0;
  for (size_t k = 0; k < nodes; ++k) {
    int match = -1;
    for (int n = 0; n < cable.model->nodeCount(); ++n)
      if (std::abs(X(0, n) - x[k]) < 1e-9) match = n;
    ASSERT_GE(match, 0) << "no node of the reference at x = " << x[k];
    worst = std::max({worst, std::abs(ux[k] - state.displacement(0, match)),
                      std::abs(uz[k] - state.displacement(2, match))});
  }
  std::cout << "[ last converged state ] " << records << " record(s); largest displacement "
            << largest << " ft, worst difference from the in-code relaxation step " << worst
            << " ft\n";
  EXPECT_LT(worst, 1e-12 * largest);
  expectLastRecordFinite(nc, record_dim, last);
  nc_close(nc);
}

}  // namespace
