// NetcdfWriter's layout (netcdf_writer.hpp): the two record dimensions (time: the dynamic steps'
// records, strictly increasing; stage: the states closing the other steps, by step number), the
// end coordinate, and the lines (names, anchors, each node's and element's line, arc lengths).
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/output/netcdf_writer.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "tests/support/netcdf_reader.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
using Reader = test::NetcdfReader;

// Two-node cables: "moor" (nodes 0-1-2 at x = 0, 3, 7 m, elements 1-2; a mooring line anchored
// at its start, its segment "moor_top" the second element), "bridle" (nodes 2-3, 5 m up z,
// element 3, anchored at its end) and element 4 (nodes 3-4) on no line.
Case linesCase() {
  Case c;
  c.name = "layout-test";
  c.units = UnitSystem::SI;
  c.model = std::make_unique<model::Model>();
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(7, 0, 0),
        Eigen::Vector3d(7, 0, 5), Eigen::Vector3d(9, 0, 5)})
    c.model->addNode(x);
  element::CableSection section;
  section.area = 1e-4;
  section.density = 7850.0;
  section.material =
      std::make_shared<material::LinearElasticCable>(2e11, material::Compression::TensionOnly);
  for (const auto& [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 4}})
    c.model->addElement(element::makeCableElement({a, b}, section));
  c.named_lines.push_back({"moor", {0, 1, 2}, {0, 1}, "", CaseLine::Anchor::Start});
  c.named_lines.push_back({"moor_top", {1, 2}, {1}, "moor", CaseLine::Anchor::None});  // segment
  c.named_lines.push_back({"bridle", {2, 3}, {2}, "", CaseLine::Anchor::End});
  return c;
}

model::State stateAt(double time, double u) {
  model::State s(5);
  s.displacement.setConstant(u);
  s.time = time;
  s.load_factor = 1.0;
  return s;
}

ResultFrame frameOf(int step, const std::string& name, const model::State& s, bool stage) {
  ResultFrame f;
  f.step_index = step;
  f.step_name = name;
  f.stage = stage;
  f.state = &s;
  f.elements.resize(4);
  for (size_t e = 0; e < 4; ++e) {
    f.elements[e].point_tension = {100.0 + e, 101.0 + e};
    f.elements[e].end_tension[0] = 10.0 * e + 1.0;
    f.elements[e].end_tension[1] = 10.0 * e + 2.0;
  }
  f.reactions = model::NodalField::Zero(3, 5);
  return f;
}

class NetcdfLayoutTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexmoor-layout-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    path_ = (dir_ / "layout-test.nc").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  Case case_ = linesCase();
  fs::path dir_;
  std::string path_;
};

