#include "dataset_part.hpp"

#include "fsi/core/error.hpp"

namespace fsi::app::h5 {

[[noreturn]] void h5_fail(const std::filesystem::path& file, const std::string& what) {
  throw RunError("output: " + file.string() + ": " + what);
}

void check(herr_t status, const std::filesystem::path& file, const std::string& what) {
  if (status < 0) h5_fail(file, what);
}

namespace {

/// Selects `part`'s rows of `file_space` ([rows x columns]): one block (FileRows), everything on
/// rank 0 or nothing; the memory space of as many local rows.
hid_t select_part(hid_t file_space, const Part& part, const std::vector<hsize_t>& dims) {
  std::vector<hsize_t> local = dims;
  if (part.rows) {
    local.front() = part.rows->count;
    std::vector<hsize_t> start(dims.size(), 0);
    start.front() = part.rows->first;
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, local.data(), nullptr);
  } else if (!part.root) {
    H5Sselect_none(file_space);
  }
  const hid_t mem = H5Screate_simple(static_cast<int>(local.size()), local.data(), nullptr);
  if (!part.rows && !part.root) H5Sselect_none(mem);
  return mem;
}

} // namespace

void write_array(hid_t parent, const std::string& name, hid_t mem_type, const void* data,
                 std::vector<hsize_t> dims, const std::filesystem::path& file, const Part& part) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t file_type = mem_type == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : H5T_STD_I64LE;
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (part.collective) H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER); // every row is written
  const hid_t set =
      H5Dcreate2(parent, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  H5Pclose(dcpl);
  if (set < 0) h5_fail(file, "cannot create dataset " + name);
  herr_t status = 0;
  if (!part.collective) {
    if (dims.front() != 0) status = H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  } else {
    const hid_t mem = select_part(space, part, dims);
    // Independent transfer (H5P_DEFAULT): one block a rank, faster than MPI-IO's collective
    // buffering on this data (docs/architecture.md); the dataset's creation stays collective.
    const double none = 0.0; // a rank writing no row still passes a buffer
    status = H5Dwrite(set, mem_type, mem, space, H5P_DEFAULT, data ? data : &none);
    H5Sclose(mem);
  }
  H5Dclose(set);
  H5Sclose(space);
  check(status, file, "cannot write dataset " + name);
}

} // namespace fsi::app::h5
