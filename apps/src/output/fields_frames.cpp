// FieldsFile's meshes and frames: the connectivity of each mesh, each frame's grids with their
// fields, a frame refused before it starts when the disk has no room for it.
#include "fields_file_parts.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

namespace fsi::app {

using h5::check;
using h5::Part;
using h5::write_array;

namespace {

/// Tetrahedron_10 node k (XDMF/VTK: edge nodes 0-1, 1-2, 2-0, 0-3, 1-3, 2-3) is Gmsh's node
/// kT10ToXdmf[k] (edge nodes 0-1, 1-2, 2-0, 3-0, 3-2, 3-1; structure_fem's t10_edges).
constexpr std::array<int, 10> kT10ToXdmf{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

/// Bytes fields.h5 may still grow by: the free space of its file system, and the room below
/// RLIMIT_FSIZE (a write past it fails with EFBIG).
std::uintmax_t room_for(const std::filesystem::path& h5) {
  std::uintmax_t room = std::numeric_limits<std::uintmax_t>::max();
  struct statvfs fs {};
  if (::statvfs(h5.parent_path().empty() ? "." : h5.parent_path().c_str(), &fs) == 0)
    room = static_cast<std::uintmax_t>(fs.f_bavail) * fs.f_frsize;
  struct rlimit limit {};
  struct stat st {};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      ::stat(h5.c_str(), &st) == 0) {
    const auto size = static_cast<std::uintmax_t>(st.st_size);
    room = std::min(room, limit.rlim_cur > size ? limit.rlim_cur - size : 0);
  }
  return room;
}

std::uintmax_t size_of(const std::filesystem::path& file) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  return ec ? 0 : size;
}

} // namespace

void FieldsFile::add_mesh(const std::string& grid, const std::vector<std::int64_t>& t6) {
  declare_mesh(grid, t6, 6);
}

void FieldsFile::add_mesh_t10(const std::string& grid, const std::vector<std::int64_t>& t10) {
  std::vector<std::int64_t> xdmf(t10.size());
  for (std::size_t e = 0; e + 10 <= t10.size(); e += 10)
    for (std::size_t k = 0; k < 10; ++k)
      xdmf[e + k] = t10[e + static_cast<std::size_t>(kT10ToXdmf[k])];
  declare_mesh(grid, xdmf, 10);
}

void FieldsFile::declare_mesh(const std::string& grid,
                              const std::vector<std::int64_t>& connectivity, int nodes) {
  guarded([&] {
    const hid_t g = make_group(file_, "meshes/" + grid, h5_path_);
    const auto n = static_cast<std::size_t>(nodes);
    try {
      write_array(g, connectivity_name(nodes), H5T_NATIVE_INT64, connectivity.data(),
                  {connectivity.size() / n, n}, h5_path_, {ranks_ != nullptr, root(), nullptr});
    } catch (...) {
      H5Gclose(g);
      throw;
    }
    check(H5Gclose(g), h5_path_, "cannot close group " + grid);
    meshes_.push_back({grid, connectivity.size() / n, nodes});
  });
}

void FieldsFile::begin_frame(double time) {
  guarded([&] {
    // Room for a frame: twice the largest frame so far and 64 KiB (index, metadata), checked
    // before anything of it is written, so a full disk stops between frames.
    const std::uintmax_t need = 2 * frame_bytes_ + (64U << 10);
    const std::uintmax_t room = room_for(h5_path_);
    if (ranks_ ? !ranks_->all(room >= need) : room < need) {
      refused_ = true;
      h5_fail(h5_path_,
              "no room for frame " + std::to_string(frames_.size()) + ": " + std::to_string(room) +
                  " bytes left (free space, or room below the file size limit), a frame " +
                  "needs about " + std::to_string(need) + " (disk full; every frame " + "of " +
                  xmf_path_.filename().string() + " is complete)");
    }
    frame_start_size_ = size_of(h5_path_);
    const std::string name = "frames/" + std::to_string(frames_.size());
    frame_group_ = make_group(file_, name, h5_path_);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attr =
        H5Acreate2(frame_group_, "time", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    const herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, &time);
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(space);
    check(status, h5_path_, "cannot write frame time");
    frames_.push_back({time, {}});
  });
}

