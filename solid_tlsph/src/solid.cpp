#include "solid_tlsph/solid.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"
#include "particles/cell_grid.hpp"
#include "particles/kernels.hpp"
#include "particles/neighbor_list.hpp"

namespace fsi::tlsph {

namespace {

constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

template <class T> void require(bool ok, const std::string& key, T value, const char* range) {
  if (ok) return;
  std::ostringstream s;
  s << "tlsph: " << key << " = " << value << " must be " << range;
  throw InputError(s.str());
}

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b, double* xi) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  if (xi) *xi = t;
  return (p - (a + t * ab)).norm();
}

/// The quadratic fit's monomials of d = (X_b - X_a) / h (build_quadratic).
Eigen::Matrix<double, 5, 1> monomials(double dx, double dy) {
  Eigen::Matrix<double, 5, 1> p;
  p << dx, dy, 0.5 * dx * dx, dx * dy, 0.5 * dy * dy;
  return p;
}

} // namespace

void validate(const TlsphOptions& o) {
  materials::validate(o.material);
  require(o.dp > 0.0, "dp", o.dp, "> 0");
  require(o.h_factor >= 1.0 && o.h_factor <= 2.0, "h_factor", o.h_factor, "in [1, 2]");
  require(o.cfl > 0.0 && o.cfl <= 1.0, "cfl", o.cfl, "in (0, 1]");
  require(o.pair_damping >= 0.0, "pair_damping", o.pair_damping, ">= 0");
  require(o.mass_damping >= 0.0, "mass_damping", o.mass_damping, ">= 0");
  require(o.max_neighbors >= 8, "max_neighbors", o.max_neighbors, ">= 8");
  require(o.hourglass >= 0.0, "hourglass", o.hourglass, ">= 0");
  if (o.gradient_correction == GradientCorrection::quadratic && !o.kernel_correction)
    throw InputError("tlsph: gradient_correction = quadratic needs kernel_correction = true");
  require(o.gravity.allFinite(), "gravity", o.gravity.transpose(), "finite");
  for (std::size_t k = 0; k < o.clamps.size(); ++k) {
    const auto& c = o.clamps[k];
    if (!c.contains)
      throw InputError("tlsph: clamps[" + std::to_string(k) + "].contains is not set");
    if (!c.face_normal.allFinite() || !c.face_point.allFinite())
      throw InputError("tlsph: clamps[" + std::to_string(k) + "]: face is not finite");
    if (static_cast<bool>(c.position) != static_cast<bool>(c.velocity))
      throw InputError("tlsph: clamps[" + std::to_string(k) +
                       "]: set both position and velocity of a moving clamp, or neither");
  }
}

TlsphSolid::TlsphSolid(SolidGeometry geometry, TlsphOptions options)
    : options_(std::move(options)), x_(fields_.add_real("x")), y_(fields_.add_real("y")),
      vx_(fields_.add_real("vx")), vy_(fields_.add_real("vy")), ax_(fields_.add_real("ax")),
      ay_(fields_.add_real("ay")), fx_(fields_.add_real("fx")), fy_(fields_.add_real("fy")),
      X0_(fields_.add_real("X0", false)), Y0_(fields_.add_real("Y0", false)),
      V0_(fields_.add_real("V0", false)), B00_(fields_.add_real("B00", false)),
      B01_(fields_.add_real("B01", false)), B10_(fields_.add_real("B10", false)),
      B11_(fields_.add_real("B11", false)), clamped_(fields_.add_flag("clamp", false)),
      surface_(fields_.add_flag("surface", false)), F00_(fields_.add_real("F00", false)),
      F01_(fields_.add_real("F01", false)), F10_(fields_.add_real("F10", false)),
      F11_(fields_.add_real("F11", false)), PB00_(fields_.add_real("PB00", false)),
      PB01_(fields_.add_real("PB01", false)), PB10_(fields_.add_real("PB10", false)),
      PB11_(fields_.add_real("PB11", false)) {
  validate(options_);
  const std::size_t n = geometry.X0.size();
  if (n == 0) throw InputError("tlsph: the geometry holds no particles");
  if (geometry.V0.size() != n)
    throw InputError("tlsph: " + std::to_string(geometry.V0.size()) + " volumes for " +
                     std::to_string(n) + " particles");
  if (geometry.outline_tags.size() != geometry.outline.size())
    throw InputError("tlsph: outline has " + std::to_string(geometry.outline.size()) +
                     " edges but " + std::to_string(geometry.outline_tags.size()) + " tags");
  material_ = materials::make_material(options_.material);
  rho0_ = options_.material.density;
  h_ = options_.h_factor * options_.dp;
  {
    const double E = options_.material.youngs_modulus, nu = options_.material.poisson_ratio;
    const double K = E / (3.0 * (1.0 - 2.0 * nu)); // eq. 11
    c_s_ = std::sqrt(K / rho0_);
  }
  fields_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(geometry.V0[i] > 0.0))
      throw InputError("tlsph: particle " + std::to_string(i) + " has volume <= 0");
    X0_[i] = x_[i] = geometry.X0[i].x();
    Y0_[i] = y_[i] = geometry.X0[i].y();
    V0_[i] = geometry.V0[i];
    for (std::size_t k = 0; k < options_.clamps.size(); ++k)
      if (options_.clamps[k].contains(geometry.X0[i])) {
        clamped_[i] = static_cast<std::uint8_t>(k + 1);
        break;
      }
  }
  build_reference();
  build_interface(geometry);
  build_images();
  if (quadratic_ && options_.hourglass > 0.0) { // k_ab = hourglass E V_a w_ab; not on images
    const std::size_t pairs = pair_b_.size();
    pair_k_.assign(pairs, 0.0), pair_rx_.assign(pairs, 0.0), pair_ry_.assign(pairs, 0.0);
    const double k = options_.hourglass * options_.material.youngs_modulus;
    for (std::size_t a = 0; a < n; ++a)
      if (!imaged(a))
        for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q)
          pair_k_[q] = k * V0_[a] * pair_dwr_[q];
  }
  prescribe(0.0);
  compute_stress();
  compute_acceleration();
}

