#include "harness/core/text_format.hpp"

#include <iomanip>
#include <sstream>

namespace vsgl {

std::string number_text(double value, int digits) {
  std::ostringstream out;
  out << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace vsgl
