// nodes:, lines: and elements: of a case file, into the case's MeshSpec (and so, once built, its
// model). Nodes are the explicit nodes in ascending id, then the nodes each line generates, then
// those of each surface; elements are the explicit elements in file order, then the cable
// elements of each line, then each surface's elements.
//
// A line with `segment_of: NAME` is a segment of the multi-segment line NAME (chain - wire -
// chain, each segment its own section and mesh): NAME's segments in file order, each after the
// first starting at the end node of the one before (start_node: PREVIOUS.end). NAME is then a line
// too: its nodes from its first segment's start to its last's end (NAME.start, NAME.end), its
// elements theirs; with initial_shape, the segments start on the one catenary of the whole line.
#include <algorithm>
#include <numeric>

#include "apps/case/case_builder.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

// One end of a line: `from: [x, y, z]` or `start_node: REF` (and `to` / `end_node`).
struct LineEnd {
  Eigen::Vector3d position;
  int node = -1;  // the attached model node, or -1 for a generated one
};

std::optional<LineEnd> readLineEnd(CaseBuilder& b, Fields& f, const char* point, const char* node) {
  const YAML::Node* p = f.find(point);
  const YAML::Node* n = f.find(node);
  if (p && n) {
    b.diag.error(*n, f.path() + ": give either " + point + " or " + node + ", not both");
    return std::nullopt;
  }
  if (!p && !n) {
    if (f.isMap())
      b.diag.error(f.node(), f.path() + ": missing key '" + point + "' (or '" + node + "')");
    return std::nullopt;
  }
  if (p) {
    const auto x = b.in.vector3(*p, f.path(point), kind::kLength);
    return x ? std::optional<LineEnd>({*x, -1}) : std::nullopt;
  }
  const auto attached = nodeRef(b, *n, f.path(node));
  if (!attached) return std::nullopt;
  return LineEnd{b.mesh.position(*attached), *attached};
}

// Joins a line to the multi-segment line `segment_of` names: a new name for its first segment,
// else its nodes must start where the last segment ends. False when wrong (reported).
bool joinSegments(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                  const std::string& name, const std::vector<int>& nodes) {
  const auto count = b.line_segments.find(name);
  if (count == b.line_segments.end() && b.broken_node_names.count(name)) return false;
  if (count == b.line_segments.end()) {
    if (!checkName(b, n, path, name)) return false;
    b.line_segments[name] = 1;
    b.c.lines[name] = nodes;
    b.line_order.push_back(name);
    return true;
  }
  std::vector<int>& line = b.c.lines.at(name);
  if (nodes.front() != line.back()) {
    b.diag.error(n, path + ": segment " + std::to_string(count->second + 1) + " of " + name +
                        " does not start where segment " + std::to_string(count->second) +
                        " ends (got node " + std::to_string(b.c.node_ids[nodes.front()]) +
                        ", expected node " + std::to_string(b.c.node_ids[line.back()]) +
                        ", where it ends: start_node: PREVIOUS.end)");
    return false;
  }
  ++count->second;
  line.insert(line.end(), nodes.begin() + 1, nodes.end());
  return true;
}

// `anchor: start | end` of a line, or of a segment for the whole line it is a segment of (its
// segments must agree): the line is a mooring line with its anchor at that end and its fairlead
// at the other, which `anchor` and `fairlead` then name (LINE.anchor, line: NAME, end: fairlead).
void readAnchor(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                const std::string& line) {
  using Anchor = CaseLine::Anchor;
  const auto anchor =
      b.in.choice<Anchor>(n, path, {{"start", Anchor::Start}, {"end", Anchor::End}});
  if (!anchor) return;
  if (line.empty()) {
    b.diag.error(n, path + ": a line without a name (got anchor: on a line nothing can refer " +
                        "to, expected name: with it)");
    return;
  }
  const auto [it, added] = b.line_anchors.emplace(line, *anchor);
  if (!added && it->second != *anchor)
    b.diag.error(n, path + ": not the anchor another segment of " + line + " gives (got " +
                        n.Scalar() + ", expected " +
                        (it->second == Anchor::Start ? "start" : "end") + ")");
}