TlsphSolid::~TlsphSolid() = default;

void TlsphSolid::build_reference() {
  const std::size_t n = size();
  Vec2 lo(X0_[0], Y0_[0]), hi = lo;
  for (std::size_t i = 0; i < n; ++i)
    lo = lo.cwiseMin(Vec2(X0_[i], Y0_[i])), hi = hi.cwiseMax(Vec2(X0_[i], Y0_[i]));
  const particles::WendlandC2 kernel(h_);
  const double radius = kernel.cutoff();
  particles::CellGrid grid(lo, hi, radius);
  grid.bin(X0_.data(), Y0_.data(), n);
  particles::NeighborList list;
  const auto capacity = static_cast<std::size_t>(options_.max_neighbors);
  if (!list.build(grid, X0_.data(), Y0_.data(), n, radius, capacity))
    throw InputError("tlsph: particle " + std::to_string(list.overflow()) + " has more than " +
                     "max_neighbors = " + std::to_string(capacity) + " neighbours within 2h");
  pair_start_.assign(n + 1, 0);
  for (std::size_t a = 0; a < n; ++a) pair_start_[a + 1] = pair_start_[a] + list.count(a);
  const std::size_t pairs = pair_start_[n];
  pair_b_.resize(pairs), pair_gx_.resize(pairs), pair_gy_.resize(pairs), pair_dwr_.resize(pairs);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    const std::uint32_t* row = list.row(a);
    std::vector<std::uint32_t> sorted(row, row + list.count(a));
    std::sort(sorted.begin(), sorted.end()); // a fixed summation order
    Mat2 M = Mat2::Zero();
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      const std::size_t p = pair_start_[a] + k, b = sorted[k];
      const Vec2 X_ab(X0_[a] - X0_[b], Y0_[a] - Y0_[b]);
      const double r = X_ab.norm(), dW = kernel.dW(r);
      const Vec2 g = X_ab / r * dW * V0_[b]; // grad0 W_ab V_b, gradient with respect to X_a
      pair_b_[p] = static_cast<std::uint32_t>(b);
      pair_gx_[p] = g.x(), pair_gy_[p] = g.y();
      pair_dwr_[p] = -dW / r * V0_[b];
      M -= X_ab * g.transpose(); // sum (X_b - X_a) (x) grad0 W_ab V_b (eq. 14)
    }
    Mat2 B = Mat2::Identity();
    if (options_.kernel_correction) {
      const double det = M.determinant();
      if (!(std::abs(det) > 1e-8)) { // M ~ I for a full lattice: det ~ 1
        if (bad == none) bad = a;
      } else {
        B = M.inverse();
      }
    }
    B00_[a] = B(0, 0), B01_[a] = B(0, 1), B10_[a] = B(1, 0), B11_[a] = B(1, 1);
  }
  if (bad != none)
    throw InputError("tlsph: particle " + std::to_string(bad) +
                     " has a singular moment matrix (eq. 14): too few neighbours in 2h");
  quadratic_ = options_.gradient_correction == GradientCorrection::quadratic;
  if (quadratic_) build_quadratic();
}

