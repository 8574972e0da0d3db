#include "geometry_erp/triangle_wall_set.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace fsi::erp {

namespace {

std::string triangle_name(int group, std::size_t k) {
  return "triangle wall group " + std::to_string(group) + ", triangle " + std::to_string(k);
}

/// Unit normal of an edge or vertex from its summed normals; zero where the sum vanishes.
Vec3 unit_or_zero(const Vec3& sum) {
  const double norm = sum.norm();
  return norm < 1e-12 ? Vec3::Zero() : Vec3(sum / norm);
}

} // namespace

TriangleRange TriangleWallSet::add_triangles(std::span<const Vec3> points,
                                             std::span<const std::array<int, 3>> triangles,
                                             int group) {
  const auto n = static_cast<int>(points.size());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const auto& [a, b, c] = triangles[k];
    if (std::min({a, b, c}) < 0 || std::max({a, b, c}) >= n)
      throw InputError(triangle_name(group, k) + ": node index outside 0.." +
                       std::to_string(n - 1));
    if (a == b || b == c || c == a)
      throw InputError(triangle_name(group, k) + ": repeated node index");
    const Vec3 &xa = points[static_cast<std::size_t>(a)], &xb = points[static_cast<std::size_t>(b)],
               &xc = points[static_cast<std::size_t>(c)];
    const double longest2 =
        std::max({(xb - xa).squaredNorm(), (xc - xb).squaredNorm(), (xa - xc).squaredNorm()});
    if (!((xb - xa).cross(xc - xa).norm() > 1e-12 * longest2))
      throw InputError(triangle_name(group, k) + ": degenerate (zero area)");
  }
  TriangleRange range{static_cast<int>(nodes_.size()), n, static_cast<int>(triangles_.size()),
                      static_cast<int>(triangles.size())};
  for (const Vec3& p : points) {
    nodes_.x.push_back(p);
    nodes_.v.push_back(Vec3::Zero());
    nodes_.a.push_back(Vec3::Zero());
  }
  for (const auto& [a, b, c] : triangles) {
    triangles_.node.push_back({a + range.first_node, b + range.first_node, c + range.first_node});
    triangles_.group.push_back(group);
  }
  build_edges();
  update();
  return range;
}

void TriangleWallSet::build_edges() {
  // Edges as sorted node pairs; (t, k) with equal pairs share an edge id.
  std::vector<std::tuple<int, int, int>> pairs; // (lower node, upper node, 3 t + k)
  pairs.reserve(3 * triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int p = triangles_.node[t][static_cast<std::size_t>(k)];
      const int q = triangles_.node[t][static_cast<std::size_t>((k + 1) % 3)];
      pairs.emplace_back(std::min(p, q), std::max(p, q), static_cast<int>(3 * t) + k);
    }
  std::sort(pairs.begin(), pairs.end());
  edge_of_.assign(pairs.size(), -1);
  edge_count_.clear();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const bool same = i > 0 && std::get<0>(pairs[i]) == std::get<0>(pairs[i - 1]) &&
                      std::get<1>(pairs[i]) == std::get<1>(pairs[i - 1]);
    if (!same) edge_count_.push_back(0);
    ++edge_count_.back();
    edge_of_[static_cast<std::size_t>(std::get<2>(pairs[i]))] =
        static_cast<int>(edge_count_.size()) - 1;
  }
  open_node_.assign(nodes_.size(), 0);
  for (const auto& [p, q, tk] : pairs)
    if (edge_count_[static_cast<std::size_t>(edge_of_[static_cast<std::size_t>(tk)])] == 1)
      open_node_[static_cast<std::size_t>(p)] = open_node_[static_cast<std::size_t>(q)] = 1;
}

void TriangleWallSet::update() {
  const auto& x = nodes_.x;
  face_normal_.resize(triangles_.size());
  edge_normal_.assign(edge_count_.size(), Vec3::Zero());
  node_normal_.assign(nodes_.size(), Vec3::Zero());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& abc = triangles_.node[t];
    const Vec3 n =
        (x[static_cast<std::size_t>(abc[1])] - x[static_cast<std::size_t>(abc[0])])
            .cross(x[static_cast<std::size_t>(abc[2])] - x[static_cast<std::size_t>(abc[0])])
            .normalized();
    face_normal_[t] = n;
    for (std::size_t k = 0; k < 3; ++k) {
      edge_normal_[static_cast<std::size_t>(edge_of_[3 * t + k])] += n;
      // Angle of the triangle at vertex k, atan2(|u x v|, u . v) (accurate at any angle).
      const Vec3& xk = x[static_cast<std::size_t>(abc[k])];
      const Vec3 u = x[static_cast<std::size_t>(abc[(k + 1) % 3])] - xk;
      const Vec3 v = x[static_cast<std::size_t>(abc[(k + 2) % 3])] - xk;
      node_normal_[static_cast<std::size_t>(abc[k])] += std::atan2(u.cross(v).norm(), u.dot(v)) * n;
    }
  }
  for (Vec3& n : edge_normal_) n = unit_or_zero(n);
  for (Vec3& n : node_normal_) n = unit_or_zero(n);
}

Vec3 TriangleWallSet::pseudo_normal(int t, TriangleFeature feature) const {
  const auto f = static_cast<int>(feature);
  const auto ut = static_cast<std::size_t>(t);
  Vec3 n = face_normal_[ut];
  if (f < 3)
    n = node_normal_[static_cast<std::size_t>(triangles_.node[ut][static_cast<std::size_t>(f)])];
  else if (f < 6)
    n = edge_normal_[static_cast<std::size_t>(edge_of_[3 * ut + static_cast<std::size_t>(f - 3)])];
  return n.squaredNorm() > 0.0 ? n : face_normal_[ut];
}

bool TriangleWallSet::open(int t, TriangleFeature feature) const {
  const auto f = static_cast<int>(feature);
  const auto ut = static_cast<std::size_t>(t);
  if (f < 3)
    return open_node_[static_cast<std::size_t>(triangles_.node[ut][static_cast<std::size_t>(f)])];
  if (f < 6)
    return edge_count_[static_cast<std::size_t>(
               edge_of_[3 * ut + static_cast<std::size_t>(f - 3)])] == 1;
  return false;
}

} // namespace fsi::erp
