#include "geometry_erp/surface_fill.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::erp {

namespace {

/// The projection of a point onto the y-z plane, (u, v) = (y, z).
struct Uv {
  double u, v;
};

bool less(const Uv& a, const Uv& b) {
  return a.u < b.u || (a.u == b.u && a.v < b.v);
}

/// The edge function of P -> Q at p, (Q - P) x (p - P), computed from the lexicographically
/// smaller end so that both triangles on an edge get the same magnitude, bit for bit.
double edge_function(const Uv& P, const Uv& Q, const Uv& p) {
  const bool forward = less(P, Q);
  const Uv& S = forward ? P : Q;
  const Uv& T = forward ? Q : P;
  const double f = (T.u - S.u) * (p.v - S.v) - (T.v - S.v) * (p.u - S.u);
  return forward ? f : -f;
}

/// Whether a zero edge function on P -> Q (counter-clockwise) counts as inside: for the edge and
/// its reverse exactly one does (the top-left rule).
bool owns(const Uv& P, const Uv& Q) {
  const double du = Q.u - P.u, dv = Q.v - P.v;
  return dv < 0.0 || (dv == 0.0 && du > 0.0);
}

} // namespace

std::vector<Vec3> fill_closed_surface(std::span<const Vec3> points,
                                      std::span<const std::array<int, 3>> triangles, double l0) {
  if (points.empty() || triangles.empty()) return {};
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const auto count = [&](int a) { // the points strictly inside the bounding box along axis a
    int n = 0;
    while (lo[a] + (n + 0.5) * l0 < hi[a]) ++n;
    return n;
  };
  const int nx = count(0), ny = count(1), nz = count(2);
  const auto at = [&](int a, int i) { return lo[a] + (i + 0.5) * l0; };
  // The x of every crossing of each ray (j, k), from each triangle's rows.
  std::vector<std::vector<double>> hits(static_cast<std::size_t>(ny) *
                                        static_cast<std::size_t>(nz));
  for (const auto& t : triangles) {
    std::array<Vec3, 3> x;
    std::array<Uv, 3> q;
    for (std::size_t c = 0; c < 3; ++c) {
      x[c] = points[static_cast<std::size_t>(t[c])];
      q[c] = {x[c].y(), x[c].z()};
    }
    const double area =
        (q[1].u - q[0].u) * (q[2].v - q[0].v) - (q[1].v - q[0].v) * (q[2].u - q[0].u);
    if (area == 0.0) continue;                                    // parallel to the rays
    if (area < 0.0) std::swap(q[1], q[2]), std::swap(x[1], x[2]); // counter-clockwise in (u, v)
    // The rows its bounding box spans, one more each side (rounding must not drop a tie).
    const auto first = [&](int a, double low) {
      return std::max(0, static_cast<int>(std::ceil((low - lo[a]) / l0 - 0.5)) - 1);
    };
    const auto last = [&](int a, double high, int n) {
      return std::min(n - 1, static_cast<int>(std::floor((high - lo[a]) / l0 - 0.5)) + 1);
    };
    const int j0 = first(1, std::min({x[0].y(), x[1].y(), x[2].y()}));
    const int j1 = last(1, std::max({x[0].y(), x[1].y(), x[2].y()}), ny);
    const int k0 = first(2, std::min({x[0].z(), x[1].z(), x[2].z()}));
    const int k1 = last(2, std::max({x[0].z(), x[1].z(), x[2].z()}), nz);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j) {
        const Uv p{at(1, j), at(2, k)};
        std::array<double, 3> f; // f[c]: the edge opposite corner c
        bool inside = true;
        for (std::size_t c = 0; c < 3 && inside; ++c) {
          const Uv &P = q[(c + 1) % 3], &Q = q[(c + 2) % 3];
          f[c] = edge_function(P, Q, p);
          inside = f[c] > 0.0 || (f[c] == 0.0 && owns(P, Q));
        }
        if (!inside) continue;
        const double sum = f[0] + f[1] + f[2]; // the barycentric weights of p, times the area
        const double x_hit = (f[0] * x[0].x() + f[1] * x[1].x() + f[2] * x[2].x()) / sum;
        hits[static_cast<std::size_t>(k) * static_cast<std::size_t>(ny) +
             static_cast<std::size_t>(j)]
            .push_back(x_hit);
      }
  }
  std::vector<Vec3> filled;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      std::vector<double>& row = hits[static_cast<std::size_t>(k) * static_cast<std::size_t>(ny) +
                                      static_cast<std::size_t>(j)];
      std::sort(row.begin(), row.end());
      for (int i = 0; i < nx; ++i) {
        const double xi = at(0, i);
        const auto beyond = row.end() - std::upper_bound(row.begin(), row.end(), xi);
        if (beyond % 2 == 1) filled.emplace_back(xi, at(1, j), at(2, k));
      }
    }
  return filled;
}

} // namespace fsi::erp
