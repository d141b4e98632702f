#include "apps/case/case_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "apps/case/build/build_conditions.hpp"
#include "apps/case/build/build_initial_shape.hpp"
#include "apps/case/build/build_mesh.hpp"
#include "apps/case/build/build_ocean.hpp"
#include "apps/case/case_builder.hpp"
#include "apps/case/input/nearest_names.hpp"
#include "apps/case/input/yaml_load.hpp"
#include "apps/case/scenarios/scenario_model.hpp"
#include "apps/common/data_dir.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTopKeys = {
    "name",     "title",     "units",    "materials", "sections", "nodes", "lines", "surfaces",
    "elements", "node_sets", "supports", "histories", "loads",    "water", "waves", "current",
    "seabed",   "bodies",    "steps",    "summary",   "figure",   "output"};

// The case's name: used for output files, so a plain word.
std::string readName(Diagnostics& diag, Input& in, const Fields& top, const std::string& path) {
  const std::string stem = fs::path(path).stem().string();
  const YAML::Node* n = top.find("name");
  if (!n) return stem;
  const std::string name = in.text(*n, "name").value_or(stem);
  const bool plain = std::all_of(name.begin(), name.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.';
  });
  if (plain && !name.empty() && name.front() != '.') return name;
  diag.error(*n, "name: not usable as a file name (got '" + name +
                     "', expected letters, digits, '-', '_' and '.')");
  return stem;
}

// Every .yaml under the cases directory (apps/common/data_dir.hpp).
std::vector<fs::path> caseFiles() {
  std::vector<fs::path> files;
  const fs::path dir = casesDir();
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".yaml")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return a.stem().string() < b.stem().string();
  });
  return files;
}

// The bodies' masses as point_mass elements, numbered after those of elements:, lines: and
// surfaces:.
void addBodyMasses(CaseBuilder& b) {
  for (const PendingPointMass& m : b.body_masses) {
    b.mesh.addElement(ElementSpec::pointMass(m.node, m.mass));
    b.element_types.push_back("point_mass");
    b.origins.elements.push_back({m.line, m.where, ""});
  }
}

// Morison loads on the cable-like elements of each section with hydro: (the checks refuse them on
// a hoop ring).
void addMorison(CaseBuilder& b) {
  for (const auto& [name, section] : b.sections) {
    if (!section || !section->hydro) continue;
    MorisonSpec morison{{}, *section->hydro};
    for (int e = 0; e < b.mesh.elementCount(); ++e)
      if ((b.element_types[e] == "cable" || b.element_types[e] == "hoop_cable") &&
          b.origins.elements[e].section == name)
        morison.elements.push_back(e);
    if (!morison.elements.empty()) b.ocean.morison.push_back(std::move(morison));
  }
}

// The entries of `series`, read with their own file's diagnostics.
void readForeignSeries(CaseBuilder& b, ForeignSeries& series) {
  b.diag.redirect(series.diag, series.prefix);
  for (const ForeignSeries::Entry& e : series.entries)
    series.specs.push_back(readSeriesQuantity(b, e.map, e.path, e.name, e.other_keys));
  b.diag.redirect(nullptr);
}

}  // namespace

Case readCase(const std::string& path) { return readCase(loadCase(path)); }

CaseDocument loadCase(const std::string& path) {
  Diagnostics diag(path);
  CaseDocument document{path, {}, {}};
  document.root = loadCaseDocument(diag, document.node_table);
  return document;
}

CaseDocument loadCaseFromText(const std::string& text, const std::string& name) {
  Diagnostics diag(name);
  CaseDocument document{name, {}, {}};
  document.root = loadCaseText(diag, text, document.node_table);
  return document;
}

