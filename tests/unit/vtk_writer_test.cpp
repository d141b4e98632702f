// writeVtk: the legacy VTK file of the deformed configuration.
#include "apps/output/vtk_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/material/cable_material.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

class VtkWriterTest : public ::testing::Test {
 protected:
  // Nodes 0, 1, 2 along x joined by a three-node cable; a point mass at node 2.
  void SetUp() override {
    for (int n = 0; n < 3; ++n) model_.addNode(Eigen::Vector3d(5.0 * n, 0.0, 0.0));
    element::CableSection section;
    section.area = 0.1;
    section.density = 0.03;
    section.material =
        std::make_shared<material::LinearElasticCable>(1.0e6, material::Compression::TensionOnly);
    model_.addElement(element::makeCableElement({0, 1, 2}, section));
    model_.addElement(std::make_unique<element::PointMassElement>(2, 1.0));

    state_.displacement.col(1) = Eigen::Vector3d(0.0, 0.0, -1.5);
    frame_.state = &state_;
    frame_.reactions = model::NodalField::Zero(3, 3);
    frame_.reactions(2, 0) = 4.0;
    frame_.elements.resize(2);
    frame_.elements[0].point_tension = {10.0, 20.0, 30.0};

    dir_ = fs::temp_directory_path() /
           ("flexmoor-vtk-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    path_ = (dir_ / "case-1.vtk").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string written() const {
    std::ifstream in(path_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  bool has(const std::string& text) const { return written().find(text) != std::string::npos; }

  model::Model model_;
  model::State state_{3};
  ResultFrame frame_;
  fs::path dir_;
  std::string path_;
};

TEST_F(VtkWriterTest, OnePolyLinePerCableAndOneVertexPerPointMass) {
  writeVtk(path_, model_, frame_);
  EXPECT_EQ(written().rfind("# vtk DataFile Version 3.0\n", 0), 0u);
  EXPECT_TRUE(has("DATASET UNSTRUCTURED_GRID\n"));
  EXPECT_TRUE(has("POINTS 3 double\n"));
  EXPECT_TRUE(has("CELLS 2 6\n3 0 1 2\n1 2\n"));
  EXPECT_TRUE(has("CELL_TYPES 2\n4\n1\n"));
}

TEST_F(VtkWriterTest, PointsAreTheDeformedConfiguration) {
  writeVtk(path_, model_, frame_);
  EXPECT_TRUE(has("POINTS 3 double\n0 0 0\n5 0 -1.5\n10 0 0\n"));
}

TEST_F(VtkWriterTest, PointDataHoldsDisplacementAndReactionVectors) {
  writeVtk(path_, model_, frame_);
  EXPECT_TRUE(has("POINT_DATA 3\nVECTORS displacement double\n0 0 0\n0 0 -1.5\n0 0 0\n"));
  EXPECT_TRUE(has("VECTORS reaction double\n0 0 4\n0 0 0\n0 0 0\n"));
}

TEST_F(VtkWriterTest, CellTensionIsTheMeanOfThePointTensions) {
  writeVtk(path_, model_, frame_);
  EXPECT_TRUE(has("CELL_DATA 2\nSCALARS tension double 1\nLOOKUP_TABLE default\n20\n0\n"));
}

TEST_F(VtkWriterTest, NaNDisplacementIsRefusedAndNoFileIsWritten) {
  state_.displacement(0, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(writeVtk(path_, model_, frame_), std::runtime_error);
  EXPECT_FALSE(fs::exists(path_));
}

}  // namespace
}  // namespace flexmoor::app