void TlsphSolid::build_quadratic() {
  // Weighted least squares of u_b - u_a by c . p(d), d = (X_b - X_a) / h, with the monomials
  // p = (d_x, d_y, d_x^2 / 2, d_x d_y, d_y^2 / 2) and the weights of eq. 14, w_ab = |dW_ab| /
  // r_ab V_b (with p = (d_x, d_y) alone this is exactly B0: g~_ab = B0_a grad0 W_ab V_b). The
  // gradient is (c_0, c_1) / h, so g~_ab = w_ab [A_a^-1 p_ab]_(0,1) / h, A_a = sum w p p^T.
  using Vec5 = Eigen::Matrix<double, 5, 1>;
  using Mat5 = Eigen::Matrix<double, 5, 5>;
  const std::size_t n = size(), pairs = pair_b_.size();
  pair_qx_.resize(pairs), pair_qy_.resize(pairs), pair_rev_.resize(pairs);
  auto pair_monomials = [&](std::size_t a, std::size_t b) {
    return monomials((X0_[b] - X0_[a]) / h_, (Y0_[b] - Y0_[a]) / h_);
  };
  const bool hourglass = options_.hourglass > 0.0;
  if (hourglass) pair_fit_.assign(5 * pairs, 0.0);
  std::size_t bad = none;
  for (std::size_t a = 0; a < n; ++a) {
    Mat5 A = Mat5::Zero();
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Vec5 p = pair_monomials(a, pair_b_[q]);
      A += pair_dwr_[q] * h_ * h_ * p * p.transpose(); // w scaled by h^2: A ~ 1
    }
    const Eigen::PartialPivLU<Mat5> lu(A);
    if (!(lu.rcond() > 1e-10)) {
      if (bad == none) bad = a;
      continue;
    }
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const Vec5 c = lu.solve(pair_monomials(a, pair_b_[q]));
      pair_qx_[q] = pair_dwr_[q] * h_ * c(0), pair_qy_[q] = pair_dwr_[q] * h_ * c(1);
      if (hourglass) // the fit's coefficients are sum_c (u_c - u_a) s_ac^T
        for (int m = 0; m < 5; ++m) pair_fit_[5 * q + m] = pair_dwr_[q] * h_ * h_ * c(m);
    }
  }
  if (bad != none)
    throw InputError("tlsph: particle " + std::to_string(bad) +
                     " has a singular quadratic moment matrix: too few neighbours in 2h for "
                     "gradient_correction = quadratic");
  // The one-sided quadratic stencils of surface and corner particles have larger weights than
  // B0's, and the highest frequency grows with them: the stable step is divided by the ratio
  // of the largest sum_b |g~_ab| to the largest sum_b |B0_a grad0 W_ab V_b|.
  double sum_q = 0.0, sum_l = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    double sq = 0.0, sl = 0.0;
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      sq += std::hypot(pair_qx_[q], pair_qy_[q]);
      sl += std::hypot(B00_[a] * pair_gx_[q] + B01_[a] * pair_gy_[q],
                       B10_[a] * pair_gx_[q] + B11_[a] * pair_gy_[q]);
    }
    sum_q = std::max(sum_q, sq), sum_l = std::max(sum_l, sl);
  }
  dt_scale_ = std::min(1.0, sum_l / sum_q);
  // The reverse pair (b, a) in b's row (rows are sorted by neighbour, the list is symmetric).
  for (std::size_t a = 0; a < n; ++a)
    for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q) {
      const std::uint32_t b = pair_b_[q];
      const auto first = pair_b_.begin() + pair_start_[b],
                 last = pair_b_.begin() + pair_start_[b + 1];
      const auto it = std::lower_bound(first, last, static_cast<std::uint32_t>(a));
      if (it == last || *it != a)
        throw InputError("tlsph: the reference neighbour list is not symmetric at particle " +
                         std::to_string(a)); // cannot happen with one radius
      pair_rev_[q] = static_cast<std::uint32_t>(it - pair_b_.begin());
    }
}

void TlsphSolid::build_interface(const SolidGeometry& geometry) {
  const auto& outline = geometry.outline;
  const std::size_t m = outline.size(), n = size();
  if (m == 0) return;
  std::vector<double> s0(m + 1, 0.0); // arc length at the start of each edge
  for (std::size_t e = 0; e < m; ++e)
    s0[e + 1] = s0[e] + (outline[(e + 1) % m] - outline[e]).norm();
  auto tagged = [&](std::size_t e) {
    const auto& tags = options_.interface_tags;
    return tags.empty() ||
           std::find(tags.begin(), tags.end(), geometry.outline_tags[e]) != tags.end();
  };
  // Interface nodes lie ON the tagged outline, each attached to a surface particle: the
  // particle's projection onto its nearest tagged edge, and every vertex of a tagged edge
  // (attached to the particle nearest to it), so the chain is watertight down to a clamp or a
  // floor. Clamped particles belong to it too (their loads are reactions).
  struct Node {
    double s;        // arc length along the outline
    std::uint32_t i; // the attached particle
    Vec2 X, n0;      // reference position on the outline, outward normal
  };
  std::vector<Node> nodes;
  const double band = options_.dp; // the outer lattice layer lies at dp / 2 from the outline
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 X(X0_[i], Y0_[i]);
    // The nearest tagged edge places the particle along the outline (a corner particle
    // belongs to every edge within the band; the first tagged one wins a tie). Only a
    // projection inside the edge counts: past a concave vertex (an interface edge ending on a
    // clamp's face) it would land on the vertex, which has its own node.
    double best = std::numeric_limits<double>::max(), best_xi = 0.0;
    std::size_t best_e = m;
    for (std::size_t e = 0; e < m; ++e) {
      const Vec2 &a = outline[e], &b = outline[(e + 1) % m];
      double xi = 0.0;
      const double d = point_segment_distance(X, a, b, &xi);
      if (d >= band) continue;
      surface_[i] = 1;
      if (tagged(e) && d < best && xi > 0.0 && xi < 1.0) best = d, best_e = e, best_xi = xi;
    }
    if (best_e == m) continue;
    const Vec2 &a = outline[best_e], &b = outline[(best_e + 1) % m];
    const Vec2 t = (b - a).normalized();
    nodes.push_back({s0[best_e] + best_xi * (s0[best_e + 1] - s0[best_e]),
                     static_cast<std::uint32_t>(i), a + best_xi * (b - a), Vec2(t.y(), -t.x())});
  }
  for (std::size_t v = 0; v < m; ++v) { // vertex v joins edge v - 1 and edge v
    const std::size_t before = (v + m - 1) % m;
    if (!tagged(v) && !tagged(before)) continue;
    const Vec2& X = outline[v];
    Vec2 normal = Vec2::Zero();
    for (const std::size_t e : {before, v})
      if (tagged(e)) {
        const Vec2 t = (outline[(e + 1) % m] - outline[e]).normalized();
        normal += Vec2(t.y(), -t.x()); // outward for a counter-clockwise outline
      }
    nodes.push_back(
        {s0[v], static_cast<std::uint32_t>(nearest_particle(X)), X, normal.normalized()});
  }
  std::stable_sort(nodes.begin(), nodes.end(),
                   [](const Node& a, const Node& b) { return a.s < b.s; });
  interface_mesh_.order = 1;
  interface_mesh_.X0.clear();
  interface_mesh_.edges.clear();
  for (const Node& node : nodes) {
    interface_.push_back(node.i);
    interface_n0_.push_back(node.n0);
    interface_offset_.push_back(node.X - Vec2(X0_[node.i], Y0_[node.i]));
    interface_mesh_.X0.push_back(node.X);
  }
  // Order-1 edges between neighbours along the outline (dp apart along an edge, 1.5 dp from a
  // vertex to the first projection past a corner); the chain closes when the whole outline is
  // interface.
  const double link = 2.0 * options_.dp;
  const std::size_t k = nodes.size();
  for (std::size_t a = 0; a + 1 < k; ++a)
    if ((interface_mesh_.X0[a + 1] - interface_mesh_.X0[a]).norm() < link)
      interface_mesh_.edges.push_back({a, a, a + 1});
  if (k > 2 && (interface_mesh_.X0[0] - interface_mesh_.X0[k - 1]).norm() < link)
    interface_mesh_.edges.push_back({k - 1, k - 1, 0});
  interface_mesh_.particle_volume.clear();
  if (!options_.interface_particles) return;
  for (std::size_t i = 0; i < n; ++i) { // the particles themselves, on no edge
    interface_.push_back(static_cast<std::uint32_t>(i));
    interface_n0_.push_back(Vec2::Zero());
    interface_offset_.push_back(Vec2::Zero());
    interface_mesh_.X0.push_back(Vec2(X0_[i], Y0_[i]));
    interface_mesh_.particle_volume.push_back(V0_[i]);
  }
}

