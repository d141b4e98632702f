#include "apps/common/format_number.hpp"

#include <sstream>

namespace flexmoor::app {

std::string formatNumber(double value) {
  std::ostringstream s;
  s.precision(10);  // the default float format is %g's
  s << value;
  return s.str();
}

}  // namespace flexmoor::app
