#include "fsi_app/output/checkpoint_file.hpp"

#include "fsi_app/output/file_lock.hpp"
#include "fsi_app/output/text_file.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <hdf5.h>

namespace fsi::app {

namespace {

/// Name of the attribute that holds a dataset's checksum.
constexpr const char* kChecksum = "fnv1a64";

/// Closes an HDF5 id on every path out of a scope (errors of the close are reported by the
/// explicit close() where they matter).
class Id {
public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() { close(); }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  herr_t close() {
    const herr_t status = id_ >= 0 ? close_(id_) : 0;
    id_ = -1;
    return status;
  }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Writes the in-memory HDF5 image to `file` (see write_checkpoint).
struct Writer {
  const std::filesystem::path& file;
  hid_t h5;
  hid_t lcpl; // creates the groups of a key's path on the way

  [[noreturn]] void fail(const std::string& what) const {
    throw RunError("checkpoint: " + file.string() + ": " + what);
  }

  template <class T> void write(const std::string& key, const std::vector<T>& values) {
    const bool real = std::is_same_v<T, double>;
    const hsize_t n = values.size();
    Id space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    if (!space.valid()) fail("cannot write " + key);
    Id set(H5Dcreate2(h5, key.c_str(), real ? H5T_IEEE_F64LE : H5T_STD_I64LE, space.get(), lcpl,
                      H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
    if (!set.valid()) fail("cannot write " + key);
    if (n > 0 && H5Dwrite(set.get(), real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, H5S_ALL, H5S_ALL,
                          H5P_DEFAULT, values.data()) < 0)
      fail("cannot write " + key);
    const std::uint64_t sum = checkpoint_checksum(values);
    Id scalar(H5Screate(H5S_SCALAR), H5Sclose);
    Id attr(H5Acreate2(set.get(), kChecksum, H5T_STD_U64LE, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Aclose);
    if (!attr.valid() || H5Awrite(attr.get(), H5T_NATIVE_UINT64, &sum) < 0 || attr.close() < 0 ||
        set.close() < 0)
      fail("cannot write " + key);
  }
};

std::string hex(std::uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

struct Reader {
  const std::filesystem::path& file;
  StateArchive archive;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file.string() + ": " + what);
  }

  template <class T> void verify(hid_t set, const std::string& key, const std::vector<T>& v) {
    if (H5Aexists(set, kChecksum) <= 0)
      fail("dataset '" + key + "' has no checksum (not a checkpoint of this fsi)");
    Id attr(H5Aopen(set, kChecksum, H5P_DEFAULT), H5Aclose);
    std::uint64_t stored = 0;
    if (!attr.valid() || H5Aread(attr.get(), H5T_NATIVE_UINT64, &stored) < 0)
      fail("dataset '" + key + "': cannot read its checksum");
    const std::uint64_t sum = checkpoint_checksum(v);
    if (sum != stored)
      fail("dataset '" + key + "' is damaged: its checksum is " + hex(sum) + ", the file says " +
           hex(stored) + " (restart from another checkpoint)");
  }

  void read_dataset(hid_t set, const std::string& key) {
    hssize_t n = -1;
    {
      Id space(H5Dget_space(set), H5Sclose);
      if (space.valid()) n = H5Sget_simple_extent_npoints(space.get());
    }
    H5T_class_t kind = H5T_NO_CLASS;
    {
      Id type(H5Dget_type(set), H5Tclose);
      if (type.valid()) kind = H5Tget_class(type.get());
    }
    if (n < 0) fail("unreadable dataset " + key);
    herr_t status = 0;
    if (kind == H5T_FLOAT) {
      std::vector<double> v(static_cast<std::size_t>(n));
      if (n > 0) status = H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
      if (status < 0) fail("cannot read dataset " + key);
      verify(set, key, v);
      archive.put(key, std::move(v));
    } else if (kind == H5T_INTEGER) {
      std::vector<std::int64_t> v(static_cast<std::size_t>(n));
      if (n > 0) status = H5Dread(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
      if (status < 0) fail("cannot read dataset " + key);
      verify(set, key, v);
      archive.put(key, std::move(v));
    } else {
      fail("dataset " + key + " is neither float nor integer");
    }
  }

  // Every dataset below `group`, keyed by its path without the leading '/'.
  void read_group(hid_t group, const std::string& prefix) {
    std::vector<std::string> names;
    if (H5Literate(
            group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
            [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
              static_cast<std::vector<std::string>*>(data)->push_back(name);
              return 0;
            },
            &names) < 0)
      fail("cannot list " + (prefix.empty() ? std::string("/") : prefix));
    for (const auto& name : names) {
      Id object(H5Oopen(group, name.c_str(), H5P_DEFAULT), H5Oclose);
      if (!object.valid()) fail("cannot open " + prefix + name);
      if (H5Iget_type(object.get()) == H5I_GROUP)
        read_group(object.get(), prefix + name + "/");
      else
        read_dataset(object.get(), prefix + name);
    }
  }
};

} // namespace

std::uint64_t checkpoint_checksum(const std::vector<double>& values) {
  std::uint64_t h = 14695981039346656037ULL; // FNV-1a 64: offset basis
  for (double v : values) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xffU)) * 1099511628211ULL;
  }
  return h;
}

std::uint64_t checkpoint_checksum(const std::vector<std::int64_t>& values) {
  std::uint64_t h = 14695981039346656037ULL;
  for (std::int64_t v : values) {
    const auto bits = static_cast<std::uint64_t>(v);
    for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xffU)) * 1099511628211ULL;
  }
  return h;
}

