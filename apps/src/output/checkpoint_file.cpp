#include "fsi_app/output/checkpoint_file.hpp"

#include <hdf5.h>

namespace fsi::app {

namespace {

struct Writer {
  const std::filesystem::path& file;
  hid_t h5;
  hid_t lcpl; // creates the groups of a key's path on the way

  template <class T> void write(const std::string& key, const std::vector<T>& values) {
    const bool real = std::is_same_v<T, double>;
    const hsize_t n = values.size();
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t set = H5Dcreate2(h5, key.c_str(), real ? H5T_IEEE_F64LE : H5T_STD_I64LE, space,
                                 lcpl, H5P_DEFAULT, H5P_DEFAULT);
    herr_t status = set < 0 ? -1 : 0;
    if (set >= 0 && n > 0)
      status = H5Dwrite(set, real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, H5S_ALL, H5S_ALL,
                        H5P_DEFAULT, values.data());
    if (set >= 0) H5Dclose(set);
    H5Sclose(space);
    if (status < 0) throw RunError("checkpoint: " + file.string() + ": cannot write " + key);
  }
};

struct Reader {
  const std::filesystem::path& file;
  StateArchive archive;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file.string() + ": " + what);
  }

  void read_dataset(hid_t set, const std::string& key) {
    const hid_t space = H5Dget_space(set);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    const hid_t type = H5Dget_type(set);
    const H5T_class_t kind = H5Tget_class(type);
    H5Tclose(type);
    if (n < 0) fail("unreadable dataset " + key);
    herr_t status = 0;
    if (kind == H5T_FLOAT) {
      std::vector<double> v(static_cast<std::size_t>(n));
      if (n > 0) status = H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
      archive.put(key, std::move(v));
    } else if (kind == H5T_INTEGER) {
      std::vector<std::int64_t> v(static_cast<std::size_t>(n));
      if (n > 0) status = H5Dread(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
      archive.put(key, std::move(v));
    } else {
      fail("dataset " + key + " is neither float nor integer");
    }
    if (status < 0) fail("cannot read dataset " + key);
  }

  // Every dataset below `group`, keyed by its path without the leading '/'.
  void read_group(hid_t group, const std::string& prefix) {
    std::vector<std::string> names;
    H5Literate(
        group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
        [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
          static_cast<std::vector<std::string>*>(data)->push_back(name);
          return 0;
        },
        &names);
    for (const auto& name : names) {
      const hid_t object = H5Oopen(group, name.c_str(), H5P_DEFAULT);
      if (object < 0) fail("cannot open " + prefix + name);
      if (H5Iget_type(object) == H5I_GROUP)
        read_group(object, prefix + name + "/");
      else
        read_dataset(object, prefix + name);
      H5Oclose(object);
    }
  }
};

} // namespace

void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::filesystem::path tmp = file.string() + ".tmp";
  const hid_t h5 = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (h5 < 0) throw RunError("checkpoint: " + tmp.string() + ": cannot create");
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  Writer w{tmp, h5, lcpl};
  try {
    for (const auto& [key, values] : archive.all_reals()) w.write(key, values);
    for (const auto& [key, values] : archive.all_integers()) w.write(key, values);
  } catch (...) {
    H5Pclose(lcpl);
    H5Fclose(h5);
    throw;
  }
  H5Pclose(lcpl);
  if (H5Fflush(h5, H5F_SCOPE_GLOBAL) < 0 || H5Fclose(h5) < 0)
    throw RunError("checkpoint: " + tmp.string() + ": cannot write");
  std::filesystem::rename(tmp, file);
}

StateArchive read_checkpoint(const std::filesystem::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (h5 < 0) throw InputError(file.string() + ": cannot open as an HDF5 checkpoint");
  Reader r{file, {}};
  try {
    r.read_group(h5, "");
  } catch (...) {
    H5Fclose(h5);
    throw;
  }
  H5Fclose(h5);
  return std::move(r.archive);
}

} // namespace fsi::app
