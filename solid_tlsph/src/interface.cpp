// The solid's coupling interface: nodes on the tagged outline attached to surface particles,
// order-1 edges between them, and their positions, velocities, accelerations and normals as
// the solid deforms. The 2-D outline here; the 3-D box's faces in interface_box.cpp.
#include <Eigen/LU>
#include <algorithm>
#include <limits>

#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

namespace {

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b, double* xi) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  if (xi) *xi = t;
  return (p - (a + t * ab)).norm();
}

} // namespace

template <int D>
void BasicTlsphSolid<D>::build_outline_interface(const Geometry& geometry) requires(D == 2) {
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
    const Vec2 X = at(X0_, i);
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
    interface_offset_.push_back(node.X - at(X0_, node.i));
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
  add_particle_nodes();
}

template <int D> void BasicTlsphSolid<D>::add_particle_nodes() {
  interface_mesh_.particle_volume.clear();
  if (!options_.interface_particles) return;
  for (std::size_t i = 0; i < size(); ++i) { // the particles themselves, on no element
    interface_.push_back(static_cast<std::uint32_t>(i));
    interface_n0_.push_back(Vec::Zero());
    interface_offset_.push_back(Vec::Zero());
    interface_mesh_.X0.push_back(at(X0_, i));
    interface_mesh_.particle_volume.push_back(V0_[i]);
  }
}

template <int D> BasicInterfaceMesh<D> BasicTlsphSolid<D>::interface_mesh() const {
  return interface_mesh_;
}

// A node moves with its particle's deformation: x = x_p + F_p (X - X_p); v and a are the
// particle's (the rotation of the dp/2 offset neglected, O(dp |grad v|)). A node on an
// odd-image clamp stays at its reference position (the images are a device of the free
// particles' stencils; the clamp itself is rigid).
template <int D> std::vector<VecD<D>> BasicTlsphSolid<D>::interface_positions() const {
  std::vector<Vec> out;
  for (std::size_t k = 0; k < interface_.size(); ++k) {
    const auto i = interface_[k];
    if (imaged(i)) {
      out.push_back(at(X0_, i) + interface_offset_[k]);
      continue;
    }
    out.push_back(at(x_, i) + deformation_gradient(i) * interface_offset_[k]);
  }
  return out;
}
template <int D> std::vector<VecD<D>> BasicTlsphSolid<D>::interface_velocities() const {
  std::vector<Vec> out;
  for (const auto i : interface_) out.push_back(imaged(i) ? Vec::Zero() : at(v_, i));
  return out;
}
template <int D> std::vector<VecD<D>> BasicTlsphSolid<D>::interface_accelerations() const {
  std::vector<Vec> out;
  for (const auto i : interface_) out.push_back(imaged(i) ? Vec::Zero() : at(a_, i));
  return out;
}

template <int D> std::vector<VecD<D>> BasicTlsphSolid<D>::interface_normals() const {
  std::vector<Vec> out;
  for (std::size_t k = 0; k < interface_.size(); ++k) {
    if (interface_n0_[k].isZero()) { // a particle node
      out.push_back(Vec::Zero());
      continue;
    }
    const Mat F = imaged(interface_[k]) ? Mat::Identity() : deformation_gradient(interface_[k]);
    out.push_back((F.inverse().transpose() * interface_n0_[k]).normalized()); // Nanson
  }
  return out;
}

template void BasicTlsphSolid<2>::build_outline_interface(const Geometry&);
template void BasicTlsphSolid<2>::add_particle_nodes();
template BasicInterfaceMesh<2> BasicTlsphSolid<2>::interface_mesh() const;
template std::vector<Vec2> BasicTlsphSolid<2>::interface_positions() const;
template std::vector<Vec2> BasicTlsphSolid<2>::interface_velocities() const;
template std::vector<Vec2> BasicTlsphSolid<2>::interface_accelerations() const;
template std::vector<Vec2> BasicTlsphSolid<2>::interface_normals() const;
template void BasicTlsphSolid<3>::add_particle_nodes();
template BasicInterfaceMesh<3> BasicTlsphSolid<3>::interface_mesh() const;
template std::vector<Vec3> BasicTlsphSolid<3>::interface_positions() const;
template std::vector<Vec3> BasicTlsphSolid<3>::interface_velocities() const;
template std::vector<Vec3> BasicTlsphSolid<3>::interface_accelerations() const;
template std::vector<Vec3> BasicTlsphSolid<3>::interface_normals() const;

} // namespace fsi::tlsph