void readLine(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path,
           {"name", "from", "to", "start_node", "end_node", "elements", "order", "section",
            "initial_shape", "segment_of", "anchor"});
  std::string name;
  if (const YAML::Node* n = f.find("name")) {
    name = b.in.text(*n, f.path("name")).value_or("");
    if (!name.empty() && !checkName(b, *n, f.path("name"), name)) name.clear();
  }
  const auto start = readLineEnd(b, f, "from", "start_node");
  const auto end = readLineEnd(b, f, "to", "end_node");
  const YAML::Node* ne = f.require("elements");
  const YAML::Node* no = f.require("order");
  const int elements = ne ? b.in.integer(*ne, f.path("elements"), 1, 1000000).value_or(0) : 0;
  const int order = no ? b.in.integer(*no, f.path("order"), 2, 4).value_or(0) : 0;
  const YAML::Node* ns = f.require("section");
  const SectionSpec* section = ns ? b.section(*ns, f.path("section")) : nullptr;
  if (!start || !end || elements == 0 || order == 0) {
    if (!name.empty()) b.broken_node_names.insert(name);
    return;
  }
  if (!((end->position - start->position).norm() > 0.0)) {
    b.diag.error(item, path +
                           ": zero length (got the same point at both ends, expected a line "
                           "of length > 0)");
    if (!name.empty()) b.broken_node_names.insert(name);
    return;
  }
  // Nodes equally spaced from start to end; generated ones take the next ids in this order.
  const int count = elements * (order - 1) + 1;
  std::vector<int> nodes(count);
  for (int k = 0; k < count; ++k) {
    const double s = static_cast<double>(k) / (count - 1);
    if (k == 0 && start->node >= 0)
      nodes[k] = start->node;
    else if (k == count - 1 && end->node >= 0)
      nodes[k] = end->node;
    else
      nodes[k] = b.addGeneratedNode((1.0 - s) * start->position + s * end->position, lineOf(item));
  }
  std::string segment_of;
  if (const YAML::Node* n = f.find("segment_of")) {
    segment_of = b.in.text(*n, f.path("segment_of")).value_or("");
    if (!segment_of.empty() && segment_of == name) {
      b.diag.error(*n, f.path("segment_of") + ": the segment's own name (got '" + name +
                           "', expected the name of the whole line, another than its segments')");
      segment_of.clear();
    } else if (!segment_of.empty() &&
               !joinSegments(b, *n, f.path("segment_of"), segment_of, nodes)) {
      b.broken_node_names.insert(segment_of);
      segment_of.clear();
    }
  }
  if (section)
    for (int e = 0; e < elements; ++e) {
      const auto first = nodes.begin() + e * (order - 1);
      b.line_cables.push_back({std::vector<int>(first, first + order), ns->Scalar(), lineOf(item),
                               path, name, segment_of});
    }
  if (const YAML::Node* shape = f.find("initial_shape"))
    readInitialShape(b, *shape, f.path("initial_shape"), nodes, section, segment_of);
  if (const YAML::Node* anchor = f.find("anchor"))
    readAnchor(b, *anchor, f.path("anchor"), segment_of.empty() ? name : segment_of);
  if (!name.empty()) {
    b.c.lines[name] = std::move(nodes);
    b.line_order.push_back(name);
  }
}

// The named lines in the order they were defined, with their elements (CaseLine).
void collectNamedLines(CaseBuilder& b) {
  std::map<std::string, std::string> segment_of;
  for (const PendingCable& p : b.line_cables)
    if (!p.name.empty() && !p.segment_of.empty()) segment_of[p.name] = p.segment_of;
  for (const std::string& name : b.line_order) {
    CaseLine line;
    line.name = name;
    line.nodes = b.c.lines.at(name);
    if (const auto e = b.line_elements.find(name); e != b.line_elements.end())
      line.elements = e->second;
    if (const auto s = segment_of.find(name); s != segment_of.end()) line.segment_of = s->second;
    if (const auto a = b.line_anchors.find(name); a != b.line_anchors.end())
      line.anchor = a->second;
    b.c.named_lines.push_back(std::move(line));
  }
}