void TlsphSolid::clamp_face(std::size_t k, Vec2& point, Vec2& normal) const {
  const Clamp& c = options_.clamps[k];
  const double dp = options_.dp, tol = 1e-6 * dp;
  if (c.face_normal.norm() > 0.0) {
    point = c.face_point, normal = c.face_normal.normalized();
    return;
  }
  // The clamped-free pairs one lattice spacing apart: their directions give the normal, their
  // midpoints the face.
  Vec2 sum_d = Vec2::Zero(), sum_m = Vec2::Zero();
  std::vector<std::pair<Vec2, Vec2>> pairs; // (X_p - X_g, midpoint)
  for (std::size_t g = 0; g < size(); ++g) {
    if (clamped_[g] != k + 1) continue;
    for (std::uint32_t q = pair_start_[g]; q < pair_start_[g + 1]; ++q) {
      const std::uint32_t p = pair_b_[q];
      const Vec2 d(X0_[p] - X0_[g], Y0_[p] - Y0_[g]);
      if (clamped_[p] || std::abs(d.norm() - dp) > tol) continue;
      const Vec2 m(0.5 * (X0_[p] + X0_[g]), 0.5 * (Y0_[p] + Y0_[g]));
      pairs.emplace_back(d, m), sum_d += d, sum_m += m;
    }
  }
  const std::string clamp = "tlsph: clamps[" + std::to_string(k) + "]";
  if (pairs.empty() || !(sum_d.norm() > 0.0))
    throw InputError(clamp + ": no clamped particle is dp from a free one; set face_point and "
                             "face_normal, or odd_image = false");
  normal = sum_d.normalized(), point = sum_m / static_cast<double>(pairs.size());
  for (const auto& [d, m] : pairs)
    if ((d - dp * normal).norm() > tol || std::abs((m - point).dot(normal)) > tol)
      throw InputError(clamp + ": the clamped particles do not meet the free ones on one "
                               "straight face (odd_image); set face_point and face_normal, or "
                               "odd_image = false");
}

void TlsphSolid::build_images() {
  const std::size_t n = size(), clamps = options_.clamps.size();
  image_partner_.assign(n, none), image_of_.assign(n, none);
  imaged_.assign(clamps, 0);
  std::vector<Vec2> face_point(clamps), face_normal(clamps);
  for (std::size_t k = 0; k < clamps; ++k) {
    const Clamp& c = options_.clamps[k];
    imaged_[k] = c.odd_image && !c.position;
    if (!imaged_[k]) continue;
    bool any = false;
    for (std::size_t i = 0; i < n && !any; ++i) any = clamped_[i] == k + 1;
    if (any) clamp_face(k, face_point[k], face_normal[k]);
  }
  const double tol = 1e-6 * options_.dp;
  for (std::size_t g = 0; g < n; ++g) {
    if (!imaged(g)) continue;
    const std::size_t k = clamped_[g] - 1u;
    const Vec2 nrm = face_normal[k], X(X0_[g], Y0_[g]);
    const Vec2 M = X - 2.0 * (X - face_point[k]).dot(nrm) * nrm; // mirror position
    const std::size_t p = nearest_particle(M);
    if (!clamped_[p] && (Vec2(X0_[p], Y0_[p]) - M).norm() <= tol) {
      image_partner_[g] = p, image_of_[p] = g;
      images_ = true;
      continue;
    }
    // No partner: the particle stays at X0 and must not be a free particle's neighbour.
    for (std::uint32_t q = pair_start_[g]; q < pair_start_[g + 1]; ++q)
      if (!clamped_[pair_b_[q]])
        throw InputError("tlsph: clamped particle " + std::to_string(g) +
                         " lies within 2h of "
                         "free particle " +
                         std::to_string(pair_b_[q]) +
                         " but has no free particle at its mirror position (odd_image)");
  }
  image_ax_.assign(n, 0.0), image_ay_.assign(n, 0.0);
}

