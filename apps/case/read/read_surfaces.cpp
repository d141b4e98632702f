// surfaces: of a case file: each item's shape, geometry, element kind, divisions, section and
// cables, checked and meshed by meshSurface (surface_mesh.hpp, which describes the shapes).
#include <Eigen/Geometry>
#include <cmath>

#include "apps/case/build/surface_mesh.hpp"
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

// Adds the surface's nodes (merged with existing ones), its membrane elements, cell by cell, then
// the cables of each row, as a PendingSurface of the builder, and records its nodes by name.
void generateSurface(CaseBuilder& b, const SurfaceSpec& s, const std::vector<CableRow>& rows,
                     int line) {
  SurfaceElements mesh = meshSurface(b.mesh.reference, s, rows, [&](const Eigen::Vector3d& x) {
    return b.addGeneratedNode(x, line);
  });
  if (s.map.shape == SurfaceShape::Meridian)
    for (int node : mesh.nodes)  // y carries nothing
      b.conditions.supports.push_back({node, 1, 0.0, nullptr, 0});
  PendingSurface pending{s.name, line, {}};
  for (SurfaceElements::Generated& e : mesh.elements)
    pending.elements.push_back(
        {e.type, b.sectionName(e.row_section ? e.row_section : s.section), std::move(e.element)});
  b.surfaces[s.name] = std::move(mesh.nodes);
  b.surface_elements.push_back(std::move(pending));
}

const std::vector<std::pair<std::string, ElementKind>>& elementKinds() {
  static const std::vector<std::pair<std::string, ElementKind>> kinds = {
      {"Q4", {false, 4, 1}}, {"Q8", {false, 8, 2}}, {"Q12", {false, 12, 3}},
      {"T3", {true, 3, 1}},  {"T6", {true, 6, 2}},  {"T10", {true, 10, 3}}};
  return kinds;
}

std::optional<std::array<int, 2>> readDivisions(CaseBuilder& b, const YAML::Node& n,
                                                const std::string& path) {
  if (!n.IsSequence() || n.size() != 2) {
    b.diag.error(n, path + ": expected [n1, n2], the cells along each direction (got " +
                        describeNode(n) + ")");
    return std::nullopt;
  }
  const auto n1 = b.in.integer(n[0], itemPath(path, 0), 1, 100000);
  const auto n2 = b.in.integer(n[1], itemPath(path, 1), 1, 100000);
  if (!n1 || !n2) return std::nullopt;
  return std::array<int, 2>{*n1, *n2};
}

// angles: [from, to] of a cylinder or disc (plain numbers are radians; `90 deg` works).
bool readAngles(CaseBuilder& b, Fields& f, SurfaceMap& m) {
  const YAML::Node* n = f.find("angles");
  if (!n) return true;
  if (!n->IsSequence() || n->size() != 2) {
    b.diag.error(*n, f.path("angles") + ": expected [from, to] (got " + describeNode(*n) + ")");
    return false;
  }
  const auto a0 = b.in.quantity((*n)[0], itemPath(f.path("angles"), 0), kind::kNumber);
  const auto a1 = b.in.quantity((*n)[1], itemPath(f.path("angles"), 1), kind::kNumber);
  if (!a0 || !a1) return false;
  if (!(std::abs(*a1 - *a0) > 0.0) || std::abs(*a1 - *a0) > 2.0 * M_PI + 1e-12) {
    b.diag.error(*n,
                 f.path("angles") + ": expected two different angles at most a full turn apart");
    return false;
  }
  m.theta0 = *a0;
  m.theta1 = *a1;
  return true;
}

// The geometric keys of each shape.
const std::vector<std::string>& keysOf(SurfaceShape shape) {
  static const std::vector<std::string> common = {"name",      "shape",     "element", "section",
                                                  "divisions", "diagonals", "cables"};
  static const auto with = [](std::vector<std::string> more) {
    more.insert(more.begin(), common.begin(), common.end());
    return more;
  };
  static const std::vector<std::string> rectangle = with({"corner", "side1", "side2"});
  static const std::vector<std::string> cylinder =
      with({"centre", "radius", "length", "angles", "axis"});
  static const std::vector<std::string> disc = with({"centre", "radius", "angles"});
  static const std::vector<std::string> meridian = {"name", "shape",    "section", "from",
                                                    "to",   "elements", "order",   "cables"};
  switch (shape) {
    case SurfaceShape::Rectangle:
      return rectangle;
    case SurfaceShape::Cylinder:
      return cylinder;
    case SurfaceShape::Disc:
      return disc;
    case SurfaceShape::Meridian:
      return meridian;
  }
  return rectangle;
}

