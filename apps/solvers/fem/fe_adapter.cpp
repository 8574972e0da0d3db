#include "fem/fe_adapter.hpp"

namespace fsi::app::fem_plugin {

template <class Family>
BasicFeAdapter<Family>::BasicFeAdapter(fem::BasicStructure<Family>& structure,
                                       const fem::BasicFeInterface<dim>& interface)
    : structure_(structure), interface_(interface),
      forces_(fem::Vector::Zero(dim * static_cast<Eigen::Index>(structure.num_nodes()))) {}

template <class Family>
void BasicFeAdapter<Family>::set_interface_loads(const coupling::BasicInterfaceLoads<dim>& loads) {
  forces_.setZero();
  for (std::size_t k = 0; k < loads.size(); ++k) // eq. 59
    forces_.template segment<dim>(dim * interface_.fe_node[k]) = loads.f[k];
  structure_.set_external_forces(forces_);
}

template <class Family> void BasicFeAdapter<Family>::advance(double /*t*/, double dt) {
  structure_.advance(dt);
}

template <class Family>
auto BasicFeAdapter<Family>::interface_motion() const -> coupling::BasicInterfaceMotion<dim> {
  const std::size_t n = interface_.fe_node.size();
  auto m = coupling::BasicInterfaceMotion<dim>::zeros(n);
  const auto& X = structure_.mesh().X;
  const auto &u = structure_.displacement(), &v = structure_.velocity(),
             &a = structure_.acceleration();
  for (std::size_t k = 0; k < n; ++k) { // eqs. 60-62
    const int K = interface_.fe_node[k];
    m.x[k] = X[static_cast<std::size_t>(K)] + u.template segment<dim>(dim * K);
    m.v[k] = v.template segment<dim>(dim * K);
    m.a[k] = a.template segment<dim>(dim * K);
  }
  return m;
}

template <class Family> void BasicFeAdapter<Family>::save_state() {
  saved_ = structure_.save();
}

template <class Family> void BasicFeAdapter<Family>::restore_state() {
  structure_.restore(*saved_);
}

template class BasicFeAdapter<fem::T6>;
template class BasicFeAdapter<fem::T10>;

} // namespace fsi::app::fem_plugin