InterfaceMesh TlsphSolid::interface_mesh() const {
  return interface_mesh_;
}

void TlsphSolid::prescribe(double t) {
  parallel_for(size(), [&](std::size_t i) {
    if (!clamped_[i]) return;
    const Clamp& c = options_.clamps[clamped_[i] - 1u];
    const std::size_t p = image_partner_[i];
    if (p != none) { // u_g = -u_p, v_g = -v_p
      x_[i] = X0_[i] - (x_[p] - X0_[p]), y_[i] = Y0_[i] - (y_[p] - Y0_[p]);
      vx_[i] = -vx_[p], vy_[i] = -vy_[p], ax_[i] = -ax_[p], ay_[i] = -ay_[p];
    } else if (c.position) {
      const Vec2 X(X0_[i], Y0_[i]);
      const Vec2 x = c.position(X, t), v = c.velocity(X, t);
      // a by a central difference of the prescribed velocity (output only: clamped particles
      // are not integrated).
      const double d = 1e-6 * (1.0 + std::abs(t));
      const Vec2 a = (c.velocity(X, t + d) - c.velocity(X, t - d)) / (2.0 * d);
      x_[i] = x.x(), y_[i] = x.y(), vx_[i] = v.x(), vy_[i] = v.y(), ax_[i] = a.x(), ay_[i] = a.y();
    } else {
      x_[i] = X0_[i], y_[i] = Y0_[i], vx_[i] = vy_[i] = ax_[i] = ay_[i] = 0.0;
    }
  });
}

Mat2 TlsphSolid::deformation_gradient(std::size_t a) const {
  // eq. 13: F_a = (sum_b (u_b - u_a) (x) grad0 W_ab V_b) B0_a + I
  const double ux_a = x_[a] - X0_[a], uy_a = y_[a] - Y0_[a];
  // The quadratic correction: F_a = I + sum_b (u_b - u_a) (x) g~_ab (the gradients corrected).
  const double* gx = quadratic_ ? pair_qx_.data() : pair_gx_.data();
  const double* gy = quadratic_ ? pair_qy_.data() : pair_gy_.data();
  double G00 = 0.0, G01 = 0.0, G10 = 0.0, G11 = 0.0;
  for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
    const std::uint32_t b = pair_b_[p];
    const double dux = x_[b] - X0_[b] - ux_a, duy = y_[b] - Y0_[b] - uy_a;
    G00 += dux * gx[p], G01 += dux * gy[p];
    G10 += duy * gx[p], G11 += duy * gy[p];
  }
  if (quadratic_) {
    Mat2 F;
    F << 1.0 + G00, G01, G10, 1.0 + G11;
    return F;
  }
  Mat2 F;
  F(0, 0) = 1.0 + G00 * B00_[a] + G01 * B10_[a];
  F(0, 1) = G00 * B01_[a] + G01 * B11_[a];
  F(1, 0) = G10 * B00_[a] + G11 * B10_[a];
  F(1, 1) = 1.0 + G10 * B01_[a] + G11 * B11_[a];
  return F;
}

Mat2 TlsphSolid::correction_matrix(std::size_t a) const {
  Mat2 B;
  B << B00_[a], B01_[a], B10_[a], B11_[a];
  return B;
}

void TlsphSolid::hourglass_residuals(std::size_t a, double* rx, double* ry) const {
  // r_ab = (u_b - u_a) - C_a p_ab with the fit C_a = sum_c (u_c - u_a) s_ac^T
  const std::uint32_t start = pair_start_[a], end = pair_start_[a + 1];
  const double ux_a = x_[a] - X0_[a], uy_a = y_[a] - Y0_[a];
  double cx[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, cy[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pair_b_[q];
    const double dux = x_[b] - X0_[b] - ux_a, duy = y_[b] - Y0_[b] - uy_a;
    for (int m = 0; m < 5; ++m)
      cx[m] += dux * pair_fit_[5 * q + m], cy[m] += duy * pair_fit_[5 * q + m];
  }
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pair_b_[q];
    const auto p = monomials((X0_[b] - X0_[a]) / h_, (Y0_[b] - Y0_[a]) / h_);
    double fx = 0.0, fy = 0.0;
    for (int m = 0; m < 5; ++m) fx += cx[m] * p(m), fy += cy[m] * p(m);
    rx[q - start] = x_[b] - X0_[b] - ux_a - fx, ry[q - start] = y_[b] - Y0_[b] - uy_a - fy;
  }
}

