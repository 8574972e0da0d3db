#pragma once
// The oscillating cantilever plate (Gray, Monaghan & Swift 2001; Zhang et al. 2021's set-up in
// SPHinXsys): L = 0.2, H = 0.02 free, clamped over 0.06 m at x < 0, E = 2 MPa, nu = 0.3975,
// rho = 1000, plane strain; initial v_y = V_f c_s f(x) / f(L) with the first mode shape f.
#include <vector>

#include "common.hpp"

namespace tlsph_test {

inline Beam plate(int layers) {
  Beam b;
  b.L = 0.2, b.H = 0.02, b.y0 = -0.01;
  b.E = 2.0e6, b.nu = 0.3975, b.rho = 1000.0;
  b.layers = layers;
  b.clamp_length = 0.06;
  return b;
}

/// The plate's solid with the initial velocity of the first mode.
inline std::unique_ptr<TlsphSolid> plate_solid(const Beam& b, double V_f, TlsphOptions o) {
  auto s = std::make_unique<TlsphSolid>(beam_geometry(b), std::move(o));
  std::vector<Vec2> v(s->size(), Vec2::Zero());
  const double c = s->sound_speed(), fL = mode_shape(b.L, b.L);
  for (std::size_t i = 0; i < s->size(); ++i) {
    const double x = s->reference_position(i).x();
    if (x > 0.0) v[i] = Vec2(0.0, V_f * c * mode_shape(x, b.L) / fL);
  }
  s->set_velocities(v);
  return s;
}

/// Tip deflection history: mean y displacement of the tip column's one or two mid particles.
struct History {
  std::vector<double> t, w;
};

/// Times where w crosses zero (linear interpolation), skipping t = 0.
inline std::vector<double> zero_crossings(const History& h) {
  std::vector<double> out;
  for (std::size_t k = 1; k < h.w.size(); ++k)
    if (h.t[k - 1] > 0.0 && ((h.w[k - 1] < 0.0) != (h.w[k] < 0.0)))
      out.push_back(h.t[k - 1] + (h.t[k] - h.t[k - 1]) * h.w[k - 1] / (h.w[k - 1] - h.w[k]));
  return out;
}

/// Extreme |w| in each half period between zero crossings (the amplitude history).
inline std::vector<double> peaks(const History& h) {
  std::vector<double> out;
  double m = 0.0;
  for (std::size_t k = 1; k < h.w.size(); ++k) {
    if ((h.w[k - 1] < 0.0) != (h.w[k] < 0.0) && h.t[k - 1] > 0.0) out.push_back(m), m = 0.0;
    m = std::max(m, std::abs(h.w[k]));
  }
  return out;
}

} // namespace tlsph_test
