#pragma once
// A serial particles::Decomposition that makes a fluid periodic along one axis over [lo, lo + L)
// (the 3-D EMPS fluid's periodic_z): its ghosts are the images x +- L e_axis of the owned
// particles within `reach` of the two faces, appended after them, so the pair loops, which read
// ghosts and write owned particles, see the period without a change; migrate() wraps the owned
// positions back into [lo, lo + L) before each neighbour-list build. One process: the reductions
// are LocalParticles'.
#include "particles/decomposition.hpp"

#include <cstdint>
#include <vector>

namespace fsi::particles {

template <int D> class PeriodicImages final : public LocalParticles<D> {
public:
  /// Periodic along `axis` over [lo, lo + period); `x` is the set's position field (its
  /// component along the axis receives the images' shifts). Needs period > 0.
  PeriodicImages(int axis, double lo, double period, const VectorField<D>& x);

  /// Removes the images and wraps every owned position into [lo, lo + L) (a particle has moved
  /// less than L since the last build); the order does not change (returns false). One
  /// process: `work` balances nothing.
  bool migrate(FieldSet& fields, const VectorField<D>& x, const std::vector<double>*) override;
  /// The images of the owned particles whose coordinate along the axis lies within `reach` of a
  /// face: x + L e_axis of those near lo, x - L e_axis of those near lo + L.
  void build_ghosts(FieldSet& fields, const VectorField<D>& x, double reach) override {
    build_images(fields, x[axis_].data(), reach);
  }
  /// The same, the owned particles chosen by their coordinates `along` the axis (a checkpoint's
  /// neighbour-list build positions), the images copied from the set's current values.
  void build_images(FieldSet& fields, const double* along, double reach);
  /// Copies the owned values of the arrays `changed` names onto their images, the position along
  /// the axis shifted by the image's +-L.
  void update_ghosts(FieldSet& fields, const FieldList& changed) override;
  void drop_ghosts(FieldSet& fields) override;
  std::size_t ghosts() const override { return source_.size(); }
  /// Image k's owned particle and its shift along the axis (+-L).
  std::uint32_t source(std::size_t k) const { return source_[k]; }
  double shift(std::size_t k) const { return shift_[k]; }

private:
  int axis_;
  double lo_, period_;
  const std::vector<double>* along_; ///< the set's position component along the axis
  std::vector<std::uint32_t> source_;
  std::vector<double> shift_;
};

} // namespace fsi::particles