// The nodes of an explicit element: a list of `count_min`..`count_max` distinct node references.
std::optional<std::vector<int>> elementNodes(CaseBuilder& b, Fields& f, int count_min,
                                             int count_max) {
  const YAML::Node* n = f.require("nodes");
  if (!n) return std::nullopt;
  const std::string expected = count_min == count_max
                                   ? std::to_string(count_min)
                                   : std::to_string(count_min) + " to " + std::to_string(count_max);
  if (!n->IsSequence() || static_cast<int>(n->size()) < count_min ||
      static_cast<int>(n->size()) > count_max) {
    const std::string got =
        n->IsSequence() ? std::to_string(n->size()) + " nodes" : describeNode(*n);
    b.diag.error(*n, f.path("nodes") + ": wrong number of nodes (got " + got +
                         ", expected a list of " + expected + ")");
    return std::nullopt;
  }
  std::vector<int> nodes;
  bool ok = true;
  for (size_t i = 0; i < n->size(); ++i) {
    const auto node = nodeRef(b, (*n)[i], itemPath(f.path("nodes"), i));
    ok = ok && node.has_value();
    if (node) nodes.push_back(*node);
  }
  if (!ok) return std::nullopt;
  std::vector<int> sorted = nodes;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    b.diag.error(*n, f.path("nodes") + ": a node appears twice (expected distinct nodes)");
    return std::nullopt;
  }
  const model::NodalField& X = b.mesh.reference;
  if (!((X.col(nodes.back()) - X.col(nodes.front())).norm() > 0.0)) {
    b.diag.error(*n,
                 f.path("nodes") + ": the end nodes coincide (expected an element of length > 0)");
    return std::nullopt;
  }
  return nodes;
}

std::optional<ElementSpec> readCable(CaseBuilder& b, Fields& f) {
  const auto nodes = elementNodes(b, f, 2, 4);
  const YAML::Node* s = f.require("section");
  const SectionSpec* section = s ? b.section(*s, f.path("section")) : nullptr;
  if (!nodes || !section) return std::nullopt;
  return ElementSpec::cable(*nodes, section->section, section->quadrature);
}

// A membrane of 3, 6 or 10 nodes (triangle) or 4, 8 or 12 (quadrilateral), in the node order of
// shape/quad_shape.hpp and shape/triangle_shape.hpp (Gmsh and VTK order).
std::optional<ElementSpec> readMembrane(CaseBuilder& b, Fields& f) {
  const auto nodes = elementNodes(b, f, 3, 12);
  const YAML::Node* s = f.require("section");
  const SectionSpec* section = s ? b.section(*s, f.path("section"), SectionUse::Membrane) : nullptr;
  if (!nodes) return std::nullopt;
  const int count = static_cast<int>(nodes->size());
  const bool triangle = count == 3 || count == 6 || count == 10;
  if (!triangle && count != 4 && count != 8 && count != 12) {
    b.diag.error(*f.find("nodes"), f.path("nodes") + ": no membrane has " + std::to_string(count) +
                                       " nodes (expected 3, 6, 10 for a triangle or 4, 8, 12 for "
                                       "a quadrilateral)");
    return std::nullopt;
  }
  if (!section) return std::nullopt;
  using Kind = ElementSpec::Kind;
  return ElementSpec::membrane(triangle ? Kind::MembraneTriangle : Kind::MembraneQuad, *nodes,
                               section->membrane, section->quadrature);
}

// A meridian element of 2 to 4 nodes in the x-z plane; its nodes' y dofs are fixed.
std::optional<ElementSpec> readAxisymmetricMembrane(CaseBuilder& b, Fields& f) {
  const auto nodes = elementNodes(b, f, 2, 4);
  const YAML::Node* s = f.require("section");
  const SectionSpec* section = s ? b.section(*s, f.path("section"), SectionUse::Membrane) : nullptr;
  if (!nodes || !section) return std::nullopt;
  for (int node : *nodes) b.conditions.supports.push_back({node, 1, 0.0, nullptr, 0});
  return ElementSpec::membrane(ElementSpec::Kind::AxisymmetricMembrane, *nodes, section->membrane,
                               section->quadrature);
}

