#include "fluid_sph/interface_boundary3.hpp"

#include "fsi/core/closest_on_triangle.hpp"
#include "fsi/core/error.hpp"
#include "particles/box_grid.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>

namespace fsi::sph {

namespace {

/// Face f's corner-triangle frame at node positions x: t1 along corner 0 -> 1, n out of the solid
/// (into the fluid), t2 = n x t1.
struct Frame {
  Vec3 t1, t2, n;
};
Frame frame(const InterfaceMesh3& mesh, const std::vector<Vec3>& x, std::size_t f) {
  const auto& k = mesh.faces[f];
  const Vec3 t1 = (x[k[1]] - x[k[0]]).normalized();
  const Vec3 n = (x[k[1]] - x[k[0]]).cross(x[k[2]] - x[k[0]]).normalized();
  return {t1, n.cross(t1), n};
}

/// What decides a scan over the faces in order for the nearest one, whose ties (faces as near to
/// within `tie`) depend on the order: a scan over a subset S of the faces, in order, ends as the
/// scan over all of them when S holds every face within t of q, at least one, and no face lies at
/// a distance in (t, t + gap], gap > 2 tie. Then the first face within t restarts the scan (it is
/// nearer by more than a tie than any farther face seen before), and no face farther than t + gap
/// changes it afterwards: both scans see the same faces from there on. `see` is told every
/// distance the scan computes.
struct Reach {
  double t, gap;
  bool near = false, band = false;
  void see(double d) {
    near = near || d <= t;
    band = band || (d > t && d <= t + gap);
  }
};

/// The nearest of signed_distance's flat triangles to q so far: the scan over the faces in order.
struct Surface {
  double best = std::numeric_limits<double>::max();
  Vec3 foot = Vec3::Zero(), normal = Vec3::Zero();
  void triangle(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, Reach& reach) {
    const Vec3 f = triangle_point(closest_on_triangle(q, a, b, c), a, b, c);
    const Vec3 n = (b - a).cross(c - a).normalized();
    const double d = (q - f).norm(), tie = 1e-12 * (d + (b - a).norm());
    reach.see(d);
    if (d < best - tie)
      best = d, foot = f, normal = n;
    else if (d <= best + tie && (f - foot).norm() <= tie) // the same edge or vertex, another face
      normal += n;
  }
  void face(const InterfaceMesh3& mesh, const std::vector<Vec3>& x, std::size_t f, const Vec3& q,
            Reach& reach) {
    const auto& k = mesh.faces[f];
    if (mesh.order == 1) {
      triangle(q, x[k[0]], x[k[1]], x[k[2]], reach);
    } else { // the four sub-triangles through the mid-side nodes 3 (0-1), 4 (1-2), 5 (2-0)
      triangle(q, x[k[0]], x[k[3]], x[k[5]], reach);
      triangle(q, x[k[3]], x[k[1]], x[k[4]], reach);
      triangle(q, x[k[5]], x[k[4]], x[k[2]], reach);
      triangle(q, x[k[3]], x[k[4]], x[k[5]], reach);
    }
  }
  double value(const Vec3& q) const { return (q - foot).dot(normal) >= 0.0 ? best : -best; }
};

} // namespace

template <class Scan>
void InterfaceBoundary3::scan_near(const Vec3& q, double floor, Scan&& scan) const {
  assert(q.allFinite());
  std::vector<int> faces;
  for (double r = 1.001 * reach_ + 1e-5 * size_;; r *= 2.0) {
    grid_.overlapping(q - Vec3::Constant(r), q + Vec3::Constant(r), faces);
    const double gap = 1e-6 * (r + size_);
    Reach reach{r - 2.0 * gap, gap};
    scan(std::span<const int>(faces), reach);
    if (faces.size() == mesh_.faces.size() || (reach.near ? !reach.band : reach.t >= floor)) return;
  }
}

InterfaceBoundary3::InterfaceBoundary3(const InterfaceMesh3& mesh, double dp, int layers,
                                       double spacing)
    : mesh_(mesh) {
  if (mesh.faces.empty()) throw InputError("fluid_sph: the interface mesh has no face");
  if (layers < 1) throw InputError("fluid_sph: interface layers " + std::to_string(layers));
  if (!(spacing >= 0.0 && spacing <= dp))
    throw InputError("fluid_sph: interface spacing " + std::to_string(spacing) +
                     " outside (0, dp]");
  const double s = spacing > 0.0 ? spacing : dp, depth = layers * dp, tie = 1e-9 * dp;
  if (!std::all_of(mesh.X0.begin(), mesh.X0.end(), [](const Vec3& x) { return x.allFinite(); }))
    throw InputError("fluid_sph: an interface node is not finite");
  // The faces' boxes (every node) at X0 in cells of side depth.
  std::vector<particles::Box3d> boxes;
  for (const auto& k : mesh.faces) {
    particles::Box3d b{mesh.X0[k[0]], mesh.X0[k[0]]};
    for (std::size_t j = 1; j < (mesh.order == 1 ? 3u : 6u); ++j)
      b.lo = b.lo.cwiseMin(mesh.X0[k[j]]), b.hi = b.hi.cwiseMax(mesh.X0[k[j]]);
    size_ = std::max(size_, (b.hi - b.lo).norm());
    boxes.push_back(b);
  }
  reach_ = depth;
  grid_.build(boxes, depth);
  // Open edges (of one face only) and the vertices on them: a point whose nearest feature is one
  // lies beyond the interface's rim.
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (const auto& k : mesh.faces)
    for (std::size_t j = 0; j < 3; ++j) ++uses[std::minmax(k[j], k[(j + 1) % 3])];
  std::vector<std::uint8_t> rim(mesh.node_count(), 0);
  for (const auto& [edge, count] : uses)
    if (count == 1) rim[edge.first] = rim[edge.second] = 1;
  auto open = [&](std::size_t f, TriangleFeature feature) {
    const auto& k = mesh.faces[f];
    auto edge = [&](std::size_t a, std::size_t b) { return uses.at(std::minmax(k[a], k[b])) == 1; };
    switch (feature) {
    case TriangleFeature::vertex_a:
      return rim[k[0]] != 0;
    case TriangleFeature::vertex_b:
      return rim[k[1]] != 0;
    case TriangleFeature::vertex_c:
      return rim[k[2]] != 0;
    case TriangleFeature::edge_ab:
      return edge(0, 1);
    case TriangleFeature::edge_bc:
      return edge(1, 2);
    case TriangleFeature::edge_ca:
      return edge(2, 0);
    default:
      return false;
    }
  };
  Vec3 lo = mesh.X0[mesh.faces[0][0]], hi = lo;
  for (const auto& k : mesh.faces)
    for (std::size_t j = 0; j < 3; ++j)
      lo = lo.cwiseMin(mesh.X0[k[j]]), hi = hi.cwiseMax(mesh.X0[k[j]]);
  auto keep = [&](const Vec3& q, std::size_t node, double volume) {
    double best = 0.0;
    std::array<std::size_t, 3> faces{};
    TrianglePoint nearest{0.0, 0.0, TriangleFeature::face};
    Vec3 normal, foot;
    // The faces in order as a scan over all would see them (scan_near), the nearest first.
    scan_near(q, depth, [&](std::span<const int> near, Reach& reach) {
      best = std::numeric_limits<double>::max(), faces = {kNone, kNone, kNone};
      nearest = {0.0, 0.0, TriangleFeature::face}, normal = foot = Vec3::Zero();
      for (const int i : near) {
        const auto f = static_cast<std::size_t>(i);
        const auto& k = mesh.faces[f];
        const Vec3 &a = mesh.X0[k[0]], &b = mesh.X0[k[1]], &c = mesh.X0[k[2]];
        const TrianglePoint t = closest_on_triangle(q, a, b, c);
        const Vec3 p = triangle_point(t, a, b, c); // on the corner triangle
        const double d = (q - p).norm();
        reach.see(d);
        const Vec3 n = frame(mesh, mesh.X0, f).n;
        if (d < best - tie) {
          best = d, nearest = t, foot = p, normal = n, faces = {f, kNone, kNone};
        } else if (d <= best + tie && (p - foot).norm() <= tie) {
          normal += n; // an edge or vertex shared with the nearest face: the mean normal
          // Another normal (a bisector): one of at most two more faces the point's normal averages.
          const Vec3 n0 = frame(mesh, mesh.X0, faces[0]).n;
          const bool other = (n - n0).norm() > 1e-9;
          if (other && faces[1] == kNone)
            faces[1] = f;
          else if (other && faces[2] == kNone &&
                   (n - frame(mesh, mesh.X0, faces[1]).n).norm() > 1e-9)
            faces[2] = f;
        }
      }
    });
    if (best >= depth || (q - foot).dot(normal) >= 0.0 || open(faces[0], nearest.feature)) return;
    // Anchored at x(xi, eta) of the face, offset in its frame.
    const Frame fr = frame(mesh, mesh.X0, faces[0]);
    const Vec3 r = q - face_point(mesh, mesh.X0, faces[0], nearest.v, nearest.w);
    face_.push_back(faces);
    node_.push_back(node);
    parent_.push_back({nearest.v, nearest.w});
    offset_.emplace_back(r.dot(fr.t1), r.dot(fr.t2), -r.dot(fr.n));
    volume_.push_back(volume);
  };
  if (!mesh.particle_volume.empty()) { // the solid's own particles
    for (std::size_t k = mesh.first_particle(); k < mesh.node_count(); ++k)
      keep(mesh.X0[k], k, mesh.particle_volume[k - mesh.first_particle()]);
  } else { // lattice points at (i + 1/2) s from the first face's corner 0
    const Vec3 origin = mesh.X0[mesh.faces[0][0]];
    std::array<int, 3> i0{}, i1{};
    for (int c = 0; c < 3; ++c) {
      const auto uc = static_cast<std::size_t>(c);
      i0[uc] = static_cast<int>(std::floor((lo[c] - depth - origin[c]) / s)) - 1;
      i1[uc] = static_cast<int>(std::ceil((hi[c] + depth - origin[c]) / s)) + 1;
    }
    for (int k = i0[2]; k <= i1[2]; ++k)
      for (int j = i0[1]; j <= i1[1]; ++j)
        for (int i = i0[0]; i <= i1[0]; ++i)
          keep(origin + s * Vec3(i + 0.5, j + 0.5, k + 0.5), kNone, s * s * s);
  }
  if (face_.empty()) throw InputError("fluid_sph: no boundary point fits behind the interface");
}

std::vector<WallPoint3> InterfaceBoundary3::wall_points(int group) const {
  std::vector<Vec3> x, n;
  place(mesh_.X0, x, n);
  std::vector<WallPoint3> out(size());
  for (std::size_t p = 0; p < size(); ++p) {
    // Depth along the point's normal to its face's plane: offset depth / cos(the angle between).
    const Vec3 n0 = frame(mesh_, mesh_.X0, face_[p][0]).n;
    const double d = offset_[p].z() / n[p].dot(n0);
    // A convex edge: the anchor is behind the other face's plane (at a concave one both are the
    // edge).
    double corner = 0.0;
    if (face_[p][1] != kNone) {
      const Vec3 n1 = frame(mesh_, mesh_.X0, face_[p][1]).n;
      const Vec3 anchor = face_point(mesh_, mesh_.X0, face_[p][0], parent_[p][0], parent_[p][1]);
      if ((anchor - mesh_.X0[mesh_.faces[face_[p][1]][0]]).dot(n1) < -1e-9 * offset_[p].z())
        corner = 0.5 * (n0 - n1).norm();
    }
    out[p] = {x[p], n[p], group, d, corner, volume_[p]};
  }
  return out;
}

void InterfaceBoundary3::place(const std::vector<Vec3>& x, std::vector<Vec3>& position,
                               std::vector<Vec3>& normal) const {
  position.resize(size());
  normal.resize(size());
  for (std::size_t p = 0; p < size(); ++p) {
    const Frame fr = frame(mesh_, x, face_[p][0]);
    Vec3 n = fr.n;
    for (std::size_t j = 1; j < 3 && face_[p][j] != kNone; ++j) n += frame(mesh_, x, face_[p][j]).n;
    normal[p] = n.normalized();
    const Vec3& a = offset_[p];
    position[p] = node_[p] != kNone
                      ? x[node_[p]]
                      : Vec3(face_point(mesh_, x, face_[p][0], parent_[p][0], parent_[p][1]) +
                             a.x() * fr.t1 + a.y() * fr.t2 - a.z() * fr.n);
  }
}

double InterfaceBoundary3::signed_distance(const std::vector<Vec3>& x, const Vec3& q) const {
  Surface surface;
  Reach unused{0.0, 0.0};
  for (std::size_t f = 0; f < mesh_.faces.size(); ++f) surface.face(mesh_, x, f, q, unused);
  return surface.value(q);
}

double InterfaceBoundary3::signed_distance(const Vec3& q) const {
  Surface surface;
  scan_near(q, std::numeric_limits<double>::infinity(),
            [&](std::span<const int> near, Reach& reach) {
              surface = Surface{};
              for (const int f : near)
                surface.face(mesh_, mesh_.X0, static_cast<std::size_t>(f), q, reach);
            });
  return surface.value(q);
}

void InterfaceBoundary3::interpolate(const std::vector<Vec3>& nodal,
                                     std::vector<Vec3>& at_points) const {
  at_points.resize(size());
  for (std::size_t p = 0; p < size(); ++p)
    at_points[p] = node_[p] != kNone
                       ? nodal[node_[p]]
                       : face_point(mesh_, nodal, face_[p][0], parent_[p][0], parent_[p][1]);
}

void InterfaceBoundary3::distribute(const std::vector<Vec3>& point_force,
                                    std::vector<Vec3>& nodal) const {
  nodal.assign(mesh_.node_count(), Vec3::Zero());
  for (std::size_t p = 0; p < size(); ++p) {
    if (node_[p] != kNone) {
      nodal[node_[p]] += point_force[p];
      continue;
    }
    const auto N = face_shape_functions(mesh_.order, parent_[p][0], parent_[p][1]);
    const auto& k = mesh_.faces[face_[p][0]];
    for (std::size_t j = 0; j < 6; ++j) nodal[k[j]] += N[j] * point_force[p];
  }
}

} // namespace fsi::sph
