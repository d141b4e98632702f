#include "apps/output/vtk_writer.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/output/atomic_output.hpp"
#include "apps/output/finite_value.hpp"
#include "apps/output/membrane_resultants.hpp"

namespace flexmoor::app {
namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkPolyLine = 4;
constexpr int kVtkTriangle = 5;
constexpr int kVtkPolygon = 7;
constexpr int kVtkQuad = 9;
constexpr int kVtkQuadraticTriangle = 22;
constexpr int kVtkQuadraticQuad = 23;

struct VtkCell {
  int type;
  std::vector<int> nodes;
};

// The VTK cell of an element. Membrane node orders are VTK's already for Q4, Q8, T3 and T6
// (libstruct/shape); the cubic Q12 and T10 are drawn as polygons through their boundary nodes.
VtkCell vtkCell(const element::Element& e) {
  const std::vector<int>& n = e.nodes();
  const std::string type = e.typeName();
  if (n.size() == 1) return {kVtkVertex, n};
  if (type.rfind("membrane", 0) != 0) return {kVtkPolyLine, n};
  switch (n.size()) {
    case 3:
      return {kVtkTriangle, n};
    case 4:
      return {kVtkQuad, n};
    case 6:
      return {kVtkQuadraticTriangle, n};
    case 8:
      return {kVtkQuadraticQuad, n};
    case 10:  // corners 0 1 2, edge nodes 3 4 | 5 6 | 7 8, centroid 9
      return {kVtkPolygon, {n[0], n[3], n[4], n[1], n[5], n[6], n[2], n[7], n[8]}};
    case 12:  // corners 0 1 2 3, edge nodes 4 5 | 6 7 | 8 9 | 10 11
      return {kVtkPolygon,
              {n[0], n[4], n[5], n[1], n[6], n[7], n[2], n[8], n[9], n[3], n[10], n[11]}};
  }
  return {kVtkPolyLine, n};
}

double meanTension(const element::ElementResult& r) {
  if (r.point_tension.empty()) return 0.0;
  return std::accumulate(r.point_tension.begin(), r.point_tension.end(), 0.0) /
         static_cast<double>(r.point_tension.size());
}

void requireMatches(const std::string& path, const model::Model& model, const ResultFrame& frame) {
  const int nodes = model.nodeCount();
  if (!frame.state || frame.state->displacement.cols() != nodes ||
      frame.reactions.cols() != nodes ||
      static_cast<int>(frame.elements.size()) != model.elementCount())
    throw std::runtime_error(path + ": the result frame of step \"" + frame.step_name +
                             "\" does not match the model (" + std::to_string(nodes) + " nodes, " +
                             std::to_string(model.elementCount()) + " elements)");
}

// One "x y z" line per node.
void writeTriples(std::ostream& os, const std::string& path, const char* name,
                  const model::NodalField& field) {
  for (int n = 0; n < field.cols(); ++n) {
    for (int k = 0; k < 3; ++k) {
      requireFinite(field(k, n), path, [&] {
        return std::string(name) + " of node " + std::to_string(n) + " (0-based), component " +
               std::to_string(k);
      });
      os << (k ? " " : "") << field(k, n);
    }
    os << "\n";
  }
}

void writeCells(std::ostream& os, const model::Model& model) {
  std::vector<VtkCell> cells;
  int size = 0;
  for (const auto& e : model.elements()) {
    cells.push_back(vtkCell(*e));
    size += 1 + static_cast<int>(cells.back().nodes.size());
  }
  os << "CELLS " << cells.size() << " " << size << "\n";
  for (const VtkCell& c : cells) {
    os << c.nodes.size();
    for (const int n : c.nodes) os << " " << n;
    os << "\n";
  }
  os << "CELL_TYPES " << cells.size() << "\n";
  for (const VtkCell& c : cells) os << c.type << "\n";
}

// One cell scalar: the mean tension of cables and springs, and the principal resultants of
// membranes (zero on the other elements).
template <class Value>
void writeCellScalar(std::ostream& os, const std::string& path, const ResultFrame& frame,
                     const char* name, Value value) {
  os << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
  for (size_t e = 0; e < frame.elements.size(); ++e) {
    const double v = value(frame.elements[e]);
    requireFinite(v, path, [&] {
      return std::string(name) + " of element " + std::to_string(e) + " (0-based)";
    });
    os << v << "\n";
  }
}

void writeCellData(std::ostream& os, const std::string& path, const ResultFrame& frame) {
  os << "CELL_DATA " << frame.elements.size() << "\n";
  writeCellScalar(os, path, frame, "tension", meanTension);
  const bool membranes = std::any_of(frame.elements.begin(), frame.elements.end(),
                                     [](const auto& r) { return !r.point_resultant.empty(); });
  if (!membranes) return;
  writeCellScalar(os, path, frame, "resultant_max", [](const element::ElementResult& r) {
    return principalResultants(r).value_or(std::pair(0.0, 0.0)).first;
  });
  writeCellScalar(os, path, frame, "resultant_min", [](const element::ElementResult& r) {
    return principalResultants(r).value_or(std::pair(0.0, 0.0)).second;
  });
}

}  // namespace

void writeVtk(const std::string& path, const model::Model& model, const ResultFrame& frame) {
  requireMatches(path, model, frame);
  const int nodes = model.nodeCount();

  std::ostringstream text;
  text.precision(std::numeric_limits<double>::max_digits10);
  text << "# vtk DataFile Version 3.0\n"
       << "flexmoor step " << frame.step_index + 1 << " (deformed configuration)\n"
       << "ASCII\nDATASET UNSTRUCTURED_GRID\n"
       << "POINTS " << nodes << " double\n";
  writeTriples(text, path, "position", model.reference() + frame.state->displacement);
  writeCells(text, model);
  text << "POINT_DATA " << nodes << "\nVECTORS displacement double\n";
  writeTriples(text, path, "displacement", frame.state->displacement);
  text << "VECTORS reaction double\n";
  writeTriples(text, path, "reaction", frame.reactions);
  for (size_t k = 0; k < frame.mode_shapes.size(); ++k) {  // a modes step: one field per mode
    const std::string name = "mode_" + std::to_string(k + 1);
    text << "VECTORS " << name << " double\n";
    writeTriples(text, path, name.c_str(), frame.mode_shapes[k]);
  }
  writeCellData(text, path, frame);

  writeFileAtomically(path, text.str());
}

}  // namespace flexmoor::app
