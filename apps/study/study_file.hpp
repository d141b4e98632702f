#pragma once
// DIR/study.nc (CF-1.8), from the members' outcomes and series.nc (member_store.hpp), as
// /work/notes/study_format.md says: dimension member; member(member) 1-based; one variable per
// varied parameter (numbers in SI, or text); status(member) and error(member, error_strlen);
// NAME_S(member) for every collect NAME and statistic S (max, min, mean, std, amplitude: time-
// weighted, study_statistics.hpp), _FillValue where the member failed; and for every collect
// with spectrum: NAME_psd(member, frequency), Welch's estimate (libhydro/signal/welch.hpp) on
// one frequency axis for the study: every member's series resampled linearly at one dt, the
// segment's length divided into an even number L of samples no longer than the largest median
// time step of the members, so that omega_k = 2 pi k / segment, k = 0 .. L / 2, for all.
// NAME_mpm (with mpm_duration, s, and mpm_fit) is the most probable maximum over the stated
// duration (libhydro/signal/extremes.hpp) of the series resampled at its median step, the fill
// value where the record is too short for the fit.
#include <string>

#include "apps/study/study.hpp"

namespace flexmoor::app {

// Writes DIR/study.nc in place (atomically); returns how many members are complete.
int writeStudyFile(const Study& study, const std::string& dir);

}  // namespace flexmoor::app
