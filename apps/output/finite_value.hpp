#pragma once
// The writers' guard: no NaN or infinity ever reaches an output silently. A non-finite value
// stops the write with an error that names the file and the value's place in it.
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexmoor::app {

// Throws std::runtime_error "PATH: WHAT is NaN; refusing to write a non-finite value" when
// `value` is not finite. `what` is called only then, so building the description costs nothing
// on the normal path.
template <class Describe>
void requireFinite(double value, const std::string& path, Describe what) {
  if (std::isfinite(value)) return;
  const char* kind = std::isnan(value) ? "NaN" : (value > 0 ? "+Inf" : "-Inf");
  throw std::runtime_error(path + ": " + what() + " is " + kind +
                           "; refusing to write a non-finite value");
}

// The same for the `count` values at `values`; `what(i)` describes value i.
template <class Describe>
void requireAllFinite(const double* values, size_t count, const std::string& path, Describe what) {
  for (size_t i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) requireFinite(values[i], path, [&] { return what(i); });
}

}  // namespace flexmoor::app
