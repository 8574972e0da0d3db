#include "geometry_erp/convex_wedge3.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace fsi::erp {

namespace {

constexpr double parallel_cos = 1.0 - 1e-9, perpendicular_cos = 1e-9;
constexpr double inf = std::numeric_limits<double>::infinity();

/// Rows of the lattice along one axis, at coordinates c from the particle: all rows j l0 (free),
/// or the half-line of rows c = side (a + l0/2 + m l0), m >= 0, beyond a plane at distance a >= 0.
struct Rows {
  double sign; // the term's sign in the axis's expansion
  bool free;
  double side, a;
};

/// The rows l < c < u along one axis as signed sums of Rows: a bound the particle is outside of
/// gives a half-line, one it is inside of the free rows less the half-line beyond it.
std::vector<Rows> axis_rows(double l, double u) {
  if (l == -inf && u == inf) return {{1.0, true, 0.0, 0.0}};
  if (l == -inf)
    return u < 0.0 ? std::vector<Rows>{{1.0, false, -1.0, -u}}
                   : std::vector<Rows>{{1.0, true, 0.0, 0.0}, {-1.0, false, 1.0, u}};
  if (u == inf)
    return l > 0.0 ? std::vector<Rows>{{1.0, false, 1.0, l}}
                   : std::vector<Rows>{{1.0, true, 0.0, 0.0}, {-1.0, false, -1.0, -l}};
  if (u < 0.0) return {{1.0, false, -1.0, -u}, {-1.0, false, -1.0, -l}};
  if (l > 0.0) return {{1.0, false, 1.0, l}, {-1.0, false, 1.0, u}};
  return {{1.0, true, 0.0, 0.0}, {-1.0, false, 1.0, u}, {-1.0, false, -1.0, -l}};
}

std::vector<double> coordinates(const Rows& rows, double l0, double r_e) {
  std::vector<double> c;
  if (rows.free) {
    const int reach = static_cast<int>(std::ceil(r_e / l0));
    for (int j = -reach; j <= reach; ++j) c.push_back(j * l0);
  } else {
    for (double d = rows.a + 0.5 * l0; d < r_e; d += l0) c.push_back(rows.side * d);
  }
  return c;
}

} // namespace

std::optional<LatticeSum3> region_lattice_sum3(std::span<const HalfSpace3> region, double l0,
                                               double r_e, const particles::MpsWeight& w) {
  // The half-spaces as bounds l < c < u on the coordinates c along up to three perpendicular axes.
  std::array<Vec3, 3> axis;
  std::array<double, 3> lower{-inf, -inf, -inf}, upper{inf, inf, inf};
  std::size_t axes = 0;
  for (const HalfSpace3& h : region) {
    std::size_t a = 0;
    for (; a < axes; ++a) {
      const double c = std::abs(h.n.dot(axis[a]));
      if (c > parallel_cos) break;
      if (c > perpendicular_cos) return std::nullopt;
    }
    if (a == axes) {
      if (axes == axis.size()) return std::nullopt;
      axis[axes++] = h.n;
    }
    if (h.n.dot(axis[a]) > 0.0) // (y - x_i) . n < -s
      upper[a] = std::min(upper[a], -h.s);
    else
      lower[a] = std::max(lower[a], h.s);
  }
  std::array<std::vector<Rows>, 3> terms;
  for (std::size_t a = 0; a < 3; ++a) {
    if (a < axes && lower[a] >= upper[a]) return LatticeSum3{}; // empty
    terms[a] = a < axes ? axis_rows(lower[a], upper[a]) : axis_rows(-inf, inf);
  }
  LatticeSum3 sum;
  for (const Rows& t0 : terms[0])
    for (const Rows& t1 : terms[1])
      for (const Rows& t2 : terms[2]) {
        const double sign = t0.sign * t1.sign * t2.sign;
        const std::vector<double> c0 = coordinates(t0, l0, r_e), c1 = coordinates(t1, l0, r_e),
                                  c2 = coordinates(t2, l0, r_e);
        std::array<double, 3> g{0.0, 0.0, 0.0};
        double weight = 0.0;
        for (double d0 : c0)
          for (double d1 : c1)
            for (double d2 : c2) {
              const double rho2 = d0 * d0 + d1 * d1 + d2 * d2;
              if (rho2 == 0.0 || rho2 >= r_e * r_e) continue; // the particle's own site
              const double wk = w(std::sqrt(rho2));
              weight += wk;
              g[0] += d0 * wk / rho2, g[1] += d1 * wk / rho2, g[2] += d2 * wk / rho2;
            }
        sum.weight += sign * weight;
        for (std::size_t a = 0; a < axes; ++a) sum.gradient += sign * g[a] * axis[a];
      }
  return sum;
}

} // namespace fsi::erp
