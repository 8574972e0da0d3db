#pragma once
// Shared by the fluid's sources (private to fluid_sph): the no-particle index and the number
// format of messages.
#include "fsi/core/format.hpp"

#include <cstddef>
#include <limits>
#include <string>

namespace fsi::sph {

/// No particle (an unset index; the neutral element of a first-bad-particle reduction).
inline constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// A number as a message shows it: 6 significant digits.
inline std::string fmt(double v) {
  return significant(v, 6);
}

} // namespace fsi::sph
