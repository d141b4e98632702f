// Membrane results as a user reads them: principal stress resultants per element in netCDF (fill
// value on elements that are not membranes) and VTK, for a sheet under uniform biaxial stretch
// whose resultant is known in closed form.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;

// A 1 m square sheet of T6 triangles, edge cable along y = 0, its edges pulled out by 1 mm in x
// and y: stretch lambda = 1.001 both ways, Green strain g = (lambda^2 - 1) / 2. The plane-stress
// law on the Green strain gives S = E g / (1 - nu) both ways, and the resultant per current
// length is S h0 (the stretch of the edge cancels that of the force).
const char* kStretchedSheet = R"(name: stretched-sheet
units: SI
materials:
  film: {type: linear_elastic, E: 1.0e6, nu: 0.3}
sections:
  skin: {material: film, thickness: 0.001, density: 1000}
  edge: {material: film, area: 1.0e-6}
lines:
  - {name: hem, from: [0, 0, 0], to: [1, 0, 0], elements: 2, order: 3, section: edge}
surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [2, 2], element: T6, diagonals: centre, section: skin}
supports:
  - {nodes: {where: {x: 0}}, fix: [x]}
  - {nodes: {where: {y: 0}}, fix: [y]}
  - {nodes: {where: {x: 1}}, fix: [x], displacement: [0.001]}
  - {nodes: {where: {y: 1}}, fix: [y], displacement: [0.001]}
  - {nodes: sheet, fix: [z]}
steps:
  - static: {name: stretch}
summary:
  n_max: {quantity: resultant_max, element: sheet.3}
  n_min: {quantity: resultant_min, element: sheet.3}
)";

// The `count` values of the cell scalar `name` of a legacy VTK file (after its LOOKUP_TABLE line).
std::vector<double> cellScalars(const std::string& vtk, const std::string& name, size_t count) {
  const size_t at = vtk.find("SCALARS " + name + " double 1\nLOOKUP_TABLE default\n");
  if (at == std::string::npos) return {};
  std::istringstream in(vtk.substr(vtk.find("default\n", at) + 8));
  std::vector<double> values;
  double v = 0.0;
  while (values.size() < count && in >> v) values.push_back(v);
  return values;
}

TEST(MembraneOutput, PrincipalResultantsInNetcdfVtkAndSummaryMatchClosedForm) {
  // A directory of this process: other test processes may run the same test side by side.
  const auto dir = flexmoor::test::scratch("membrane-output-" + std::to_string(getpid()));
  std::ofstream(dir / "sheet.yaml") << kStretchedSheet;
  const auto r = flexmoor("run " + (dir / "sheet.yaml").string() + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double lambda = 1.001, g = (lambda * lambda - 1.0) / 2.0;
  const double expected = 1.0e6 * g / (1.0 - 0.3) * 0.001;

  int file = -1;
  ASSERT_EQ(nc_open((dir / "stretched-sheet.nc").c_str(), NC_NOWRITE, &file), NC_NOERR);
  const size_t elements = 2 + 8;  // the hem's two cables, then the sheet's eight triangles
  // The static step's state: a stage record.
  for (const char* name : {"stage_membrane_resultant_max", "stage_membrane_resultant_min"}) {
    int var = -1;
    ASSERT_EQ(nc_inq_varid(file, name, &var), NC_NOERR) << name;
    std::vector<double> n(elements);
    ASSERT_EQ(nc_get_var_double(file, var, n.data()), NC_NOERR);
    for (size_t e = 0; e < 2; ++e) EXPECT_EQ(n[e], NC_FILL_DOUBLE) << name << " cable " << e;
    for (size_t e = 2; e < elements; ++e) EXPECT_NEAR(n[e] / expected, 1.0, 1e-9) << name << e;
  }
  nc_close(file);

  const std::string json = flexmoor::test::readFile(dir / "stretched-sheet.summary.json");
  EXPECT_NEAR(flexmoor::test::summaryValue(json, "n_max") / expected, 1.0, 1e-9) << json;
  EXPECT_NEAR(flexmoor::test::summaryValue(json, "n_min") / expected, 1.0, 1e-9) << json;
  EXPECT_NE(json.find("\"n_max\": \"N/m\""), std::string::npos) << json;

  // VTK: one value per cell (the two cables first, written as 0, then the eight triangles).
  const std::string vtk = flexmoor::test::readFile(dir / "stretched-sheet-1.vtk");
  for (const char* name : {"resultant_max", "resultant_min"}) {
    const std::vector<double> n = cellScalars(vtk, name, elements);
    ASSERT_EQ(n.size(), elements) << name;
    for (size_t e = 0; e < 2; ++e) EXPECT_EQ(n[e], 0.0) << name << " cable " << e;
    for (size_t e = 2; e < elements; ++e) EXPECT_NEAR(n[e] / expected, 1.0, 1e-9) << name << e;
  }
}

}  // namespace
