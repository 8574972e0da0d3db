#pragma once
// The particle positions of a wall query: one array of points, or one array per coordinate.
// BasicQueryPoints<D> for D = 2 (QueryPoints, polygon walls) and 3 (QueryPoints3, triangle walls).
#include "fsi/core/types.hpp"

#include <array>
#include <cstddef>
#include <span>

namespace fsi::erp {

template <int D> class BasicQueryPoints {
public:
  explicit BasicQueryPoints(std::span<const VecD<D>> p) : p_(p.data()), n_(p.size()) {}
  BasicQueryPoints(std::span<const double> x, std::span<const double> y) requires(D == 2)
      : c_{x.data(), y.data()}, n_(x.size()) {}
  BasicQueryPoints(std::span<const double> x, std::span<const double> y,
                   std::span<const double> z) requires(D == 3)
      : c_{x.data(), y.data(), z.data()}, n_(x.size()) {}
  std::size_t size() const { return n_; }
  VecD<D> operator()(std::size_t i) const {
    if (p_) return p_[i];
    if constexpr (D == 2)
      return Vec2(c_[0][i], c_[1][i]);
    else
      return Vec3(c_[0][i], c_[1][i], c_[2][i]);
  }

private:
  const VecD<D>* p_ = nullptr;
  std::array<const double*, D> c_{};
  std::size_t n_;
};

using QueryPoints = BasicQueryPoints<2>;
using QueryPoints3 = BasicQueryPoints<3>;

} // namespace fsi::erp
