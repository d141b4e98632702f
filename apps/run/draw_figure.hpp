#pragma once
// The figure of a run (a case's figure:): drawn by apps/plot/flexmoor_plot.py (found by
// plotScript of apps/common/data_dir.hpp) under Debian's interpreter from the netCDF the run left,
// into a temporary file renamed into place, so a figure is whole or absent.
#include <ostream>
#include <string>
#include <vector>

#include "apps/problem/case.hpp"

namespace flexmoor::app {

// The command line of apps/plot/flexmoor_plot.py under Debian's interpreter (its matplotlib and
// xarray belong to it): `flexmoor plot` hands over to it, and drawFigure runs it. figure_options
// are the plot's other options as given ("--spectrum", "wave_elevation", ...), checked by it.
// Throws std::runtime_error when the script is not found.
std::vector<std::string> plotArguments(const std::string& netcdf, const std::string& png,
                                       const std::vector<std::string>& series,
                                       const std::string& title,
                                       const std::vector<std::string>& figure_options = {});

// Draws `figure` of `netcdf` into `png`. Returns false, saying why on `diag`, when it could not
// (no /usr/bin/python3 or matplotlib, the plot failed); the run's results stand either way.
bool drawFigure(const FigureSpec& figure, const std::string& case_title, const std::string& netcdf,
                const std::string& png, std::ostream& diag);

}  // namespace flexmoor::app
