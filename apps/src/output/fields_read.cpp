// fields.h5 read back (FieldsFile's readers for tests and restart tools).
#include "fsi_app/output/fields_file.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/file_lock.hpp"

#include <algorithm>
#include <hdf5.h>

namespace fsi::app {

Dataset read_dataset(const std::filesystem::path& h5, const std::string& name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw InputError(h5.string() + ": cannot open HDF5 file" + lock_note(h5, false));
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) {
    H5Fclose(file);
    throw InputError(h5.string() + ": no dataset " + name);
  }
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  Dataset out;
  std::size_t count = 1;
  for (auto d : dims) out.dims.push_back(d), count *= d;
  out.values.resize(count);
  if (count > 0) H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data());
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  return out;
}

double read_frame_time(const std::filesystem::path& h5, int frame) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw InputError(h5.string() + ": cannot open HDF5 file" + lock_note(h5, false));
  try {
    const double time = read_frame_time(h5, file, frame);
    H5Fclose(file);
    return time;
  } catch (...) {
    H5Fclose(file);
    throw;
  }
}

} // namespace fsi::app
