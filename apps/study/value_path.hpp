#pragma once
// Case values by their dotted paths, as a study names them: "waves.spectrum.Hs" is the key Hs of
// the map spectrum of the map waves; a number is a list's index, 0-based
// ("waves.components.0.period" is the first component's period).
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

namespace flexmoor::app {

// The node at `path` in `root`; nullopt, with what is missing ("no key 'Hz' in waves.spectrum
// (expected one of: type, Hs, Tp)") in `missing`, when there is none.
std::optional<YAML::Node> nodeAtPath(const YAML::Node& root, const std::string& path,
                                     std::string& missing);

// Makes `target` (a node of a document) hold `value`: a scalar in place, so that the node keeps
// its mark and the case reader's messages about it name the line of the document's own value;
// a list or map as a copy of it.
void setNode(YAML::Node target, const YAML::Node& value);

// The path as a netCDF name: '.' replaced by '_' ("waves_spectrum_Hs").
std::string pathVariableName(const std::string& path);

}  // namespace flexmoor::app
