#include "apps/case/scenarios/spread_mooring.hpp"

#include "apps/case/build/line_summary.hpp"
#include "apps/problem/unit_system.hpp"
#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::app {
namespace {

const char* const kAxes[] = {"x", "y", "z"};

// The nodes of one segment from `start` (an existing node, or -1 for a new one at `from`) to
// `to`, equally spaced, as a case file's line generates them.
std::vector<int> segmentNodes(MeshSpec& mesh, int start, const Eigen::Vector3d& from,
                              const Eigen::Vector3d& to, const MooringSegment& segment) {
  const int count = segment.elements * (segment.order - 1) + 1;
  std::vector<int> nodes(count);
  for (int k = 0; k < count; ++k) {
    const double s = static_cast<double>(k) / (count - 1);
    nodes[k] = k == 0 && start >= 0 ? start : mesh.addNode((1.0 - s) * from + s * to);
  }
  return nodes;
}

// One mooring line's nodes: its segments' from the anchor, laid straight towards the fairlead.
struct LineNodes {
  std::vector<std::vector<int>> segments;
  Eigen::Vector3d end;  // the reference's end, where the fairlead's support takes it from
};

LineNodes addLineNodes(MeshSpec& mesh, const MooringLine& m) {
  const Eigen::Vector3d along =
      Eigen::Vector3d(m.fairlead.x() - m.anchor.x(), m.fairlead.y() - m.anchor.y(), 0.0)
          .normalized();
  LineNodes line;
  Eigen::Vector3d from = m.anchor;
  double s = 0.0;
  for (const MooringSegment& segment : m.segments) {
    s += segment.length;
    const Eigen::Vector3d to = m.anchor + s * along;
    const int start = line.segments.empty() ? -1 : line.segments.back().back();
    line.segments.push_back(segmentNodes(mesh, start, from, to, segment));
    from = to;
  }
  line.end = from;
  return line;
}

// The fairlead's supports: held where the spec puts it, or each dof carried by the platform.
void addFairleadSupports(CaseSpec& c, const std::string& name, int node,
                         const Eigen::Vector3d& reference_end, const Eigen::Vector3d& fairlead,
                         const std::optional<PlatformSpec>& platform) {
  for (int k = 0; k < 3; ++k) {
    if (!platform) {
      c.conditions.supports.push_back({node, k, fairlead(k) - reference_end(k), nullptr, 0});
      continue;
    }
    const auto history = std::make_shared<model::RigidPointMotion>(
        platform->motion, fairlead - platform->reference, k, fairlead(k) - reference_end(k));
    c.histories[name + ".fairlead_" + kAxes[k]] = history;
    c.conditions.supports.push_back({node, k, 1.0, history, 0});
  }
}

SummarySpec lineSummary(const CaseSpec& c, const std::string& name, SummarySpec::Quantity q,
                        int step) {
  SummarySpec s;
  s.name = name;
  s.quantity = q;
  s.step = step;
  const UnitNames units = unitNames(c.units);
  s.unit = q == SummarySpec::Quantity::LengthOnSeabed ? units.length : units.force;
  return s;
}

// The steps the default summary reads (0-based; -1 for none): the last step before the first
// dynamic one, and the last dynamic step.
struct SummarySteps {
  int statics = -1, dynamic = -1;
};

SummarySteps summarySteps(const std::vector<StepSpec>& steps) {
  SummarySteps s;
  bool before_dynamic = true;
  for (size_t i = 0; i < steps.size(); ++i) {
    if (steps[i].kind == StepSpec::Kind::Dynamic) {
      before_dynamic = false;
      s.dynamic = static_cast<int>(i);
    } else if (before_dynamic) {
      s.statics = static_cast<int>(i);
    }
  }
  return s;
}

}  // namespace

StepSpec spreadMooringStatics() {
  StepSpec statics;
  statics.kind = StepSpec::Kind::Static;
  statics.name = "equilibrium";
  statics.statics.increments = 1;
  return statics;
}

