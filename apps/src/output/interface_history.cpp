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

static_assert(sizeof(Vec2) == 2 * sizeof(double), "Vec2 rows are stored as two doubles");
constexpr std::array<const char*, 4> kRowSets = {"position", "velocity", "acceleration", "load"};

[[noreturn]] void write_fail(const std::filesystem::path& file, const std::string& what) {
  throw RunError("output: " + file.string() + ": " + what);
}

hid_t create_rows(hid_t file, const char* name, std::size_t nodes,
                  const std::filesystem::path& path) {
  const int rank = nodes == 0 ? 1 : 3;
  const std::array<hsize_t, 3> dims = {0, nodes, 2};
  const std::array<hsize_t, 3> max = {H5S_UNLIMITED, nodes, 2};
  const std::array<hsize_t, 3> chunk = {64, std::max<hsize_t>(nodes, 1), 2};
  const hid_t space = H5Screate_simple(rank, dims.data(), max.data());
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, rank, chunk.data());
  const hid_t set = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  H5Pclose(plist);
  H5Sclose(space);
  if (set < 0) write_fail(path, std::string("cannot create dataset ") + name);
  return set;
}

// Reads row k ([1 x n x 2] or, for time, one value) of an open dataset.
herr_t read_row(hid_t set, std::size_t k, std::size_t width, double* out) {
  const hid_t file_space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(file_space);
  const std::array<hsize_t, 3> start = {k, 0, 0};
  const std::array<hsize_t, 3> count = {1, width, 2};
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

InterfaceHistoryWriter::InterfaceHistoryWriter(const std::filesystem::path& h5, std::size_t nodes)
    : path_(h5), nodes_(nodes) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) write_fail(h5, "cannot create file");
  time_ = create_rows(file_, "time", 0, h5);
  position_ = create_rows(file_, kRowSets[0], nodes, h5);
  velocity_ = create_rows(file_, kRowSets[1], nodes, h5);
  acceleration_ = create_rows(file_, kRowSets[2], nodes, h5);
  load_ = create_rows(file_, kRowSets[3], nodes, h5);
}

InterfaceHistoryWriter::~InterfaceHistoryWriter() {
  for (hid_t set : {time_, position_, velocity_, acceleration_, load_})
    if (set >= 0) H5Dclose(set);
  if (file_ >= 0) H5Fclose(file_);
}

void InterfaceHistoryWriter::append_rows(std::int64_t set, const std::vector<Vec2>& values) {
  if (values.size() != nodes_)
    write_fail(path_, "row of " + std::to_string(values.size()) + " nodes, expected " +
                          std::to_string(nodes_));
  const std::array<hsize_t, 3> extent = {rows_ + 1, nodes_, 2};
  const std::array<hsize_t, 3> start = {rows_, 0, 0};
  const std::array<hsize_t, 3> count = {1, nodes_, 2};
  herr_t status = H5Dset_extent(set, extent.data());
  const hid_t file_space = H5Dget_space(set);
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  const hid_t mem_space = H5Screate_simple(3, count.data(), nullptr);
  const double* data = values.empty() ? nullptr : values.front().data();
  if (status >= 0)
    status = H5Dwrite(set, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, data);
  H5Sclose(mem_space);
  H5Sclose(file_space);
  if (status < 0) write_fail(path_, "cannot append row " + std::to_string(rows_));
}

void InterfaceHistoryWriter::append(double time, const coupling::InterfaceMotion& motion,
                                    const coupling::InterfaceLoads& loads) {
  const std::array<hsize_t, 1> extent = {rows_ + 1}, start = {rows_}, count = {1};
  herr_t status = H5Dset_extent(time_, extent.data());
  const hid_t file_space = H5Dget_space(time_);
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  const hid_t mem_space = H5Screate_simple(1, count.data(), nullptr);
  if (status >= 0)
    status = H5Dwrite(time_, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, &time);
  H5Sclose(mem_space);
  H5Sclose(file_space);
  if (status < 0) write_fail(path_, "cannot append time row " + std::to_string(rows_));
  append_rows(position_, motion.x);
  append_rows(velocity_, motion.v);
  append_rows(acceleration_, motion.a);
  append_rows(load_, loads.f);
  ++rows_;
  if (rows_ % kFlushRows == 1 && H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0)
    write_fail(path_, "flush failed");
}

InterfaceHistory::InterfaceHistory(const std::filesystem::path& h5) : path_(h5) {
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
        dims[2] != 2)
      throw InputError(where + "/" + name + " has dimensions " + text(dims) + ", expected [" +
                       std::to_string(time_.size()) + " x nodes x 2]");
  }
}

InterfaceHistory::~InterfaceHistory() {
  if (file_ >= 0) H5Fclose(file_);
}

const InterfaceHistory::Row& InterfaceHistory::row(std::size_t k, std::size_t keep) {
  for (std::size_t i = 0; i < cache_.size(); ++i)
    if (filled_[i] && cache_[i].index == k) return cache_[i];
  const std::size_t slot = filled_[0] && cache_[0].index == keep ? 1 : 0;
  Row& r = cache_[slot];
  r.index = k;
  r.motion = coupling::InterfaceMotion::zeros(nodes_);
  r.loads = coupling::InterfaceLoads::zeros(nodes_);
  std::array<std::vector<Vec2>*, 4> targets = {&r.motion.x, &r.motion.v, &r.motion.a, &r.loads.f};
  for (std::size_t j = 0; j < kRowSets.size(); ++j) {
    const hid_t set = H5Dopen2(file_, kRowSets[j], H5P_DEFAULT);
    const herr_t status = set < 0 ? -1 : read_row(set, k, nodes_, targets[j]->front().data());
    if (set >= 0) H5Dclose(set);
    if (status < 0)
      throw RunError(path_.string() + ": cannot read row " + std::to_string(k) + " of /" +
                     kRowSets[j]);
  }
  filled_[slot] = true;
  return r;
}

void InterfaceHistory::bracket(double t, const Row*& a, const Row*& b, double& s) {
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

coupling::InterfaceMotion InterfaceHistory::motion_at(double t) {
  const Row *a = nullptr, *b = nullptr;
  double s = 0.0;
  bracket(t, a, b, s);
  return a == b ? a->motion : coupling::interpolate(a->motion, b->motion, s);
}

coupling::InterfaceLoads InterfaceHistory::loads_at(double t) {
  const Row *a = nullptr, *b = nullptr;
  double s = 0.0;
  bracket(t, a, b, s);
  if (a == b) return a->loads;
  coupling::InterfaceLoads out = a->loads;
  for (std::size_t i = 0; i < out.size(); ++i)
    out.f[i] = (1.0 - s) * a->loads.f[i] + s * b->loads.f[i];
  return out;
}

} // namespace fsi::app
