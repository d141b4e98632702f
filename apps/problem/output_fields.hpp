#pragma once
// What the records of a run's netCDF file hold besides their time, step and load factor (which
// every record has), as the case's `output: fields:` lists it. A long run written every step is
// mostly its records: a mooring line of 151 nodes writes 20 KB a record with every field, 3.6 KB
// of it reactions, so a user who wants the fairlead tension names `tension` alone. The default is
// every field. The modes of a modes step are always written.
//
//   field               netCDF variables: the time records', and the stage records' (prefixed
//                       stage_, with the dimension stage for time; netcdf_writer.hpp)
//   displacement        displacement_x/_y/_z (time, node)
//   position            position_x/_y/_z (time, node)
//   velocity            velocity_x/_y/_z (time, node)
//   reaction            reaction_x/_y/_z (time, node)
//   tension             tension_end (time, element, end), tension_point (time, point)
//   membrane_resultant  membrane_resultant_max/_min (time, element)
//   wave_elevation      wave_elevation (time), with a sea (time records only)
#include <array>
#include <bitset>
#include <optional>
#include <string>
#include <string_view>

namespace flexmoor::app {

enum class OutputField {
  Displacement,
  Position,
  Velocity,
  Reaction,
  Tension,
  MembraneResultant,
  WaveElevation
};

class OutputFields {
 public:
  static constexpr std::array<std::pair<std::string_view, OutputField>, 7> kNames = {{
      {"displacement", OutputField::Displacement},
      {"position", OutputField::Position},
      {"velocity", OutputField::Velocity},
      {"reaction", OutputField::Reaction},
      {"tension", OutputField::Tension},
      {"membrane_resultant", OutputField::MembraneResultant},
      {"wave_elevation", OutputField::WaveElevation},
  }};

  static OutputFields all() {
    OutputFields f;
    f.set_.set();
    return f;
  }
  static OutputFields none() { return {}; }

  bool has(OutputField f) const { return set_.test(index(f)); }
  void add(OutputField f) { set_.set(index(f)); }
  // Element results (tensions, resultants): a record needs them from an assembly sweep.
  bool needsElementResults() const {
    return has(OutputField::Tension) || has(OutputField::MembraneResultant);
  }
  // Element results or reactions: what a record needs beyond the state.
  bool needsResults() const { return needsElementResults() || has(OutputField::Reaction); }
  // The field a netCDF variable of a record belongs to ("position_x": position; "speed", which
  // a figure derives from the velocity: velocity); none for one that is not a field's (time, a
  // modes step's variables).
  static std::optional<OutputField> ofVariable(std::string_view variable);
  static std::string_view name(OutputField f) { return kNames[index(f)].first; }
  // "displacement, position, ..., wave_elevation", for messages.
  static std::string list();

 private:
  static size_t index(OutputField f) { return static_cast<size_t>(f); }
  std::bitset<kNames.size()> set_;
};

inline std::optional<OutputField> OutputFields::ofVariable(std::string_view variable) {
  static constexpr std::array<std::pair<std::string_view, OutputField>, 6> kPrefixes = {{
      {"displacement_", OutputField::Displacement},
      {"position_", OutputField::Position},
      {"velocity_", OutputField::Velocity},
      {"reaction_", OutputField::Reaction},
      {"tension_", OutputField::Tension},
      {"membrane_resultant_", OutputField::MembraneResultant},
  }};
  for (const auto& [prefix, field] : kPrefixes)
    if (variable.substr(0, prefix.size()) == prefix) return field;
  if (variable == "speed") return OutputField::Velocity;
  if (variable == "wave_elevation") return OutputField::WaveElevation;
  return std::nullopt;
}

inline std::string OutputFields::list() {
  std::string s;
  for (const auto& [name, field] : kNames) s += (s.empty() ? "" : ", ") + std::string(name);
  return s;
}

}  // namespace flexmoor::app