Case readCase(const CaseDocument& document, ForeignSeries* series) {
  const std::string& path = document.path;
  Diagnostics diag(path);
  const YAML::Node& root = document.root;
  const Scenario* stated = scenarioOf(diag, root);
  diag.throwIfAny();  // an unknown scenario
  Case c;
  c.file = path;
  c.model = std::make_unique<model::Model>();
  Fields top(diag, root, "", stated ? stated->keys() : kTopKeys);
  if (const YAML::Node* u = top.require("units"))
    c.units = Input(diag, UnitSystem::SI)
                  .choice(*u, "units",
                          std::vector<std::pair<std::string, UnitSystem>>{{"US", UnitSystem::US},
                                                                          {"SI", UnitSystem::SI}})
                  .value_or(UnitSystem::SI);
  CaseBuilder b(diag, c.units, c);
  b.node_table = document.node_table;
  c.name = readName(diag, b.in, top, path);
  if (const YAML::Node* t = top.find("title")) c.title = b.in.text(*t, "title").value_or("");
  std::optional<ScenarioModel> scenario;
  if (stated) {
    scenario = stated->read(b, top);
    diag.throwIfAny();  // a scenario that cannot stand for a model: its own messages say why
  }

  // In dependency order; an absent section is an empty one.
  const auto section = [&top](const char* key) {
    const YAML::Node* n = top.find(key);
    return n ? *n : YAML::Node();
  };
  readMaterials(b, section("materials"));
  readSections(b, section("sections"));
  readNodes(b, section("nodes"));
  readLines(b, section("lines"));
  readSurfaces(b, section("surfaces"));
  readElements(b, section("elements"));
  if (scenario) addScenarioModel(b, *scenario);
  readNodeSets(b, section("node_sets"));
  readHistories(b, section("histories"));
  readSupports(b, section("supports"));
  readLoads(b, section("loads"));
  readOcean(b, top);
  if (scenario) addScenarioOcean(b, *scenario, top.find("seabed") != nullptr);
  addBodyMasses(b);
  if (b.ocean.has_water) addMorison(b);
  resolveEnclosedFluids(b);
  if (scenario)
    readScenarioSteps(b, top, *scenario);
  else if (const YAML::Node* steps = top.require("steps"))
    readSteps(b, *steps);
  readSummary(b, section("summary"));
  readOutput(b, section("output"));
  readFigure(b, section("figure"));
  if (scenario) addScenarioDefaults(b, top, *scenario);
  if (series) readForeignSeries(b, *series);

  buildMesh(b.mesh, *c.model);
  buildConditions(b.conditions, *c.model);
  putEnclosedFluids(b);
  c.model->numberEquations();
  if (diag.empty()) {
    if (c.model->elementCount() == 0)
      diag.error(0, "the case has no elements (expected lines: or elements:)");
    else if (c.model->equationCount() == 0)
      diag.error(0, "every dof is fixed (expected something to solve for)");
    checkModel({c, b.mesh, b.ocean, b.origins, b.surfaces, b.histories, diag});
  }
  if (diag.empty())
    for (const SpecError& e : startOnCatenaries(catenaryStarts(b), b.ocean, c))
      diag.error(e.line, e.message);
  diag.throwIfAny();
  buildOcean(b.ocean, c);
  c.warnings = diag.warnings();
  c.notes = diag.notes();
  return c;
}

std::string resolveCasePath(const std::string& name_or_path) {
  if (fs::is_regular_file(name_or_path)) return name_or_path;
  if (fs::is_regular_file(name_or_path + ".yaml")) return name_or_path + ".yaml";
  const bool yaml = fs::path(name_or_path).extension() == ".yaml";
  const std::string name =
      yaml ? fs::path(name_or_path).stem().string() : fs::path(name_or_path).filename().string();
  if (name_or_path.find('/') != std::string::npos) {  // a path: the files next to it
    const fs::path directory = fs::path(name_or_path).parent_path();
    std::vector<std::string> stems, files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(directory, ec))
      if (entry.is_regular_file() && entry.path().extension() == ".yaml")
        stems.push_back(entry.path().stem().string());
    std::sort(stems.begin(), stems.end());
    for (const std::string& stem : nearestNames(name, stems))
      files.push_back((directory / stem).string() + (yaml ? ".yaml" : ""));
    throw std::runtime_error("no case file '" + name_or_path + "'" + didYouMean(files));
  }
  std::vector<fs::path> matches;
  std::vector<std::string> names;
  for (const fs::path& file : caseFiles()) {
    if (file.stem() == name) matches.push_back(file);
    names.push_back(file.stem().string());
  }
  if (matches.size() == 1) return matches.front().string();
  if (matches.empty()) {
    std::string available;
    for (const std::string& n : names) available += (available.empty() ? "" : ", ") + n;
    const std::string near = didYouMean(nearestNames(name, names));
    throw std::runtime_error("no case '" + name_or_path + "'" +
                             (near.empty()
                                  ? " (no such file, nor a case of that name; available: " +
                                        (available.empty() ? "none" : available) + ")"
                                  : near));
  }
  std::string where;
  for (const fs::path& m : matches) where += (where.empty() ? "" : ", ") + m.string();
  throw std::runtime_error("case name '" + name_or_path + "' is ambiguous: " + where);
}

std::vector<std::pair<std::string, std::string>> listCases() {
  std::vector<std::pair<std::string, std::string>> cases;
  for (const fs::path& file : caseFiles()) {
    std::string title;
    try {
      const YAML::Node root = YAML::LoadFile(file.string());
      if (root.IsMap() && root["title"] && root["title"].IsScalar()) title = root["title"].Scalar();
    } catch (const YAML::Exception& e) {
      title = "(not valid YAML: " + e.msg + ")";
    }
    cases.emplace_back(file.stem().string(), title);
  }
  return cases;
}

}  // namespace flexmoor::app
