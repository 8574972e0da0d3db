#include "coupling/convergence_absolute.hpp"

#include <sstream>

namespace fsi::coupling {

std::string AbsoluteConvergence::criterion() const {
  std::ostringstream s;
  s << "||r|| < " << tolerance_;
  return s.str();
}

} // namespace fsi::coupling
