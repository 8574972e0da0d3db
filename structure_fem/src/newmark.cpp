#include "structure_fem/newmark.hpp"

#include <cmath>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::fem {

void validate(const NewmarkOptions& o) {
  if (!(o.beta > 0.0) || !std::isfinite(o.beta))
    throw InputError("newmark: beta = " + std::to_string(o.beta) + ": must be > 0");
  if (!(o.gamma >= 0.5) || !std::isfinite(o.gamma))
    throw InputError("newmark: gamma = " + std::to_string(o.gamma) + ": must be >= 0.5");
}

} // namespace fsi::fem