// A hoop ring of a cable section at one node of an axisymmetric model (radius = its x).
std::optional<ElementSpec> readHoopCable(CaseBuilder& b, Fields& f) {
  const YAML::Node* n = f.require("node");
  const YAML::Node* s = f.require("section");
  const int node = n ? nodeRef(b, *n, f.path("node")).value_or(-1) : -1;
  const SectionSpec* section = s ? b.section(*s, f.path("section")) : nullptr;
  if (node < 0 || !section) return std::nullopt;
  const double radius = b.mesh.position(node).x();
  if (!(radius > 0.0)) {
    b.diag.error(*n, f.path("node") + ": a hoop needs a radius (got a node at x = " +
                         formatNumber(radius) + ", expected x > 0)");
    return std::nullopt;
  }
  return ElementSpec::hoopCable(node, section->section);
}

std::optional<ElementSpec> readSpring(CaseBuilder& b, Fields& f) {
  const auto nodes = elementNodes(b, f, 2, 2);
  const YAML::Node* k = f.require("stiffness");
  const auto stiffness =
      k ? b.in.quantity(*k, f.path("stiffness"), kind::kStiffness, Limit::Positive) : std::nullopt;
  // A negative rest length tells SpringElement to take the reference distance of its nodes.
  double rest = b.in.quantityOr(f, "rest_length", kind::kLength, Limit::NonNegative, -1.0);
  if (rest == 0.0) {  // at rest its two ends meet and its direction, (y2 - y1) / l, is 0 / 0
    b.diag.error(*f.find("rest_length"), f.path("rest_length") +
                                             ": a spring of rest length 0 has no direction when "
                                             "it is at rest (got " +
                                             f.find("rest_length")->Scalar() + ", expected > 0)");
    rest = -1.0;
  }
  material::Compression compression = material::Compression::TensionOnly;
  if (const YAML::Node* c = f.find("compression"))
    compression =
        b.in.choice(*c, f.path("compression"), compressionChoices()).value_or(compression);
  // A dashpot in parallel (N*s/m), its force c dl/dt along the spring.
  const double damping = b.in.quantityOr(f, "damping", kind::kDashpot, Limit::NonNegative, 0.0);
  if (!nodes || !stiffness) return std::nullopt;
  return ElementSpec::spring((*nodes)[0], (*nodes)[1], *stiffness, rest, compression, damping);
}

std::optional<ElementSpec> readPointMass(CaseBuilder& b, Fields& f) {
  const YAML::Node* n = f.require("node");
  const YAML::Node* m = f.require("mass");
  const auto node = n ? nodeRef(b, *n, f.path("node")) : std::nullopt;
  const auto mass =
      m ? b.in.quantity(*m, f.path("mass"), kind::kMass, Limit::Positive) : std::nullopt;
  if (!node || !mass) return std::nullopt;
  return ElementSpec::pointMass(*node, *mass);
}

// One explicit element; its type ("" when it has errors) goes to element_types.
void readElement(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  const std::string type = peekText(item, "type");
  const std::vector<std::string> cable = {"type", "nodes", "section"};
  const std::vector<std::string> spring = {"type",        "nodes",       "stiffness",
                                           "rest_length", "compression", "damping"};
  const std::vector<std::string> point_mass = {"type", "node", "mass"};
  const std::vector<std::string> hoop = {"type", "node", "section"};
  const std::vector<std::string> any = {"type",      "nodes",       "section",
                                        "stiffness", "rest_length", "compression",
                                        "node",      "mass",        "damping"};
  const bool on_nodes = type == "cable" || type == "membrane" || type == "axisymmetric_membrane";
  Fields f(b.diag, item, path,
           on_nodes               ? cable
           : type == "spring"     ? spring
           : type == "point_mass" ? point_mass
           : type == "hoop_cable" ? hoop
                                  : any);  // the type itself is reported below
  std::optional<ElementSpec> element;
  if (type == "cable")
    element = readCable(b, f);
  else if (type == "membrane")
    element = readMembrane(b, f);
  else if (type == "axisymmetric_membrane")
    element = readAxisymmetricMembrane(b, f);
  else if (type == "hoop_cable")
    element = readHoopCable(b, f);
  else if (type == "spring")
    element = readSpring(b, f);
  else if (type == "point_mass")
    element = readPointMass(b, f);
  else if (const YAML::Node* t = f.require("type"))
    b.in.choice<int>(*t, f.path("type"),
                     {{"cable", 0},
                      {"membrane", 1},
                      {"axisymmetric_membrane", 2},
                      {"hoop_cable", 3},
                      {"spring", 4},
                      {"point_mass", 5}});
  b.element_types.push_back(element ? type : "");
  b.origins.elements.push_back({lineOf(item), path, element ? peekText(item, "section") : ""});
  if (element) b.mesh.addElement(std::move(*element));
}

}  // namespace

