// FieldsFile opened and closed: a new fields.h5, or one reopened on restart and cut back to the
// checkpoint's frames; the close that keeps a broken file as its last flush left it.
#include "fields_file_parts.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/file_lock.hpp"

#include <algorithm>
#include <fcntl.h>
#include <unistd.h>

namespace fsi::app {

using h5::check;

namespace {

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

} // namespace fsi::app