CaseSpec spreadMooring(const SpreadMooringSpec& spec, std::vector<StepSpec> steps) {
  CaseSpec c;
  c.units = spec.units;
  c.ocean = OceanSpec::inWater(spec.water);
  c.ocean.has_contact = true;
  c.ocean.contact = spec.seabed;
  c.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -spec.water.gravity);
  if (spec.platform) c.rigid_motions["platform"] = spec.platform->motion;

  // The nodes, line by line; then the attachments' point masses, then the lines' cables.
  std::vector<LineNodes> nodes;
  for (const MooringLine& m : spec.lines) nodes.push_back(addLineNodes(c.mesh, m));
  const auto connection = [&](size_t i, int at) { return nodes[i].segments[at - 1].back(); };
  for (size_t i = 0; i < spec.lines.size(); ++i)
    for (const MooringAttachment& a : spec.lines[i].attachments)
      if (a.mass > 0.0) c.mesh.addElement(ElementSpec::pointMass(connection(i, a.at), a.mass));
  std::map<std::string, MorisonSpec> morison;  // of each line type
  for (size_t i = 0; i < spec.lines.size(); ++i) {
    const MooringLine& m = spec.lines[i];
    const std::string name = "line_" + std::to_string(i + 1);
    CaseLine whole{name, {}, {}, "", CaseLine::Anchor::Start};
    std::vector<CaseLine> segments;
    CatenaryStartSpec start;
    start.where = name + ".initial_shape";
    for (size_t j = 0; j < m.segments.size(); ++j) {
      const MooringSegment& segment = m.segments[j];
      const LineType& type = spec.line_types.at(segment.type);
      const std::vector<int>& line_nodes = nodes[i].segments[j];
      CaseLine part{
          name + "_segment_" + std::to_string(j + 1), line_nodes, {}, name, CaseLine::Anchor::None};
      for (int e = 0; e < segment.elements; ++e) {
        const auto first = line_nodes.begin() + e * (segment.order - 1);
        part.elements.push_back(c.mesh.addElement(
            ElementSpec::cable(std::vector<int>(first, first + segment.order), type.section, 0)));
      }
      MorisonSpec& loads =
          morison.try_emplace(segment.type, MorisonSpec{{}, type.hydro}).first->second;
      loads.elements.insert(loads.elements.end(), part.elements.begin(), part.elements.end());
      whole.nodes.insert(whole.nodes.end(), line_nodes.begin() + (j == 0 ? 0 : 1),
                         line_nodes.end());
      whole.elements.insert(whole.elements.end(), part.elements.begin(), part.elements.end());
      start.parts.push_back({line_nodes, type.section, type.diameter});
      segments.push_back(std::move(part));
    }
    c.lines.push_back(whole);
    if (m.has_segments)
      for (CaseLine& part : segments) c.lines.push_back(std::move(part));
    c.catenary_starts.push_back(std::move(start));
    for (int k = 0; k < 3; ++k)
      c.conditions.supports.push_back({whole.nodes.front(), k, 0.0, nullptr, 0});
    addFairleadSupports(c, name, whole.nodes.back(), nodes[i].end, m.fairlead, spec.platform);
    for (const MooringAttachment& a : m.attachments)
      if (a.volume > 0.0)
        c.ocean.bodies.push_back({connection(i, a.at),
                                  hydro::PointBody{a.volume, a.drag_area, a.added_mass, 0.0}, 0,
                                  name + ".attachment"});
  }
  for (auto& [type, loads] : morison) c.ocean.morison.push_back(std::move(loads));
  c.steps = steps.empty() ? std::vector<StepSpec>{spreadMooringStatics()} : std::move(steps);
  c.summary = spreadMooringSummary(c);
  c.figure = FigureSpec{FigureSpec::Kind::Mooring, {}, "", {}};
  return c;
}

std::vector<SummarySpec> spreadMooringSummary(const CaseSpec& c) {
  using Quantity = SummarySpec::Quantity;
  using Reduction = SummarySpec::Reduction;
  const SummarySteps steps = summarySteps(c.steps);
  std::vector<SummarySpec> summary;
  int k = 0;
  for (const CaseLine& line : c.lines) {
    if (!line.segment_of.empty()) continue;  // a segment of a line
    const std::string n = std::to_string(++k);
    // The ends: the fairlead the line's last node and element, the anchor its first.
    const auto tension = [&](const std::string& name, bool fairlead, int step, Reduction r) {
      SummarySpec s = lineSummary(c, name, Quantity::EndTension, step);
      s.element = fairlead ? line.elements.back() : line.elements.front();
      s.end = fairlead ? 1 : 0;
      s.reduction = r;
      summary.push_back(s);
    };
    const auto reaction = [&](const std::string& name, bool fairlead, Quantity q, int step,
                              double scale, Reduction r) {
      SummarySpec s = lineSummary(c, name, q, step);
      s.node = fairlead ? line.nodes.back() : line.nodes.front();
      s.component = q == Quantity::Reaction ? 2 : 0;
      s.scale = scale;
      s.reduction = r;
      summary.push_back(s);
    };
    if (steps.statics >= 0) {
      const int st = steps.statics;
      tension("fairlead_tension_static_" + n, true, st, Reduction::StepEnd);
      reaction("fairlead_horizontal_static_" + n, true, Quantity::ReactionHorizontal, st, 1.0,
               Reduction::StepEnd);
      reaction("fairlead_vertical_static_" + n, true, Quantity::Reaction, st, 1.0,
               Reduction::StepEnd);
      tension("anchor_tension_static_" + n, false, st, Reduction::StepEnd);
      reaction("anchor_horizontal_static_" + n, false, Quantity::ReactionHorizontal, st, 1.0,
               Reduction::StepEnd);
      // The line's pull on the anchor, upward +.
      reaction("anchor_vertical_static_" + n, false, Quantity::Reaction, st, -1.0,
               Reduction::StepEnd);
      // (not of a line with a part that floats: the bed carries no length of it)
      SummarySpec laid =
          lineSummary(c, "length_on_seabed_static_" + n, Quantity::LengthOnSeabed, st);
      if (seabedLine(line, c.mesh, c.conditions, c.ocean, laid) < 0) summary.push_back(laid);
    }
    if (steps.dynamic >= 0) {
      const int dy = steps.dynamic;
      tension("fairlead_tension_max_" + n, true, dy, Reduction::Max);
      tension("fairlead_tension_min_" + n, true, dy, Reduction::Min);
      tension("anchor_tension_max_" + n, false, dy, Reduction::Max);
      reaction("anchor_vertical_max_" + n, false, Quantity::Reaction, dy, -1.0, Reduction::Max);
    }
  }
  return summary;
}

}  // namespace flexmoor::app
