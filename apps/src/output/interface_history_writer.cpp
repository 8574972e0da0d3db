#include "fsi/core/error.hpp"
#include "fsi_app/output/interface_history.hpp"

#include <algorithm>
#include <array>
#include <hdf5.h>

namespace fsi::app {

namespace {

static_assert(sizeof(Vec2) == 2 * sizeof(double), "Vec2 rows are stored as two doubles");
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 rows are stored as three doubles");
constexpr std::array<const char*, 4> kRowSets = {"position", "velocity", "acceleration", "load"};

[[noreturn]] void write_fail(const std::filesystem::path& file, const std::string& what) {
  throw RunError("output: " + file.string() + ": " + what);
}

// An extendible dataset of rows [0 x nodes x width] (nodes = 0: /time, [0]).
hid_t create_rows(hid_t file, const char* name, std::size_t nodes, hsize_t width,
                  const std::filesystem::path& path) {
  const int rank = nodes == 0 ? 1 : 3;
  const std::array<hsize_t, 3> dims = {0, nodes, width};
  const std::array<hsize_t, 3> max = {H5S_UNLIMITED, nodes, width};
  const std::array<hsize_t, 3> chunk = {64, std::max<hsize_t>(nodes, 1), width};
  const hid_t space = H5Screate_simple(rank, dims.data(), max.data());
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, rank, chunk.data());
  const hid_t set = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  H5Pclose(plist);
  H5Sclose(space);
  if (set < 0) write_fail(path, std::string("cannot create dataset ") + name);
  return set;
}

// /faces [m x 6], int64, written once.
void write_faces(hid_t file, const std::vector<std::array<std::size_t, 6>>& faces,
                 const std::filesystem::path& path) {
  std::vector<std::int64_t> nodes;
  for (const auto& f : faces)
    for (std::size_t k : f) nodes.push_back(static_cast<std::int64_t>(k));
  const std::array<hsize_t, 2> dims = {faces.size(), 6};
  const hid_t space = H5Screate_simple(2, dims.data(), nullptr);
  const hid_t set =
      H5Dcreate2(file, "faces", H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  herr_t status = set < 0 ? -1 : 0;
  if (status >= 0 && !nodes.empty())
    status = H5Dwrite(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, nodes.data());
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (status < 0) write_fail(path, "cannot write dataset faces");
}

} // namespace

template <int D>
BasicInterfaceHistoryWriter<D>::BasicInterfaceHistoryWriter(const std::filesystem::path& h5,
                                                            std::size_t nodes, const Faces& faces)
    : path_(h5), nodes_(nodes) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) write_fail(h5, "cannot create file");
  time_ = create_rows(file_, "time", 0, D, h5);
  position_ = create_rows(file_, kRowSets[0], nodes, D, h5);
  velocity_ = create_rows(file_, kRowSets[1], nodes, D, h5);
  acceleration_ = create_rows(file_, kRowSets[2], nodes, D, h5);
  load_ = create_rows(file_, kRowSets[3], nodes, D, h5);
  if constexpr (D == 3) write_faces(file_, faces, h5);
}

template <int D> BasicInterfaceHistoryWriter<D>::~BasicInterfaceHistoryWriter() {
  for (hid_t set : {time_, position_, velocity_, acceleration_, load_})
    if (set >= 0) H5Dclose(set);
  if (file_ >= 0) H5Fclose(file_);
}

template <int D>
void BasicInterfaceHistoryWriter<D>::append_rows(std::int64_t set,
                                                 const std::vector<VecD<D>>& values) {
  if (values.size() != nodes_)
    write_fail(path_, "row of " + std::to_string(values.size()) + " nodes, expected " +
                          std::to_string(nodes_));
  const std::array<hsize_t, 3> extent = {rows_ + 1, nodes_, D};
  const std::array<hsize_t, 3> start = {rows_, 0, 0};
  const std::array<hsize_t, 3> count = {1, nodes_, D};
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

template <int D>
void BasicInterfaceHistoryWriter<D>::append(double time,
                                            const coupling::BasicInterfaceMotion<D>& motion,
                                            const coupling::BasicInterfaceLoads<D>& loads) {
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
  if (rows_ % kFlushRows == 1) flush();
}

template <int D> void BasicInterfaceHistoryWriter<D>::flush() {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) write_fail(path_, "flush failed");
}

template class BasicInterfaceHistoryWriter<2>;
template class BasicInterfaceHistoryWriter<3>;

} // namespace fsi::app
