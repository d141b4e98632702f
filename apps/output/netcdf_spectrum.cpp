// The target spectrum of a run's irregular sea, in the netCDF's global attributes
// (NetcdfWriter::defineSpectrum): what `flexmoor plot --spectrum` draws the estimate against.
#include <cmath>
#include <vector>

#include "apps/output/netcdf_writer.hpp"
#include "libhydro/waves/wave_spectrum.hpp"

namespace flexmoor::app {

void NetcdfWriter::defineSpectrum(const hydro::WaveSpectrum& s, std::pair<double, double> band) {
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_band", std::vector<double>{band.first, band.second});
  if (s.isTable()) {
    file_.putAttribute(NC_GLOBAL, "sea_spectrum", "table");
    std::vector<double> omega, density;
    for (const auto& [w, S] : s.samples()) {
      omega.push_back(w);
      density.push_back(S);
    }
    file_.putAttribute(NC_GLOBAL, "sea_spectrum_omega", omega);
    file_.putAttribute(NC_GLOBAL, "sea_spectrum_density", density);
    return;
  }
  const double gamma = s.peakEnhancement();
  file_.putAttribute(NC_GLOBAL, "sea_spectrum", gamma == 1.0 ? "pierson_moskowitz" : "jonswap");
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_Hs", s.significantHeight());
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_Tp", 2.0 * std::acos(-1.0) / s.peakFrequency());
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_gamma", gamma);
}

}  // namespace flexmoor::app