void TlsphSolid::compute_stress() {
  const materials::Material& law = *material_;
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&](std::size_t a) {
        const Mat2 F = deformation_gradient(a);
        F00_[a] = F(0, 0), F01_[a] = F(0, 1), F10_[a] = F(1, 0), F11_[a] = F(1, 1);
        // An odd-image clamp carries no strain energy: its F (the mirrored field's, one-sided
        // at the clamp's far side) enters no force and is not guarded.
        if (imaged(a)) {
          PB00_[a] = PB01_[a] = PB10_[a] = PB11_[a] = 0.0;
          return none;
        }
        const double J = F.determinant();
        if (!(J > 0.0)) { // also NaN
          PB00_[a] = PB01_[a] = PB10_[a] = PB11_[a] = 0.0;
          return a;
        }
        const Mat2 E = 0.5 * (F.transpose() * F - Mat2::Identity()); // eq. 9
        // eq. 7, P B0 (quadratic: P itself, the correction is in g~_ab)
        const Mat2 P = F * law.stress(E);
        const Mat2 PB = quadratic_ ? P : Mat2(P * correction_matrix(a));
        PB00_[a] = PB(0, 0), PB01_[a] = PB(0, 1), PB10_[a] = PB(1, 0), PB11_[a] = PB(1, 1);
        if (!pair_k_.empty())
          hourglass_residuals(a, &pair_rx_[pair_start_[a]], &pair_ry_[pair_start_[a]]);
        return none;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    s << "tlsph: det F = " << F00_[bad] * F11_[bad] - F01_[bad] * F10_[bad] << " <= 0 at particle "
      << bad << " (X0 = " << X0_[bad] << ", " << Y0_[bad] << ") in step " << step_
      << " at t = " << time_;
    throw RunError(s.str());
  }
}

void TlsphSolid::compute_acceleration() {
  const double inv_rho0 = 1.0 / rho0_;
  const double nu_d = options_.pair_damping * 0.5 * c_s_ * h_;
  const double gamma = options_.mass_damping;
  const double gx = options_.gravity.x(), gy = options_.gravity.y();
  const bool hourglass = !pair_k_.empty();
  const std::size_t bad = parallel_reduce(
      size(), none,
      [&](std::size_t a) {
        const bool image = image_partner_[a] != none;
        if (clamped_[a] && !image) return none;
        // eq. 12 per unit mass: (1 / rho0) sum_b (P_a B0_a + P_b B0_b) grad0 W_ab V_b
        double sx = 0.0, sy = 0.0, dx = 0.0, dy = 0.0;
        if (quadratic_) {
          // f_a / (rho0 V_a) = (1 / rho0) sum_b (P_a g~_ab - (V_b / V_a) P_b g~_ba)
          const double inv_Va = 1.0 / V0_[a];
          for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
            const std::uint32_t b = pair_b_[p], r = pair_rev_[p];
            const double ga0 = pair_qx_[p], ga1 = pair_qy_[p];
            const double s_b = V0_[b] * inv_Va, gb0 = s_b * pair_qx_[r], gb1 = s_b * pair_qy_[r];
            sx += PB00_[a] * ga0 + PB01_[a] * ga1 - PB00_[b] * gb0 - PB01_[b] * gb1;
            sy += PB10_[a] * ga0 + PB11_[a] * ga1 - PB10_[b] * gb0 - PB11_[b] * gb1;
            if (hourglass) { // -dPi_hg/dx_a = sum_b (k_ab r_ab - k_ba r_ba)
              sx += (pair_k_[p] * pair_rx_[p] - pair_k_[r] * pair_rx_[r]) * inv_Va;
              sy += (pair_k_[p] * pair_ry_[p] - pair_k_[r] * pair_ry_[r]) * inv_Va;
            }
            dx += (vx_[b] - vx_[a]) * pair_dwr_[p], dy += (vy_[b] - vy_[a]) * pair_dwr_[p];
          }
        } else {
          for (std::uint32_t p = pair_start_[a]; p < pair_start_[a + 1]; ++p) {
            const std::uint32_t b = pair_b_[p];
            const double g0 = pair_gx_[p], g1 = pair_gy_[p];
            sx += (PB00_[a] + PB00_[b]) * g0 + (PB01_[a] + PB01_[b]) * g1;
            sy += (PB10_[a] + PB10_[b]) * g0 + (PB11_[a] + PB11_[b]) * g1;
            dx += (vx_[b] - vx_[a]) * pair_dwr_[p], dy += (vy_[b] - vy_[a]) * pair_dwr_[p];
          }
        }
        if (image) { // the stress force on the image (its own P is zero), for its partner
          image_ax_[a] = sx * inv_rho0, image_ay_[a] = sy * inv_rho0;
          return none;
        }
        const double inv_m = inv_rho0 / V0_[a];
        ax_[a] = sx * inv_rho0 + gx + fx_[a] * inv_m + 2.0 * nu_d * dx - gamma * vx_[a];
        ay_[a] = sy * inv_rho0 + gy + fy_[a] * inv_m + 2.0 * nu_d * dy - gamma * vy_[a];
        return std::isfinite(ax_[a]) && std::isfinite(ay_[a]) ? none : a;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad != none) {
    std::ostringstream s;
    s << "tlsph: acceleration is not finite at particle " << bad << " (X0 = " << X0_[bad] << ", "
      << Y0_[bad] << ") in step " << step_ << " at t = " << time_;
    throw RunError(s.str());
  }
  if (!images_) return;
  // f_p = -dPi/dx_p with x_g = X_g - (x_p - X_p): minus the force on the image g, per unit
  // mass of p.
  parallel_for(size(), [&](std::size_t p) {
    const std::size_t g = image_of_[p];
    if (g == none) return;
    const double r = V0_[g] / V0_[p];
    ax_[p] -= r * image_ax_[g], ay_[p] -= r * image_ay_[g];
  });
}