// A static step (time 0), a dynamic step from 0 to 1 s, a second static step at 1 s: the static
// steps' states are stage records 1 and 3, the dynamic records keep time 0, 0.5, 1 s, once each.
TEST_F(NetcdfLayoutTest, StaticStepsAreStageRecordsAndTimeIsStrictlyIncreasing) {
  const model::State equilibrium = stateAt(0.0, 0.1), start = stateAt(0.0, 0.1),
                     half = stateAt(0.5, 0.2), end = stateAt(1.0, 0.3), after = stateAt(1.0, 0.4);
  {
    NetcdfWriter writer(path_, *case_.model, case_);
    writer.write(frameOf(0, "equilibrium", equilibrium, true));
    writer.write(frameOf(1, "shake", start, false));
    writer.write(frameOf(1, "shake", half, false));
    writer.write(frameOf(1, "shake", end, false));
    writer.write(frameOf(2, "settle", after, true));
    EXPECT_EQ(writer.records(), 3u);
    EXPECT_EQ(writer.stageRecords(), 2u);
  }
  const Reader nc(path_);
  EXPECT_EQ(nc.dimension("time"), 3u);
  EXPECT_EQ(nc.dimension("stage"), 2u);
  EXPECT_EQ(nc.doubles("time"), (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(nc.ints("step_number"), (std::vector<int>{2, 2, 2}));
  EXPECT_EQ(nc.ints("stage"), (std::vector<int>{1, 3}));
  EXPECT_EQ(nc.row("stage_step", 0), "equilibrium");
  EXPECT_EQ(nc.row("stage_step", 1), "settle");
  EXPECT_EQ(nc.doubles("stage_time"), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(nc.doubles("stage_load_factor"), (std::vector<double>{1.0, 1.0}));
  const std::vector<double> u = nc.doubles("displacement_z"),
                            us = nc.doubles("stage_displacement_z");
  ASSERT_EQ(u.size(), 15u);
  ASSERT_EQ(us.size(), 10u);
  EXPECT_EQ(u[5], 0.2);
  EXPECT_EQ(us[0], 0.1);
  EXPECT_EQ(us[5], 0.4);
  EXPECT_EQ(nc.doubles("stage_tension_end")[2 * 3 + 1], 32.0);  // element 4, its last end
  EXPECT_EQ(nc.text(nc.variable("stage_displacement_x"), "coordinates"),
            "stage_step stage_time stage_load_factor node_x node_y node_z node_line "
            "node_arc_length");
  EXPECT_EQ(nc.text(nc.variable("stage_tension_point"), "coordinates"),
            "stage_step stage_time stage_load_factor point_element");
  EXPECT_EQ(nc.text(nc.variable("stage"), "long_name"),
            "analysis step whose closing state (or last converged state) the record is, 1-based");
}

// The writer refuses a time record that is not after the last one and a second stage record of
// a step, writing nothing of either.
TEST_F(NetcdfLayoutTest, RepeatedTimesAndStepsAreRefused) {
  const model::State a = stateAt(0.5, 0.1), b = stateAt(0.5, 0.2), c = stateAt(0.25, 0.3);
  NetcdfWriter writer(path_, *case_.model, case_);
  writer.write(frameOf(1, "shake", a, false));
  for (const model::State* s : {&b, &c}) {
    try {
      writer.write(frameOf(1, "shake", *s, false));
      FAIL() << "a record at " << s->time << " s was written after one at 0.5 s";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("is not after the last record's, 0.5"),
                std::string::npos)
          << e.what();
    }
  }
  writer.write(frameOf(0, "equilibrium", a, true));
  EXPECT_THROW(writer.write(frameOf(0, "equilibrium", b, true)), std::runtime_error);
  EXPECT_EQ(writer.records(), 1u);
  EXPECT_EQ(writer.stageRecords(), 1u);
  writer.flush();
  const Reader nc(path_);
  EXPECT_EQ(nc.doubles("time"), (std::vector<double>{0.5}));
  EXPECT_EQ(nc.ints("stage"), (std::vector<int>{1}));
}

// end(end) = 1, 2: a label, so that a reader's sel(end=1) is the element's first node.
TEST_F(NetcdfLayoutTest, EndIsACoordinateOfOneAndTwo) {
  const model::State s = stateAt(0.0, 0.0);
  { NetcdfWriter(path_, *case_.model, case_).write(frameOf(0, "shake", s, false)); }
  const Reader nc(path_);
  EXPECT_EQ(nc.ints("end"), (std::vector<int>{1, 2}));
  EXPECT_EQ(nc.text(nc.variable("end"), "long_name"),
            "end of the element: 1 = its first node, 2 = its last node");
  EXPECT_EQ(nc.doubles("tension_end")[0], 1.0);  // element 1's first end, the frame's end 0
}

// The whole lines (not the segment moor_top) in the case's order; nodes and elements mapped to
// them (node 2, where moor and bridle meet, is moor's; node 4 and element 4 are on no line); arc
// lengths along each line's reference from its start: exactly the reference distances summed.
TEST_F(NetcdfLayoutTest, LinesNameTheirNodesAndElements) {
  const model::State s = stateAt(0.0, 0.0);
  { NetcdfWriter(path_, *case_.model, case_).write(frameOf(0, "shake", s, false)); }
  const Reader nc(path_);
  EXPECT_EQ(nc.dimension("line"), 2u);
  EXPECT_EQ(nc.ints("line"), (std::vector<int>{1, 2}));
  EXPECT_EQ(nc.row("line_name", 0), "moor");
  EXPECT_EQ(nc.row("line_name", 1), "bridle");
  EXPECT_EQ(nc.ints("line_anchor"), (std::vector<int>{1, 2}));
  EXPECT_EQ(nc.text(nc.variable("line_anchor"), "flag_meanings"),
            "no_anchor anchor_at_start anchor_at_end");
  EXPECT_EQ(nc.ints("node_line"), (std::vector<int>{1, 1, 1, 2, 0}));
  EXPECT_EQ(nc.ints("element_line"), (std::vector<int>{1, 1, 2, 0}));
  const std::vector<double> arc = nc.doubles("node_arc_length");
  EXPECT_EQ(arc, (std::vector<double>{0.0, 3.0, 7.0, 5.0, NC_FILL_DOUBLE}));
  EXPECT_EQ(nc.units("node_arc_length"), "m");
  EXPECT_EQ(nc.text(nc.variable("tension_end"), "coordinates"),
            "step_number step_name load_factor element_x element_y element_z element_line");
}

}  // namespace
}  // namespace flexmoor::app
