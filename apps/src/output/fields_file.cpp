#include "fsi_app/output/fields_file.hpp"

#include "dataset_part.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/file_lock.hpp"
#include "fsi_app/output/text_file.hpp"
#include "fsi_app/ranks.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <hdf5.h>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace fsi::app {

using h5::check;
using h5::h5_fail;
using h5::Part;
using h5::write_array;

namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is stored as int64");

hid_t make_group(hid_t parent, const std::string& name, const std::filesystem::path& file) {
  const hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE); // children listed in creation order on restart
  H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  const hid_t g = H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT);
  H5Pclose(gcpl);
  if (g < 0) h5_fail(file, "cannot create group " + name);
  return g;
}

/// Names of the links in group `path`, in creation order.
std::vector<std::string> children(hid_t file, const std::string& path,
                                  const std::filesystem::path& h5) {
  std::vector<std::string> names;
  const herr_t status = H5Literate_by_name(
      file, path.c_str(), H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
      },
      &names, H5P_DEFAULT);
  if (status < 0) throw InputError(h5.string() + ": cannot list " + path);
  return names;
}

std::vector<hsize_t> dims_of(hid_t file, const std::string& path, const std::filesystem::path& h5) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) throw InputError(h5.string() + ": no dataset " + path);
  const hid_t space = H5Dget_space(set);
  std::vector<hsize_t> dims(
      static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(space))));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return dims;
}

/// Tetrahedron_10 node k (XDMF/VTK: edge nodes 0-1, 1-2, 2-0, 0-3, 1-3, 2-3) is Gmsh's node
/// kT10ToXdmf[k] (edge nodes 0-1, 1-2, 2-0, 3-0, 3-2, 3-1; structure_fem's t10_edges).
constexpr std::array<int, 10> kT10ToXdmf{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

/// The XDMF topology and the /meshes/<grid> dataset of a mesh of 6- or 10-node elements.
const char* topology_name(int nodes) {
  return nodes == 6 ? "Triangle_6" : "Tetrahedron_10";
}
const char* connectivity_name(int nodes) {
  return nodes == 6 ? "t6" : "t10";
}

} // namespace

double read_frame_time(const std::filesystem::path& h5, std::int64_t file, int frame) {
  const std::string name = "frames/" + std::to_string(frame);
  double time = 0.0;
  const hid_t attr = H5Aopen_by_name(file, name.c_str(), "time", H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Aread(attr, H5T_NATIVE_DOUBLE, &time);
  if (attr >= 0) H5Aclose(attr);
  if (status < 0) throw InputError(h5.string() + ": no frame " + std::to_string(frame));
  return time;
}

namespace {

/// HDF5 1.10 crashes in its exit handler (H5_term_library, SIGSEGV) on a file whose close failed,
/// as the close of a broken fields.h5 does (below). Closing is this code's job, file by file, so
/// the handler is not installed: H5dont_atexit must come before any other HDF5 call, hence a
/// static initializer.
[[maybe_unused]] const bool kNoHdf5ExitHandler = [] { return H5dont_atexit() >= 0; }();

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

bool writes_collectively(const Ranks& ranks) {
#ifdef H5_HAVE_PARALLEL
  return ranks.decomposed();
#else
  (void)ranks;
  return false;
#endif
}

std::int64_t FieldsFile::file_access() const {
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
#ifdef H5_HAVE_PARALLEL
  if (ranks_) H5Pset_fapl_mpio(fapl, MPI_COMM_WORLD, MPI_INFO_NULL); // MpiRanks' communicator
#endif
  return fapl;
}

bool FieldsFile::root() const {
  return !ranks_ || ranks_->rank() == 0;
}

template <class F> void FieldsFile::opened(F&& body) {
  try {
    guarded(body);
  } catch (...) {
    close(); // a constructor that throws runs no destructor
    throw;
  }
}

template <class F> void FieldsFile::guarded(F&& body) {
  if (broken_)
    h5_fail(h5_path_, "not written after an earlier error (every frame of " +
                          xmf_path_.filename().string() + " is complete)");
  try {
    phase(body);
  } catch (...) {
    broken_ = true;
    poisoned_ = !refused_; // a refused frame wrote nothing
    throw;
  }
}

template <class F> void FieldsFile::phase(F&& body) {
  if (ranks_)
    agreed(*ranks_, body);
  else
    body();
}

FieldsFile::FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf,
                       const Ranks* collective)
    : h5_path_(h5), xmf_path_(xmf), ranks_(collective) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t fapl = file_access();
  file_ = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  if (file_ < 0) h5_fail(h5, "cannot create file");
  opened([&] {
    check(H5Gclose(make_group(file_, "meshes", h5)), h5, "cannot create group meshes");
    check(H5Gclose(make_group(file_, "frames", h5)), h5, "cannot create group frames");
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5, "flush failed");
    write_xdmf();
  });
}