double TlsphSolid::stable_dt() const {
  struct Max {
    double a2, v2;
  };
  const Max m = parallel_reduce(
      size(), Max{0.0, 0.0},
      [&](std::size_t i) {
        if (clamped_[i]) return Max{0.0, vx_[i] * vx_[i] + vy_[i] * vy_[i]};
        return Max{ax_[i] * ax_[i] + ay_[i] * ay_[i], vx_[i] * vx_[i] + vy_[i] * vy_[i]};
      },
      [](Max a, Max b) {
        return Max{std::max(a.a2, b.a2), std::max(a.v2, b.v2)};
      });
  const double a = std::sqrt(m.a2), v = std::sqrt(m.v2);
  double dt = h_ / (c_s_ + v);
  if (a > 0.0) dt = std::min(dt, std::sqrt(h_ / a));
  return options_.cfl * dt_scale_ * dt;
}

void TlsphSolid::substep(double dt) {
  const std::size_t n = size();
  const double half = 0.5 * dt;
  // Velocity Verlet: first half kick and drift with a^n.
  parallel_for(n, [&](std::size_t i) {
    if (clamped_[i]) return;
    vx_[i] += half * ax_[i], vy_[i] += half * ay_[i];
    x_[i] += dt * vx_[i], y_[i] += dt * vy_[i];
  });
  double work = 0.0; // f . dx of the loaded particles, in a fixed order
  for (const std::uint32_t i : loaded_) work += dt * (fx_[i] * vx_[i] + fy_[i] * vy_[i]);
  ++step_;
  time_ += dt;
  prescribe(time_);
  compute_stress();
  compute_acceleration();
  // Second half kick with a^{n+1}.
  parallel_for(n, [&](std::size_t i) {
    if (clamped_[i]) return;
    vx_[i] += half * ax_[i], vy_[i] += half * ay_[i];
  });
  external_work_ += work;
}

int TlsphSolid::advance(double t, double dt) {
  if (!(std::abs(t - time_) <= 1e-12 * (1.0 + std::abs(t)))) {
    std::ostringstream s;
    s.precision(17);
    s << "tlsph: advance from t = " << t << " but the solid is at t = " << time_;
    throw InputError(s.str());
  }
  if (!(dt >= 0.0)) throw InputError("tlsph: advance with dt = " + std::to_string(dt) + " < 0");
  const double t_end = time_ + dt;
  int steps = 0;
  while (time_ < t_end) {
    const double remaining = t_end - time_;
    const double dts = stable_dt();
    const double k = std::ceil(remaining / dts);
    if (k <= 1.0) {
      substep(remaining);
      time_ = t_end;
    } else {
      substep(remaining / k);
    }
    ++steps;
  }
  return steps;
}

// A node moves with its particle's deformation: x = x_p + F_p (X - X_p); v and a are the
// particle's (the rotation of the dp/2 offset neglected, O(dp |grad v|)). A node on an
// odd-image clamp stays at its reference position (the images are a device of the free
// particles' stencils; the clamp itself is rigid).
std::vector<Vec2> TlsphSolid::interface_positions() const {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < interface_.size(); ++k) {
    const auto i = interface_[k];
    if (imaged(i)) {
      out.push_back(Vec2(X0_[i], Y0_[i]) + interface_offset_[k]);
      continue;
    }
    out.push_back(Vec2(x_[i], y_[i]) + deformation_gradient(i) * interface_offset_[k]);
  }
  return out;
}
std::vector<Vec2> TlsphSolid::interface_velocities() const {
  std::vector<Vec2> out;
  for (const auto i : interface_) out.push_back(imaged(i) ? Vec2::Zero() : Vec2(vx_[i], vy_[i]));
  return out;
}
std::vector<Vec2> TlsphSolid::interface_accelerations() const {
  std::vector<Vec2> out;
  for (const auto i : interface_) out.push_back(imaged(i) ? Vec2::Zero() : Vec2(ax_[i], ay_[i]));
  return out;
}

std::vector<Vec2> TlsphSolid::interface_normals() const {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < interface_.size(); ++k) {
    if (interface_n0_[k].isZero()) { // a particle node
      out.push_back(Vec2::Zero());
      continue;
    }
    const Mat2 F = imaged(interface_[k]) ? Mat2::Identity() : deformation_gradient(interface_[k]);
    out.push_back((F.inverse().transpose() * interface_n0_[k]).normalized()); // Nanson
  }
  return out;
}

void TlsphSolid::update_loaded() {
  loaded_.clear();
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i] && (fx_[i] != 0.0 || fy_[i] != 0.0))
      loaded_.push_back(static_cast<std::uint32_t>(i));
}