std::string CaseBuilder::sectionName(const SectionSpec* spec) const {
  for (const auto& [name, s] : sections)
    if (s && &*s == spec) return name;
  return "";
}

int CaseBuilder::addGeneratedNode(const Eigen::Vector3d& position, int line) {
  const int id = largestId() + 1;
  const int node = mesh.addNode(position);
  node_of_id[id] = node;
  c.node_ids.push_back(id);
  origins.node_lines.push_back(line);
  return node;
}

void readNodes(CaseBuilder& b, const YAML::Node& n) {
  if (b.node_table) {  // already read and checked; added in ascending id like the others
    const NodeTable& t = *b.node_table;
    std::vector<int> order(t.ids.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&t](int i, int j) { return t.ids[i] < t.ids[j]; });
    model::NodalField X(3, order.size());
    for (size_t k = 0; k < order.size(); ++k) X.col(k) = t.points[order[k]];
    const int first = b.mesh.addNodes(X);
    for (size_t k = 0; k < order.size(); ++k) {
      b.node_of_id.emplace_hint(b.node_of_id.end(), t.ids[order[k]], first + k);
      b.c.node_ids.push_back(t.ids[order[k]]);
      b.origins.node_lines.push_back(t.lines[order[k]]);
    }
    return;
  }
  struct Explicit {
    Eigen::Vector3d position;
    int line;
  };
  std::map<int, Explicit> nodes;
  for (const MapEntry& e : mapEntries(b.diag, n, "nodes")) {
    const std::string path = childPath("nodes", e.key);
    const auto id = b.in.integer(e.key_node, path + " (a node id)", 1);
    const auto x = b.in.vector3(e.value, path, kind::kLength);
    if (id && nodes.count(*id)) {
      b.diag.error(e.key_node, path + ": repeated node id (first given on line " +
                                   std::to_string(nodes[*id].line) + ")");
    } else if (id && x) {
      nodes[*id] = {*x, lineOf(e.key_node)};
    } else if (id) {
      b.broken_node_ids.insert(*id);
    }
  }
  model::NodalField X(3, nodes.size());
  int k = 0;
  for (const auto& entry : nodes) X.col(k++) = entry.second.position;
  const int first = b.mesh.addNodes(X);
  k = 0;
  for (const auto& [id, node] : nodes) {
    b.node_of_id[id] = first + k++;
    b.c.node_ids.push_back(id);
    b.origins.node_lines.push_back(node.line);
  }
}

void readLines(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "lines");
  for (size_t i = 0; i < items.size(); ++i) readLine(b, items[i], itemPath("lines", i));
}

void readElements(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "elements");
  for (size_t i = 0; i < items.size(); ++i) readElement(b, items[i], itemPath("elements", i));
  for (PendingCable& p : b.line_cables) {
    const SectionSpec& s = *b.sections.at(p.section);
    const int e =
        b.mesh.addElement(ElementSpec::cable(std::move(p.nodes), s.section, s.quadrature));
    if (!p.name.empty()) b.line_elements[p.name].push_back(e);
    if (!p.segment_of.empty()) b.line_elements[p.segment_of].push_back(e);
    b.element_types.push_back("cable");
    b.origins.elements.push_back({p.line, p.where, p.section});
  }
  collectNamedLines(b);
  for (PendingSurface& surface : b.surface_elements) {
    std::vector<int>& set = b.c.element_sets[surface.name];
    for (PendingElement& e : surface.elements) {
      set.push_back(b.mesh.addElement(std::move(e.element)));
      b.element_types.push_back(e.type);
      b.origins.elements.push_back({surface.line, "surface '" + surface.name + "'", e.section});
    }
  }
}

}  // namespace flexmoor::app
