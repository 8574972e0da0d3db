#pragma once
// A reproducible random cloud in D dimensions for the grid and list tests, with a few particles
// outside the box the grid is built for (the open sides clamp them into the edge cells).
#include "particles/cell_grid.hpp"

#include <array>
#include <cstddef>
#include <random>
#include <vector>

namespace fsi::particles::test {

template <int D> struct Cloud {
  std::array<std::vector<double>, D> x;
  std::size_t size() const { return x[0].size(); }
  Coords<D> coords() const {
    Coords<D> c;
    for (std::size_t a = 0; a < D; ++a) c[a] = x[a].data();
    return c;
  }
  VecD<D> at(std::size_t i) const {
    VecD<D> p;
    for (int a = 0; a < D; ++a) p[a] = x[static_cast<std::size_t>(a)][i];
    return p;
  }
};

/// n points uniform in [0, side]^D, every 50th pushed up to `side` / 4 outside along one axis.
template <int D> Cloud<D> random_cloud(std::size_t n, double side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, side), out(-0.25 * side, 1.25 * side);
  Cloud<D> c;
  for (auto& v : c.x) v.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < D; ++a) c.x[a][i] = i % 50 == 7 && a == i % D ? out(rng) : u(rng);
  return c;
}

/// A cell grid of side h over [0, side]^D with the cloud binned in it.
template <int D> BasicCellGrid<D> binned_grid(const Cloud<D>& c, double side, double h) {
  BasicCellGrid<D> grid(VecD<D>::Zero(), VecD<D>::Constant(side), h);
  grid.bin(c.coords(), c.size());
  return grid;
}

/// The particles within `radius` of p (j != skip), by testing every particle: the reference.
template <int D>
std::vector<std::uint32_t> brute_force(const Cloud<D>& c, const VecD<D>& p, double radius,
                                       std::size_t skip) {
  std::vector<std::uint32_t> within;
  for (std::size_t j = 0; j < c.size(); ++j)
    if (j != skip && (c.at(j) - p).squaredNorm() < radius * radius)
      within.push_back(static_cast<std::uint32_t>(j));
  return within;
}

} // namespace fsi::particles::test