bool readGeometry(CaseBuilder& b, Fields& f, SurfaceSpec& s) {
  Input& in = b.in;
  SurfaceMap& m = s.map;
  const auto vector = [&](const char* key, Eigen::Vector3d& out) {
    const YAML::Node* n = f.require(key);
    const auto v = n ? in.vector3(*n, f.path(key), kind::kLength) : std::nullopt;
    if (v) out = *v;
    return v.has_value();
  };
  const auto positive = [&](const char* key, double& out) {
    const YAML::Node* n = f.require(key);
    const auto v = n ? in.quantity(*n, f.path(key), kind::kLength, Limit::Positive) : std::nullopt;
    if (v) out = *v;
    return v.has_value();
  };
  switch (m.shape) {
    case SurfaceShape::Rectangle: {
      const bool ok =
          vector("corner", m.origin) & vector("side1", m.side1) & vector("side2", m.side2);
      if (ok && !(m.side1.cross(m.side2).norm() > 1e-12 * m.side1.norm() * m.side2.norm())) {
        b.diag.error(f.node(), f.path() +
                                   ": side1 and side2 are parallel or zero (expected two "
                                   "independent edge vectors)");
        return false;
      }
      return ok;
    }
    case SurfaceShape::Cylinder: {
      const YAML::Node* axis = f.find("axis");
      const auto k =
          axis ? in.choice<int>(*axis, f.path("axis"), {{"x", 0}, {"y", 1}, {"z", 2}}) : 2;
      if (k) m.axis = *k;
      return vector("centre", m.origin) & positive("radius", m.radius) &
             positive("length", m.length) & readAngles(b, f, m) & k.has_value();
    }
    case SurfaceShape::Disc:
      return vector("centre", m.origin) & positive("radius", m.radius) & readAngles(b, f, m);
    case SurfaceShape::Meridian: {
      Eigen::Vector3d to = Eigen::Vector3d::Zero();
      const bool ok = vector("from", m.origin) & vector("to", to);
      if (!ok) return false;
      m.side1 = to - m.origin;
      if (std::abs(m.origin(1)) > 0.0 || std::abs(to(1)) > 0.0 || m.origin(0) < 0.0 ||
          to(0) < 0.0 || !(m.side1.norm() > 0.0)) {
        b.diag.error(f.node(), f.path() +
                                   ": not a meridian (expected from and to in the x-z plane, "
                                   "y = 0, radius x >= 0, and apart)");
        return false;
      }
      return true;
    }
  }
  return false;
}

std::vector<CableRow> readCableRows(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                                    const SurfaceSpec& s) {
  std::vector<CableRow> rows;
  const std::array<const char*, 2> names = directionNames(s.map.shape);
  const std::vector<YAML::Node> items = listItems(b.diag, n, path);
  for (size_t i = 0; i < items.size(); ++i) {
    Fields f(b.diag, items[i], itemPath(path, i), {"along", "at", "section"});
    const bool meridian = s.map.shape == SurfaceShape::Meridian;
    const YAML::Node* along = meridian ? f.find("along") : f.require("along");
    const YAML::Node* at = f.require("at");
    const YAML::Node* sec = f.require("section");
    const auto direction =
        along ? b.in.choice<int>(*along, f.path("along"), {{names[0], 0}, {names[1], 1}})
              : std::optional<int>(meridian ? 0 : -1);
    const SectionSpec* section = sec ? b.section(*sec, f.path("section")) : nullptr;
    if (!direction || *direction < 0 || !at) continue;
    // Boundaries across the cables' direction; a meridian's hoops sit at its element ends.
    const int across = meridian ? s.divisions[0] : s.divisions[1 - *direction];
    const std::vector<YAML::Node> boundaries = listOrOne(b.diag, *at, f.path("at"));
    for (size_t k = 0; k < boundaries.size(); ++k) {
      const auto boundary =
          b.in.integer(boundaries[k], listOrOnePath(*at, f.path("at"), k), 0, across);
      if (boundary && section) rows.push_back({*direction, *boundary, section});
    }
  }
  return rows;
}

