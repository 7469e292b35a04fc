// Errors for bad input. Physics validates parameters once, at the edge, and throws
// InputError with a message that names the offending field and its allowed range; the
// hot paths (impact solve, flight step) assume validated input and never throw.
#pragma once

#include <stdexcept>
#include <string>

namespace sweetspot {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sweetspot
