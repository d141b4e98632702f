// NetcdfWriter: the file it streams, read back through the netCDF C API.
#include "apps/output/netcdf_writer.hpp"

#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "tests/support/netcdf_reader.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
using Reader = test::NetcdfReader;

// Three nodes along x (0, 5, 10 ft) joined by one three-node cable element.
Case threeNodeCableCase() {
  Case c;
  c.name = "writer-test";
  c.title = "one three-node cable";
  c.file = "writer-test.yaml";
  c.units = UnitSystem::US;
  c.model = std::make_unique<model::Model>();
  for (int n = 0; n < 3; ++n) c.model->addNode(Eigen::Vector3d(5.0 * n, 0.0, 0.0));
  element::CableSection section;
  section.area = 0.1;
  section.density = 0.03;
  section.material =
      std::make_shared<material::LinearElasticCable>(1.0e6, material::Compression::TensionOnly);
  c.model->addElement(element::makeCableElement({0, 1, 2}, section));
  return c;
}

// A state whose values encode the step, node and component: u = step + node / 10 + k / 100.
model::State stateOfStep(int step) {
  model::State s(3);
  for (int n = 0; n < 3; ++n)
    for (int k = 0; k < 3; ++k) {
      s.displacement(k, n) = step + 0.1 * n + 0.01 * k;
      s.velocity(k, n) = -s.displacement(k, n);
    }
  s.time = 0.5 * step;
  s.load_factor = 0.25 * step;
  return s;
}

ResultFrame frameOf(int step, const model::State& s) {
  ResultFrame f;
  f.step_index = step;
  f.step_name = step == 0 ? "relax" : "static";
  f.state = &s;
  f.elements.resize(1);
  f.elements[0].point_tension = {10.0 + step, 11.0 + step, 12.0 + step};
  f.elements[0].end_tension[0] = 9.5 + step;
  f.elements[0].end_tension[1] = 12.5 + step;
  f.reactions = model::NodalField::Zero(3, 3);
  f.reactions(2, 0) = -3.0 - step;
  return f;
}

class NetcdfWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexmoor-netcdf-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    path_ = (dir_ / "writer-test.nc").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  Case case_ = threeNodeCableCase();
  model::State first_ = stateOfStep(0), second_ = stateOfStep(1);
  fs::path dir_;
  std::string path_;
};