void readSurface(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  const std::string shape_word = peekText(item, "shape");
  const std::vector<std::pair<std::string, SurfaceShape>> shapes = {
      {"rectangle", SurfaceShape::Rectangle},
      {"cylinder", SurfaceShape::Cylinder},
      {"disc", SurfaceShape::Disc},
      {"meridian", SurfaceShape::Meridian}};
  SurfaceSpec s;
  const auto known = std::find_if(shapes.begin(), shapes.end(),
                                  [&](const auto& p) { return p.first == shape_word; });
  if (known != shapes.end()) s.map.shape = known->second;
  Fields f(b.diag, item, path, keysOf(s.map.shape));
  const YAML::Node* name_node = f.require("name");
  if (name_node) s.name = b.in.text(*name_node, f.path("name")).value_or("");
  const bool named = !s.name.empty() && checkName(b, *name_node, f.path("name"), s.name);
  const YAML::Node* shape_node = f.require("shape");
  bool ok = shape_node && b.in.choice(*shape_node, f.path("shape"), shapes).has_value();
  ok = readGeometry(b, f, s) && ok;
  if (const YAML::Node* sec = f.require("section"))
    s.section = b.section(*sec, f.path("section"), SectionUse::Membrane);
  ok = ok && s.section;
  if (s.map.shape == SurfaceShape::Meridian) {
    const YAML::Node* ne = f.require("elements");
    const YAML::Node* no = f.require("order");
    const auto elements = ne ? b.in.integer(*ne, f.path("elements"), 1, 1000000) : std::nullopt;
    const auto order = no ? b.in.integer(*no, f.path("order"), 2, 4) : std::nullopt;
    ok = ok && elements && order;
    const int nodes = order.value_or(2);
    s.divisions = {elements.value_or(1), 1};
    s.kind = {false, nodes, nodes - 1};
  } else {
    const YAML::Node* element = f.require("element");
    const auto kind =
        element ? b.in.choice(*element, f.path("element"), elementKinds()) : std::nullopt;
    const YAML::Node* div = f.require("divisions");
    const auto divisions = div ? readDivisions(b, *div, f.path("divisions")) : std::nullopt;
    ok = ok && kind && divisions;
    if (kind) s.kind = *kind;
    if (divisions) s.divisions = *divisions;
    if (const YAML::Node* d = f.find("diagonals")) {
      const auto pattern = b.in.choice<std::string>(
          *d, f.path("diagonals"),
          {{"forward", "forward"}, {"backward", "backward"}, {"centre", "centre"}});
      if (pattern && !s.kind.triangle)
        b.diag.error(*d, f.path("diagonals") + ": only for triangles (got element " +
                             peekText(item, "element") + ", expected T3, T6 or T10)");
      ok = ok && pattern && s.kind.triangle;
      s.diagonals = pattern.value_or(s.diagonals);
    }
    if (kind && s.map.shape == SurfaceShape::Disc && !kind->triangle) {
      b.diag.error(*element, f.path("element") + ": a disc needs triangles (got " +
                                 element->Scalar() +
                                 ", expected T3, T6 or T10: quads would collapse at the centre)");
      ok = false;
    }
  }
  std::vector<CableRow> rows;
  if (const YAML::Node* c = f.find("cables")) rows = readCableRows(b, *c, f.path("cables"), s);
  if (!ok || !named) {
    if (!s.name.empty()) b.broken_node_names.insert(s.name);
    return;
  }
  generateSurface(b, s, rows, lineOf(item));
}

}  // namespace

void readSurfaces(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "surfaces");
  for (size_t i = 0; i < items.size(); ++i) readSurface(b, items[i], itemPath("surfaces", i));
}

}  // namespace flexmoor::app
