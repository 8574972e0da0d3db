#include "particles/periodic_images.hpp"

#include <type_traits>

namespace fsi::particles {

template <int D>
PeriodicImages<D>::PeriodicImages(int axis, double lo, double period, const VectorField<D>& x)
    : axis_(axis), lo_(lo), period_(period), along_(&x[axis]) {}

template <int D>
bool PeriodicImages<D>::migrate(FieldSet& fields, const VectorField<D>& x,
                                const std::vector<double>*) {
  drop_ghosts(fields);
  std::vector<double>& z = x[axis_];
  const double hi = lo_ + period_;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (z[i] < lo_)
      z[i] += period_;
    else if (z[i] >= hi)
      z[i] -= period_;
  }
  return false;
}

template <int D>
void PeriodicImages<D>::build_images(FieldSet& fields, const double* along, double reach) {
  const std::size_t n = fields.size(); // no images on entry
  source_.clear();
  shift_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (along[i] - lo_ < reach)
      source_.push_back(static_cast<std::uint32_t>(i)), shift_.push_back(period_);
    if (lo_ + period_ - along[i] < reach)
      source_.push_back(static_cast<std::uint32_t>(i)), shift_.push_back(-period_);
  }
  fields.resize(n + source_.size());
  update_ghosts(fields, {});
}

template <int D> void PeriodicImages<D>::update_ghosts(FieldSet& fields, const FieldList& changed) {
  const std::size_t n = fields.size() - source_.size();
  fields.for_each_array(changed, [&](auto& values) {
    for (std::size_t k = 0; k < source_.size(); ++k) values[n + k] = values[source_[k]];
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(values)>, std::vector<double>>)
      if (&values == along_)
        for (std::size_t k = 0; k < source_.size(); ++k) values[n + k] += shift_[k];
  });
}

template <int D> void PeriodicImages<D>::drop_ghosts(FieldSet& fields) {
  fields.resize(fields.size() - source_.size());
  source_.clear();
  shift_.clear();
}

template class PeriodicImages<2>;
template class PeriodicImages<3>;

} // namespace fsi::particles
