#include "apps/output/vtk_writer.hpp"

#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "apps/output/finite_value.hpp"

namespace flexmoor::app {
namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkPolyLine = 4;

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
  int size = 0;
  for (const auto& e : model.elements()) size += 1 + static_cast<int>(e->nodes().size());
  os << "CELLS " << model.elementCount() << " " << size << "\n";
  for (const auto& e : model.elements()) {
    os << e->nodes().size();
    for (const int n : e->nodes()) os << " " << n;
    os << "\n";
  }
  os << "CELL_TYPES " << model.elementCount() << "\n";
  for (const auto& e : model.elements())
    os << (e->nodes().size() == 1 ? kVtkVertex : kVtkPolyLine) << "\n";
}

void writeTension(std::ostream& os, const std::string& path, const ResultFrame& frame) {
  os << "CELL_DATA " << frame.elements.size() << "\nSCALARS tension double 1\n"
     << "LOOKUP_TABLE default\n";
  for (size_t e = 0; e < frame.elements.size(); ++e) {
    const double t = meanTension(frame.elements[e]);
    requireFinite(t, path,
                  [&] { return "tension of element " + std::to_string(e) + " (0-based)"; });
    os << t << "\n";
  }
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
  writeTension(text, path, frame);

  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text.str();
  file.close();
  if (!file) throw std::runtime_error(path + ": cannot write the VTK file");
}

}  // namespace flexmoor::app