void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  // The file is built in memory (HDF5's core driver, no backing store) and written out as one
  // image: a full disk is then a failed write() of ours, never a half-flushed HDF5 file whose
  // ids the library's exit handler would try to flush again.
  std::vector<unsigned char> image;
  {
    Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), 1 << 20, 0) < 0)
      throw RunError("checkpoint: " + file.string() + ": cannot set up the HDF5 file");
    Id h5(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
    if (!h5.valid()) throw RunError("checkpoint: " + file.string() + ": cannot create");
    Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl.get(), 1);
    Writer w{file, h5.get(), lcpl.get()};
    for (const auto& [key, values] : archive.all_reals()) w.write(key, values);
    for (const auto& [key, values] : archive.all_integers()) w.write(key, values);
    if (H5Fflush(h5.get(), H5F_SCOPE_GLOBAL) < 0) w.fail("cannot flush");
    const ssize_t size = H5Fget_file_image(h5.get(), nullptr, 0);
    if (size <= 0) w.fail("cannot build the file image");
    image.resize(static_cast<std::size_t>(size));
    if (H5Fget_file_image(h5.get(), image.data(), image.size()) != size)
      w.fail("cannot build the file image");
    if (h5.close() < 0) w.fail("cannot close");
  }
  // FILE.tmp, flushed to disk, renamed; a failed write removes FILE.tmp.
  write_file_atomically(file, image.data(), image.size(), "checkpoint: ");
}

StateArchive read_checkpoint(const std::filesystem::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Id h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid())
    throw InputError(file.string() + ": cannot open as an HDF5 checkpoint" +
                     lock_note(file, false));
  Reader r{file, {}};
  r.read_group(h5.get(), "");
  // A NaN is refused, naming its dataset. Not checked: the wall-hit cache (`*/hits/*`), whose
  // entries for particles without a hit are undefined and hold NaN in real runs (the NaN the
  // SIGINT restart test met in fluid/hits/v_wall), and the state of a failed step (which may
  // hold the NaN that stopped it; the driver refuses it with its own message).
  const auto& ints = r.archive.all_integers();
  const auto failed = ints.find("driver/failed");
  if (failed == ints.end() || failed->second.empty() || failed->second.front() == 0)
    for (const auto& [key, values] : r.archive.all_reals())
      for (std::size_t i = 0; key.find("/hits/") == std::string::npos && i < values.size(); ++i)
        if (std::isnan(values[i]))
          r.fail("dataset '" + key + "' holds NaN at entry " + std::to_string(i) +
                 " (restart from another checkpoint)");
  return std::move(r.archive);
}

} // namespace fsi::app
