#include "geometry_erp/aabb_locator.hpp"

#include "nearest_segment.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

namespace fsi::erp {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;

/// One wall segment as an AABB primitive (lifted to z = 0), with its geometry at update().
struct SegmentPrimitive {
  using Id = int;
  using Point = Kernel::Point_3;
  using Datum = Kernel::Segment_3;
  SegmentPrimitive() = default;
  template <class Iterator> explicit SegmentPrimitive(Iterator it) : geometry(*it) {}
  Id id() const { return geometry.id; }
  Datum datum() const { return {reference_point(), Point(geometry.b.x(), geometry.b.y(), 0.0)}; }
  Point reference_point() const { return {geometry.a.x(), geometry.a.y(), 0.0}; }
  SegmentGeometry geometry;
};

using Traits = CGAL::AABB_traits<Kernel, SegmentPrimitive>;
using Node = CGAL::AABB_node<Traits>;

/// Traversal that visits only boxes within the current bound (ties included, so the lower-index
/// rule of the consider functions sees every equally near segment).
template <class Consider> struct NearestWithin {
  Vec2 p;
  const double& bound;
  Consider& consider;
  bool go_further() const { return true; }
  template <class Query> void intersection(const Query&, const SegmentPrimitive& primitive) {
    consider(primitive.geometry);
  }
  template <class Query> bool do_intersect(const Query&, const Node& node) const {
    const CGAL::Bbox_3& box = node.bbox();
    const double dx = std::max({box.xmin() - p.x(), 0.0, p.x() - box.xmax()});
    const double dy = std::max({box.ymin() - p.y(), 0.0, p.y() - box.ymax()});
    return dx * dx + dy * dy <= bound;
  }
};

} // namespace

struct AabbLocator::Tree {
  std::vector<SegmentGeometry> sources;
  CGAL::AABB_tree<Traits> tree;
};

AabbLocator::AabbLocator(const WallSet& walls, double r_e)
    : WallLocator(walls, r_e), tree_(std::make_unique<Tree>()) {
  tree_->tree.do_not_accelerate_distance_queries();
  update();
}

AabbLocator::~AabbLocator() = default;

void AabbLocator::update() {
  const WallSet& walls = *walls_;
  tree_->sources.resize(walls.segments().size());
  for (std::size_t s = 0; s < tree_->sources.size(); ++s)
    tree_->sources[s] = detail::segment_geometry(walls, static_cast<int>(s));
  tree_->tree.rebuild(tree_->sources.begin(), tree_->sources.end());
}

void AabbLocator::locate(const QueryPoints& points, WallHits& hits) const {
  const WallSet& walls = *walls_;
  const auto& tree = tree_->tree;
  detail::batch_query(
      walls, r_e_, corner_faces_, points.size(), points,
      [&](const Vec2& p, const double& bound, auto&& consider) {
        NearestWithin<std::remove_reference_t<decltype(consider)>> traits{p, bound, consider};
        tree.traversal(0, traits);
      },
      hits);
}

} // namespace fsi::erp