FieldsFile::FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf,
                       int keep_frames, const Ranks* collective)
    : h5_path_(h5), xmf_path_(xmf), ranks_(collective) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t fapl = file_access();
  file_ = H5Fopen(h5.c_str(), H5F_ACC_RDWR, fapl);
  H5Pclose(fapl);
  if (file_ < 0) {
    const std::string locked = lock_note(h5, true);
    throw InputError(h5.string() + ": cannot open" +
                     (locked.empty() ? " (a restart continues the files of its run)" : locked));
  }
  opened([&] {
    for (const auto& grid : children(file_, "meshes", h5))
      if (grid != "vertices") {
        const bool t6 = H5Lexists(file_, ("meshes/" + grid + "/t6").c_str(), H5P_DEFAULT) > 0;
        const int nodes = t6 ? 6 : 10;
        const std::string set = "meshes/" + grid + "/" + connectivity_name(nodes);
        meshes_.push_back({grid, dims_of(file_, set, h5).front(), nodes});
      }
    if (H5Lexists(file_, "meshes/vertices", H5P_DEFAULT) > 0)
      vertices_ = dims_of(file_, "meshes/vertices", h5).front();
    const auto count = static_cast<int>(children(file_, "frames", h5).size());
    if (count < keep_frames)
      throw InputError(h5.string() + ": has " + std::to_string(count) +
                       " frames, the checkpoint needs " + std::to_string(keep_frames));
    for (int k = 0; k < keep_frames; ++k) {
      const std::string frame = "frames/" + std::to_string(k);
      FrameRecord record{read_frame_time(h5, file_, k), {}};
      for (const auto& grid : children(file_, frame, h5)) {
        const auto position = dims_of(file_, frame + "/" + grid + "/position", h5);
        GridRecord g{grid, position.front(), {}, static_cast<int>(position.at(1))};
        for (const auto& field : children(file_, frame + "/" + grid, h5)) {
          if (field == "position") continue;
          const auto dims = dims_of(file_, frame + "/" + grid + "/" + field, h5);
          g.fields.emplace_back(field, dims.size() > 1 ? static_cast<int>(dims[1]) : 1);
        }
        record.grids.push_back(std::move(g));
      }
      frames_.push_back(std::move(record));
    }
    // The index first, then the frames after the checkpoint deleted: an index that cannot be
    // written (a full disk) leaves the pair as it was, every frame it names present.
    write_xdmf();
    for (int k = keep_frames; k < count; ++k)
      check(H5Ldelete(file_, ("frames/" + std::to_string(k)).c_str(), H5P_DEFAULT), h5,
            "cannot delete frame " + std::to_string(k));
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5, "flush failed");
    restarted_ = true;
  });
}

FieldsFile::~FieldsFile() {
  close();
}