TEST_F(NetcdfWriterTest, DimensionsMeshAndGlobalAttributesDescribeTheModel) {
  {
    NetcdfWriter writer(path_, *case_.model, case_);
    writer.write(frameOf(0, first_));
    writer.write(frameOf(1, second_));
  }
  const Reader nc(path_);
  EXPECT_EQ(nc.dimension("node"), 3u);
  EXPECT_EQ(nc.dimension("element"), 1u);
  EXPECT_EQ(nc.dimension("end"), 2u);
  EXPECT_EQ(nc.dimension("element_node"), 3u);
  EXPECT_EQ(nc.dimension("point"), 3u);
  EXPECT_EQ(nc.dimension("time"), 2u);
  EXPECT_EQ(nc.text(NC_GLOBAL, "Conventions"), "CF-1.8");
  EXPECT_EQ(nc.text(NC_GLOBAL, "title"), "one three-node cable");
  EXPECT_EQ(nc.text(NC_GLOBAL, "case_name"), "writer-test");
  EXPECT_EQ(nc.text(NC_GLOBAL, "source").rfind("flexmoor", 0), 0u);
  EXPECT_NE(nc.text(NC_GLOBAL, "history").find("writer-test.yaml"), std::string::npos);

  EXPECT_EQ(nc.doubles("node_x"), (std::vector<double>{0.0, 5.0, 10.0}));
  EXPECT_EQ(nc.doubles("node_z"), (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(nc.row("element_type", 0), "cable3");
  EXPECT_EQ(nc.ints("element_node_count"), (std::vector<int>{3}));
  EXPECT_EQ(nc.ints("element_nodes"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(nc.text(nc.variable("element_node_count"), "sample_dimension"), "element_node");
  EXPECT_EQ(nc.ints("element_point_count"), (std::vector<int>{3}));
  EXPECT_EQ(nc.ints("point_element"), (std::vector<int>{1, 1, 1}));
}

TEST_F(NetcdfWriterTest, VariablesCarryUnitsOfTheCaseUnitSystem) {
  { NetcdfWriter(path_, *case_.model, case_).write(frameOf(0, first_)); }
  const Reader nc(path_);
  EXPECT_EQ(nc.units("node_y"), "ft");
  EXPECT_EQ(nc.units("displacement_x"), "ft");
  EXPECT_EQ(nc.units("position_z"), "ft");
  EXPECT_EQ(nc.units("velocity_x"), "ft/s");
  EXPECT_EQ(nc.units("reaction_z"), "lbf");
  EXPECT_EQ(nc.units("tension_end"), "lbf");
  EXPECT_EQ(nc.units("tension_point"), "lbf");
  EXPECT_EQ(nc.units("time"), "s");
  EXPECT_EQ(nc.units("load_factor"), "1");
  EXPECT_FALSE(nc.text(nc.variable("displacement_x"), "long_name").empty());
}

// CF-1.8: time is the record coordinate (4.4), nodes and elements are numbered coordinates, and
// every record variable names its auxiliary coordinates (5) so that readers attach them.
TEST_F(NetcdfWriterTest, CoordinatesAreDeclaredTheCfWay) {
  { NetcdfWriter(path_, *case_.model, case_).write(frameOf(0, first_)); }
  const Reader nc(path_);
  EXPECT_EQ(nc.text(nc.variable("time"), "standard_name"), "time");
  EXPECT_EQ(nc.text(nc.variable("time"), "axis"), "T");
  EXPECT_EQ(nc.ints("node"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(nc.ints("element"), (std::vector<int>{1}));
  EXPECT_EQ(nc.doubles("element_x"), (std::vector<double>{5.0}));  // centroid of 0, 5, 10 ft
  EXPECT_EQ(nc.text(nc.variable("displacement_x"), "coordinates"),
            "step_number step_name load_factor node_x node_y node_z");
  EXPECT_EQ(nc.text(nc.variable("tension_end"), "coordinates"),
            "step_number step_name load_factor element_x element_y element_z");
  EXPECT_EQ(nc.text(nc.variable("tension_point"), "coordinates"),
            "step_number step_name load_factor point_element");
  EXPECT_EQ(nc.text(nc.variable("step_name"), "_Encoding"), "utf-8");
}

// An element without an axial force (a membrane or a point mass reports no line tensions) gets
// tension_end's _FillValue, not a zero force.
TEST_F(NetcdfWriterTest, EndTensionIsMissingOnElementsWithoutAxialForce) {
  ResultFrame frame = frameOf(0, first_);
  frame.elements[0].point_tension.clear();
  { NetcdfWriter(path_, *case_.model, case_).write(frame); }
  const Reader nc(path_);
  EXPECT_EQ(nc.doubles("tension_end"), (std::vector<double>{NC_FILL_DOUBLE, NC_FILL_DOUBLE}));
}

// Records are synced at most once a second (NetcdfFile::sync); flush() puts them on disk now.
TEST_F(NetcdfWriterTest, EachRecordIsReadableFromDiskOnceFlushed) {
  NetcdfWriter writer(path_, *case_.model, case_);
  EXPECT_EQ(Reader(path_).dimension("time"), 0u);
  writer.write(frameOf(0, first_));
  writer.flush();
  EXPECT_EQ(Reader(path_).dimension("time"), 1u);
  writer.write(frameOf(1, second_));
  writer.flush();
  EXPECT_EQ(writer.records(), 2u);

  const Reader nc(path_);  // the writer is still open: the records were flushed
  EXPECT_EQ(nc.dimension("time"), 2u);
  EXPECT_EQ(nc.row("step_name", 0), "relax");
  EXPECT_EQ(nc.row("step_name", 1), "static");
  EXPECT_EQ(nc.ints("step_number"), (std::vector<int>{1, 2}));
  EXPECT_EQ(nc.doubles("time"), (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(nc.doubles("load_factor"), (std::vector<double>{0.0, 0.25}));
  // (step, node): u_y = step + node / 10 + 1 / 100; position = reference + displacement.
  const std::vector<double> uy = nc.doubles("displacement_y");
  const std::vector<double> x = nc.doubles("position_x");
  const std::vector<double> vz = nc.doubles("velocity_z");
  ASSERT_EQ(uy.size(), 6u);
  for (int step = 0; step < 2; ++step)
    for (int n = 0; n < 3; ++n) {
      EXPECT_DOUBLE_EQ(uy[3 * step + n], step + 0.1 * n + 0.01);
      EXPECT_DOUBLE_EQ(x[3 * step + n], 5.0 * n + step + 0.1 * n);
      EXPECT_DOUBLE_EQ(vz[3 * step + n], -(step + 0.1 * n + 0.02));
    }
  EXPECT_EQ(nc.doubles("reaction_z"), (std::vector<double>{-3.0, 0.0, 0.0, -4.0, 0.0, 0.0}));
  EXPECT_EQ(nc.doubles("tension_end"), (std::vector<double>{9.5, 12.5, 10.5, 13.5}));
  EXPECT_EQ(nc.doubles("tension_point"), (std::vector<double>{10.0, 11.0, 12.0, 11.0, 12.0, 13.0}));
}

// `output: fields:` (apps/problem/output_fields.hpp): the records hold the fields listed and no
// others, the listed ones with the values of a full file (exactly: the same doubles copied), and
// a frame without element results or reactions is written when none of those is listed.
TEST_F(NetcdfWriterTest, OnlyTheListedFieldsAreWritten) {
  case_.output = OutputFields::none();
  case_.output.add(OutputField::Position);
  case_.output.add(OutputField::Velocity);
  EXPECT_FALSE(case_.output.needsResults());
  {
    NetcdfWriter writer(path_, *case_.model, case_);
    EXPECT_FALSE(writer.needsResults());
    writer.write(frameOf(0, first_));
    ResultFrame bare = frameOf(1, second_);  // what Simulation streams: no results asked for
    bare.elements.clear();
    bare.reactions.resize(3, 0);
    writer.write(bare);
  }
  int id = -1;
  ASSERT_EQ(nc_open(path_.c_str(), NC_NOWRITE, &id), NC_NOERR);
  int variable = -1;
  for (const char* absent : {"displacement_x", "reaction_z", "tension_end", "tension_point",
                             "point_element", "wave_elevation"})
    EXPECT_EQ(nc_inq_varid(id, absent, &variable), NC_ENOTVAR) << absent;
  int point = -1;
  EXPECT_EQ(nc_inq_dimid(id, "point", &point), NC_EBADDIM);
  nc_close(id);
  const Reader nc(path_);
  EXPECT_EQ(nc.dimension("time"), 2u);
  const std::vector<double> x = nc.doubles("position_x");
  const std::vector<double> vz = nc.doubles("velocity_z");
  for (int step = 0; step < 2; ++step)
    for (int n = 0; n < 3; ++n) {
      EXPECT_DOUBLE_EQ(x[3 * step + n], 5.0 * n + step + 0.1 * n);
      EXPECT_DOUBLE_EQ(vz[3 * step + n], -(step + 0.1 * n + 0.02));
    }
  EXPECT_EQ(nc.ints("step_number"), (std::vector<int>{1, 2}));
}

// With tensions listed, a frame without element results is refused (it cannot be written).
TEST_F(NetcdfWriterTest, AFrameWithoutTheResultsItsFieldsNeedIsRefused) {
  case_.output = OutputFields::none();
  case_.output.add(OutputField::Tension);
  NetcdfWriter writer(path_, *case_.model, case_);
  EXPECT_TRUE(writer.needsResults());
  ResultFrame bare = frameOf(0, first_);
  bare.elements.clear();
  EXPECT_THROW(writer.write(bare), std::runtime_error);
  EXPECT_EQ(writer.records(), 0u);
}

// A frame whose results are still pending (a sink that completes them did not) is refused, not
// written with whatever its storage held.
TEST_F(NetcdfWriterTest, AFrameWithPendingResultsIsRefused) {
  NetcdfWriter writer(path_, *case_.model, case_);
  case_.model->numberEquations();
  const model::Assembler assembler(*case_.model);
  ResultFrame pending = frameOf(0, first_);
  pending.pending = &assembler;
  try {
    writer.write(pending);
    FAIL() << "a frame with pending results was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("still to be computed"), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.records(), 0u);
}

TEST_F(NetcdfWriterTest, NaNDisplacementIsRefusedNamingVariableAndIndex) {
  NetcdfWriter writer(path_, *case_.model, case_);
  writer.write(frameOf(0, first_));
  second_.displacement(1, 2) = std::numeric_limits<double>::quiet_NaN();
  try {
    writer.write(frameOf(1, second_));
    FAIL() << "a NaN displacement was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("displacement_y[record 1, node 2] is NaN"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(path_), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.records(), 1u);
  writer.flush();
  EXPECT_EQ(Reader(path_).dimension("time"), 1u);  // nothing of the refused record was written
}

TEST_F(NetcdfWriterTest, InfiniteTensionIsRefused) {
  NetcdfWriter writer(path_, *case_.model, case_);
  ResultFrame frame = frameOf(0, first_);
  frame.elements[0].point_tension[1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writer.write(frame), std::runtime_error);
  EXPECT_EQ(writer.records(), 0u);
}

TEST_F(NetcdfWriterTest, FrameWithAnotherPointLayoutIsRefused) {
  NetcdfWriter writer(path_, *case_.model, case_);
  writer.write(frameOf(0, first_));
  ResultFrame frame = frameOf(1, second_);
  frame.elements[0].point_tension.push_back(1.0);
  EXPECT_THROW(writer.write(frame), std::runtime_error);
}

// Resident memory of this process in bytes (/proc/self/statm).
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double size = 0.0, resident = 0.0;
  statm >> size >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// A long series costs memory that does not grow with it: records reach HDF5 a chunk at a time
// and its chunk cache, which would keep every chunk written (the memory of a run grew with its
// file: 81 MB against 30 MB for the demo case written 40,000 times), is off for them. 151 nodes,
// 1,500 records (29 MB of values, 14 chunks of each nodal variable): the growth of resident
// memory after the first record stays below a tenth of what was written (measured 0.34 MB; with
// HDF5's cache on, 27.7 MB). Every value of the last record reads back exactly.
TEST_F(NetcdfWriterTest, MemoryDoesNotGrowWithTheRecordsWritten) {
  Case c;
  c.name = "long-series";
  c.units = UnitSystem::SI;
  c.model = std::make_unique<model::Model>();
  const int nodes = 151;
  for (int n = 0; n < nodes; ++n) c.model->addNode(Eigen::Vector3d(0.1 * n, 0.0, 0.0));
  element::CableSection section;
  section.area = 1e-4;
  section.density = 7850.0;
  section.material =
      std::make_shared<material::LinearElasticCable>(2e7, material::Compression::TensionOnly);
  for (int n = 0; n + 1 < nodes; ++n)
    c.model->addElement(element::makeCableElement({n, n + 1}, section));
  model::State s(nodes);
  ResultFrame f;
  f.step_name = "dynamic";
  f.state = &s;
  f.elements.resize(nodes - 1);
  for (auto& r : f.elements) r.point_tension = {1.0, 2.0};
  f.reactions = model::NodalField::Zero(3, nodes);
  const int records = 1500;
  double before = 0.0, written = 0.0;
  {
    NetcdfWriter writer(path_, *c.model, c);
    writer.write(f);
    before = residentBytes();
    for (int r = 1; r < records; ++r) {
      s.time = 0.01 * r;
      s.displacement.setConstant(1e-3 * r);
      s.velocity.setConstant(-1e-3 * r);
      writer.write(f);
    }
    written = (records - 1) * (12.0 * nodes + 4.0 * (nodes - 1) + 2.0) * sizeof(double);
    EXPECT_LT(residentBytes() - before, 0.1 * written)
        << "resident memory grew by " << (residentBytes() - before) / 1e6 << " MB while "
        << written / 1e6 << " MB were written";
  }
  const Reader nc(path_);
  ASSERT_EQ(nc.dimension("time"), static_cast<size_t>(records));
  const std::vector<double> u = nc.doubles("displacement_z");
  for (int n = 0; n < nodes; ++n)
    EXPECT_EQ(u[static_cast<size_t>(records - 1) * nodes + n], 1e-3 * (records - 1));
}

TEST_F(NetcdfWriterTest, UnwritablePathThrowsWithNetcdfErrorText) {
  const std::string bad = (dir_ / "missing-directory" / "x.nc").string();
  try {
    NetcdfWriter writer(bad, *case_.model, case_);
    FAIL() << "created " << bad;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad + ": cannot create the file: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace flexmoor::app