void FieldsFile::ensure_vertices(std::size_t n) {
  if (n <= vertices_) return;
  // /meshes/vertices = 0, 1, ..., n - 1 (int64, extendible): each particle grid's vertex cells,
  // named by a hyperslab of its first `points` entries.
  hid_t set = -1;
  if (vertices_ == 0 && H5Lexists(file_, "meshes/vertices", H5P_DEFAULT) <= 0) {
    const hsize_t dims = n, max = H5S_UNLIMITED, chunk = 4096;
    const hid_t space = H5Screate_simple(1, &dims, &max);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(dcpl, 1, &chunk);
    if (ranks_) H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER); // rank 0 writes every entry
    set =
        H5Dcreate2(file_, "meshes/vertices", H5T_STD_I64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    H5Sclose(space);
  } else {
    set = H5Dopen2(file_, "meshes/vertices", H5P_DEFAULT);
    const hsize_t dims = n;
    if (set >= 0 && H5Dset_extent(set, &dims) < 0) H5Dclose(set), set = -1;
  }
  if (set < 0) h5_fail(h5_path_, "cannot write dataset meshes/vertices");
  std::vector<std::int64_t> index(n - vertices_);
  for (std::size_t i = 0; i < index.size(); ++i)
    index[i] = static_cast<std::int64_t>(vertices_ + i);
  const hsize_t start = vertices_, count = index.size();
  const hid_t file_space = H5Dget_space(set);
  const hid_t mem_space = H5Screate_simple(1, &count, nullptr);
  herr_t status = H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
  if (!root()) H5Sselect_none(file_space), H5Sselect_none(mem_space); // rank 0 writes them
  if (status >= 0)
    status = H5Dwrite(set, H5T_NATIVE_INT64, mem_space, file_space, H5P_DEFAULT, index.data());
  H5Sclose(mem_space);
  H5Sclose(file_space);
  if (H5Dclose(set) < 0) status = -1;
  check(status, h5_path_, "cannot write dataset meshes/vertices");
  vertices_ = n;
}

void FieldsFile::write_grid(const std::string& grid, const std::vector<double>& points,
                            const std::vector<GridField>& fields, int dim, const FileRows* rows) {
  guarded([&] {
    const bool mesh = std::any_of(meshes_.begin(), meshes_.end(),
                                  [&](const MeshRecord& m) { return m.grid == grid; });
    const auto d = static_cast<hsize_t>(dim);
    hsize_t n = rows ? rows->total : points.size() / d;
    if (ranks_ && !rows) { // rank 0's grid: its size on every rank
      std::vector<double> size{static_cast<double>(n)};
      ranks_->broadcast(size);
      n = static_cast<hsize_t>(size.front());
    }
    if (!mesh) phase([&] { ensure_vertices(n); });
    const hid_t g = make_group(frame_group_, grid, h5_path_);
    GridRecord record{grid, n, {}, dim};
    const Part part{ranks_ != nullptr, root(), ranks_ ? rows : nullptr};
    try {
      phase([&] {
        write_array(g, "position", H5T_NATIVE_DOUBLE, points.data(), {n, d}, h5_path_, part);
      });
      for (const auto& f : fields) {
        std::vector<hsize_t> dims = {n};
        if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
        phase([&] { write_array(g, f.name, H5T_NATIVE_DOUBLE, f.data, dims, h5_path_, part); });
        record.fields.emplace_back(f.name, f.components);
      }
    } catch (...) {
      H5Gclose(g);
      throw;
    }
    check(H5Gclose(g), h5_path_, "cannot close group " + grid);
    frames_.back().grids.push_back(std::move(record));
  });
}

void FieldsFile::end_frame() {
  guarded([&] {
    const herr_t closed = H5Gclose(frame_group_);
    frame_group_ = -1;
    check(closed, h5_path_, "cannot close frame group");
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5_path_, "flush failed");
    const std::uintmax_t size = size_of(h5_path_);
    // The first frame of a file also allocates the file's own structures: not a frame's size.
    if (size > frame_start_size_ && (frames_.size() > 1 || restarted_))
      frame_bytes_ = std::max(frame_bytes_, size - frame_start_size_);
    write_xdmf();
  });
}

std::vector<GridField> select_fields(const std::vector<std::string>& requested,
                                     std::vector<GridField> available) {
  std::erase_if(available, [&](const GridField& f) {
    return std::find(requested.begin(), requested.end(), f.name) == requested.end();
  });
  return available;
}

} // namespace fsi::app