void FieldsFile::close() noexcept {
  if (poisoned_ && file_ >= 0 && !ranks_) { // (an MPI-IO file has no descriptor to redirect)
    // A write failed inside HDF5: its cache holds metadata that the file on disk lacks, and
    // writing what still fits (the superblock with the new end of file, say) makes the file
    // unreadable. HDF5's descriptor is pointed at /dev/null, so the close writes nothing into
    // fields.h5, which stays as its last flush left it (every frame the XDMF names). The close
    // then fails (it cannot truncate /dev/null) and leaves its id half-closed: harmless, since
    // no exit handler goes back to it (kNoHdf5ExitHandler).
    void* handle = nullptr;
    if (H5Fget_vfd_handle(file_, H5P_DEFAULT, &handle) >= 0 && handle != nullptr) {
      const int sink = ::open("/dev/null", O_RDWR | O_CLOEXEC);
      if (sink >= 0) {
        ::dup2(sink, *static_cast<int*>(handle));
        ::close(sink);
      }
    }
  }
  if (frame_group_ >= 0) H5Gclose(frame_group_);
  if (file_ >= 0) H5Fclose(file_);
  frame_group_ = -1;
  file_ = -1;
}

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

void FieldsFile::write_xdmf() const {
  if (!root()) return; // rank 0 writes the index
  const std::string h5 = h5_path_.filename().string();
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
    << "<Grid Name=\"series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < frames_.size(); ++k) {
    const auto& frame = frames_[k];
    const std::string base = h5 + ":/frames/" + std::to_string(k) + "/";
    x << " <Grid Name=\"frame" << k << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "  <Time Value=\"" << frame.time << "\"/>\n";
    for (const auto& g : frame.grids) {
      const auto mesh = std::find_if(meshes_.begin(), meshes_.end(),
                                     [&](const MeshRecord& m) { return m.grid == g.grid; });
      x << "  <Grid Name=\"" << g.grid << "\" GridType=\"Uniform\">\n";
      if (mesh != meshes_.end()) {
        x << "   <Topology TopologyType=\"" << topology_name(mesh->nodes)
          << "\" NumberOfElements=\"" << mesh->elements << "\">\n    <DataItem Dimensions=\""
          << mesh->elements << " " << mesh->nodes
          << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/meshes/" << g.grid
          << "/" << connectivity_name(mesh->nodes) << "</DataItem>\n   </Topology>\n";
      } else if (g.points == 0) {
        x << "   <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"0\" "
             "NodesPerElement=\"1\"/>\n";
      } else {
        // One vertex cell per particle, with explicit connectivity: ParaView's default reader
        // (Xdmf3ReaderS) makes no cells from an implicit Polyvertex; the legacy XDMFReader
        // reads both forms.
        x << "   <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << g.points
          << "\" NodesPerElement=\"1\">\n    <DataItem ItemType=\"HyperSlab\" Dimensions=\""
          << g.points << "\" Type=\"HyperSlab\">\n     <DataItem Dimensions=\"3 1\" "
          << "Format=\"XML\">0 1 " << g.points << "</DataItem>\n     <DataItem Dimensions=\""
          << vertices_ << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5
          << ":/meshes/vertices</DataItem>\n    </DataItem>\n   </Topology>\n";
      }
      x << "   <Geometry GeometryType=\"" << (g.dim == 2 ? "XY" : "XYZ")
        << "\">\n    <DataItem Dimensions=\"" << g.points << " " << g.dim
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base << g.grid
        << "/position</DataItem>\n   </Geometry>\n";
      for (const auto& [name, components] : g.fields) {
        x << "   <Attribute Name=\"" << name << "\" AttributeType=\""
          << (components == 1 ? "Scalar" : "Vector") << "\" Center=\"Node\">\n"
          << "    <DataItem Dimensions=\"" << g.points;
        if (components > 1) x << " " << components;
        x << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base << g.grid << "/"
          << name << "</DataItem>\n   </Attribute>\n";
      }
      x << "  </Grid>\n";
    }
    x << " </Grid>\n";
  }
  x << "</Grid>\n</Domain>\n</Xdmf>\n";
  // fields.xmf.tmp, renamed; removed when the write fails (not synced: rewritten every frame).
  write_file_atomically(xmf_path_, x.str(), "output: ", false);
}

std::vector<GridField> select_fields(const std::vector<std::string>& requested,
                                     std::vector<GridField> available) {
  std::erase_if(available, [&](const GridField& f) {
    return std::find(requested.begin(), requested.end(), f.name) == requested.end();
  });
  return available;
}

} // namespace fsi::app