void TlsphSolid::set_interface_loads(const std::vector<Vec2>& forces) {
  if (forces.size() != interface_.size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " interface loads for " +
                     std::to_string(interface_.size()) + " interface nodes");
  std::fill(fx_.begin(), fx_.end(), 0.0);
  std::fill(fy_.begin(), fy_.end(), 0.0);
  for (std::size_t k = 0; k < interface_.size(); ++k) // a particle may carry several nodes
    fx_[interface_[k]] += forces[k].x(), fy_[interface_[k]] += forces[k].y();
  update_loaded();
  compute_acceleration(); // the loads act from now on (a^n of the next half kick)
}

void TlsphSolid::set_external_forces(const std::vector<Vec2>& forces) {
  if (forces.size() != size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " external forces for " +
                     std::to_string(size()) + " particles");
  for (std::size_t i = 0; i < size(); ++i) fx_[i] = forces[i].x(), fy_[i] = forces[i].y();
  update_loaded();
  compute_acceleration();
}

void TlsphSolid::set_free(const std::vector<Vec2>& values, std::vector<double>& ex,
                          std::vector<double>& ey, const char* what) {
  if (values.size() != size())
    throw InputError(std::string("tlsph: ") + what + " needs size() entries");
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i]) ex[i] = values[i].x(), ey[i] = values[i].y();
  if (images_) prescribe(time_); // the odd images follow their partners
}

void TlsphSolid::set_positions(const std::vector<Vec2>& x) {
  set_free(x, x_, y_, "set_positions");
  compute_stress();
  compute_acceleration();
}

void TlsphSolid::set_velocities(const std::vector<Vec2>& v) {
  set_free(v, vx_, vy_, "set_velocities");
  compute_acceleration();
}

std::vector<double> TlsphSolid::det_F() const {
  std::vector<double> out(size());
  parallel_for(size(), [&](std::size_t i) { out[i] = deformation_gradient(i).determinant(); });
  return out;
}

std::vector<double> TlsphSolid::von_mises() const {
  std::vector<double> out(size());
  const materials::Material& law = *material_;
  parallel_for(size(), [&](std::size_t i) {
    const Mat2 F = deformation_gradient(i);
    out[i] = materials::von_mises(law, F, 0.5 * (F.transpose() * F - Mat2::Identity()));
  });
  return out;
}

std::size_t TlsphSolid::nearest_particle(const Vec2& X) const {
  std::size_t best = 0;
  double d2 = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < size(); ++i) {
    const double d = (Vec2(X0_[i], Y0_[i]) - X).squaredNorm();
    if (d < d2) d2 = d, best = i;
  }
  return best;
}

TlsphEnergies TlsphSolid::energies() const {
  struct Sum {
    double k, s, g;
  };
  const materials::Material& law = *material_;
  const Vec2 g = options_.gravity;
  const Sum sum = parallel_reduce(
      size(), Sum{0.0, 0.0, 0.0},
      [&](std::size_t i) {
        const Mat2 F = deformation_gradient(i);
        const Mat2 E = 0.5 * (F.transpose() * F - Mat2::Identity());
        const double m = rho0_ * V0_[i];
        if (imaged(i)) return Sum{0.0, 0.0, 0.0};
        double w = V0_[i] * law.energy(E);
        if (!pair_k_.empty()) { // Pi_hg = 1/2 sum_b k_ab |r_ab|^2
          const std::uint32_t start = pair_start_[i], count = pair_start_[i + 1] - start;
          std::vector<double> rx(count), ry(count);
          hourglass_residuals(i, rx.data(), ry.data());
          for (std::uint32_t q = 0; q < count; ++q)
            w += 0.5 * pair_k_[start + q] * (rx[q] * rx[q] + ry[q] * ry[q]);
        }
        if (clamped_[i]) return Sum{0.0, w, 0.0};
        return Sum{0.5 * m * (vx_[i] * vx_[i] + vy_[i] * vy_[i]), w,
                   m * (g.x() * (x_[i] - X0_[i]) + g.y() * (y_[i] - Y0_[i]))};
      },
      [](Sum a, Sum b) {
        return Sum{a.k + b.k, a.s + b.s, a.g + b.g};
      });
  return {sum.k, sum.s, sum.g, external_work_};
}

TlsphState TlsphSolid::save() const {
  TlsphState s;
  fields_.save(s.fields);
  s.time = time_, s.step = step_, s.external_work = external_work_;
  return s;
}

void TlsphSolid::restore(const TlsphState& s) {
  fields_.restore(s.fields);
  time_ = s.time, step_ = s.step, external_work_ = s.external_work;
  update_loaded();
  compute_stress(); // F and P B0 are scratch: a later set_interface_loads() needs them current
}

void TlsphSolid::write_state(StateArchive& archive, const std::string& prefix) const {
  fields_.write_state(archive, prefix + "particles/");
  archive.put_real(prefix + "time", time_);
  archive.put_integer(prefix + "step", step_);
  archive.put_real(prefix + "external_work", external_work_);
}

void TlsphSolid::read_state(const StateArchive& archive, const std::string& prefix) {
  // Checked before reading: FieldSet::read_state resizes every array, the reference ones too.
  archive.reals(prefix + "particles/x", size());
  fields_.read_state(archive, prefix + "particles/");
  time_ = archive.real(prefix + "time");
  step_ = static_cast<long>(archive.integer(prefix + "step"));
  external_work_ = archive.real(prefix + "external_work");
  update_loaded();
  compute_stress();
}

} // namespace fsi::tlsph
