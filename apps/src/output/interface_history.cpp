#include "fsi_app/output/interface_history.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/file_lock.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <hdf5.h>
#include <sstream>

namespace fsi::app {

namespace {

constexpr std::array<const char*, 4> kRowSets = {"position", "velocity", "acceleration", "load"};

// Reads row k ([1 x n x D] or, for time, one value) of an open dataset.
herr_t read_row(hid_t set, std::size_t k, std::size_t nodes, hsize_t width, double* out) {
  const hid_t file_space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(file_space);
  const std::array<hsize_t, 3> start = {k, 0, 0};
  const std::array<hsize_t, 3> count = {1, nodes, width};
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  const hid_t mem_space = H5Screate_simple(rank, count.data(), nullptr);
  const herr_t status = H5Dread(set, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, out);
  H5Sclose(mem_space);
  H5Sclose(file_space);
  return status;
}

std::vector<hsize_t> dims_of(hid_t set) {
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  return dims;
}

std::string text(const std::vector<hsize_t>& dims) {
  std::ostringstream s;
  s << "[";
  for (std::size_t i = 0; i < dims.size(); ++i) s << (i ? " x " : "") << dims[i];
  return s.str() + "]";
}

} // namespace

template <int D>
BasicInterfaceHistory<D>::BasicInterfaceHistory(const std::filesystem::path& h5) : path_(h5) {
  const std::string where = h5.string() + ": ";
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw InputError(where + "cannot open as HDF5" + lock_note(h5, false));
  const hid_t time = H5Dopen2(file_, "time", H5P_DEFAULT);
  if (time < 0) throw InputError(where + "no dataset /time (not an interface.h5?)");
  const auto time_dims = dims_of(time);
  if (time_dims.size() != 1 || time_dims[0] < 2) {
    H5Dclose(time);
    throw InputError(where + "/time has dimensions " + text(time_dims) +
                     ", expected at least 2 rows");
  }
  time_.resize(time_dims[0]);
  const herr_t status =
      H5Dread(time, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, time_.data());
  H5Dclose(time);
  if (status < 0) throw InputError(where + "cannot read /time");
  for (std::size_t k = 0; k < time_.size(); ++k)
    if (!std::isfinite(time_[k]) || (k > 0 && !(time_[k] > time_[k - 1])))
      throw InputError(where + "/time is not finite and strictly increasing at row " +
                       std::to_string(k));
  for (const char* name : kRowSets) {
    const hid_t set = H5Dopen2(file_, name, H5P_DEFAULT);
    if (set < 0) throw InputError(where + "no dataset /" + name);
    const auto dims = dims_of(set);
    H5Dclose(set);
    if (nodes_ == 0 && dims.size() == 3) nodes_ = dims[1];
    if (dims.size() != 3 || dims[0] != time_.size() || dims[1] != nodes_ || dims[1] == 0 ||
        dims[2] != D)
      throw InputError(where + "/" + name + " has dimensions " + text(dims) + ", expected [" +
                       std::to_string(time_.size()) + " x nodes x " + std::to_string(D) + "]");
  }
}

template <int D> BasicInterfaceHistory<D>::~BasicInterfaceHistory() {
  if (file_ >= 0) H5Fclose(file_);
}

template <int D>
const typename BasicInterfaceHistory<D>::Row& BasicInterfaceHistory<D>::row(std::size_t k,
                                                                            std::size_t keep) {
  for (std::size_t i = 0; i < cache_.size(); ++i)
    if (filled_[i] && cache_[i].index == k) return cache_[i];
  const std::size_t slot = filled_[0] && cache_[0].index == keep ? 1 : 0;
  Row& r = cache_[slot];
  r.index = k;
  r.motion = coupling::BasicInterfaceMotion<D>::zeros(nodes_);
  r.loads = coupling::BasicInterfaceLoads<D>::zeros(nodes_);
  std::array<std::vector<VecD<D>>*, 4> targets = {&r.motion.x, &r.motion.v, &r.motion.a,
                                                  &r.loads.f};
  for (std::size_t j = 0; j < kRowSets.size(); ++j) {
    const hid_t set = H5Dopen2(file_, kRowSets[j], H5P_DEFAULT);
    const herr_t status = set < 0 ? -1 : read_row(set, k, nodes_, D, targets[j]->front().data());
    if (set >= 0) H5Dclose(set);
    if (status < 0)
      throw RunError(path_.string() + ": cannot read row " + std::to_string(k) + " of /" +
                     kRowSets[j]);
  }
  filled_[slot] = true;
  return r;
}

template <int D>
void BasicInterfaceHistory<D>::bracket(double t, const Row*& a, const Row*& b, double& s) {
  // A step end may differ from the recorded time by rounding (t = n dt + dt vs (n + 1) dt).
  const double slack = 1e-12 * std::max(1.0, std::abs(time_.back()));
  if (!(t >= time_.front() - slack && t <= time_.back() + slack)) {
    std::ostringstream e;
    e << path_.string() << ": t = " << t << " s is outside the recorded " << time_.front() << " .. "
      << time_.back() << " s";
    throw RunError(e.str());
  }
  t = std::clamp(t, time_.front(), time_.back());
  const auto it = std::upper_bound(time_.begin(), time_.end(), t);
  const auto k = static_cast<std::size_t>(it - time_.begin()) - 1; // time_[k] <= t
  a = &row(k, k + 1);
  if (time_[k] == t) { // a recorded time: the row itself, bit for bit
    b = a;
    s = 0.0;
    return;
  }
  b = &row(k + 1, k);
  s = (t - time_[k]) / (time_[k + 1] - time_[k]);
}

template <int D> coupling::BasicInterfaceMotion<D> BasicInterfaceHistory<D>::motion_at(double t) {
  const Row *a = nullptr, *b = nullptr;
  double s = 0.0;
  bracket(t, a, b, s);
  return a == b ? a->motion : coupling::interpolate(a->motion, b->motion, s);
}

template <int D> coupling::BasicInterfaceLoads<D> BasicInterfaceHistory<D>::loads_at(double t) {
  const Row *a = nullptr, *b = nullptr;
  double s = 0.0;
  bracket(t, a, b, s);
  if (a == b) return a->loads;
  coupling::BasicInterfaceLoads<D> out = a->loads;
  for (std::size_t i = 0; i < out.size(); ++i)
    out.f[i] = (1.0 - s) * a->loads.f[i] + s * b->loads.f[i];
  return out;
}

template class BasicInterfaceHistory<2>;
template class BasicInterfaceHistory<3>;

} // namespace fsi::app
