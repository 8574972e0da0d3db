#pragma once
// One dataset of fields.h5 written by FieldsFile: by one process, or collectively with parallel
// HDF5, each rank its part (a particle grid's block of rows, FileRows; any other dataset
// rank 0's). Failures throw RunError `output: FILE: what`.
#include "fsi_app/output/fields_file.hpp"

#include <filesystem>
#include <hdf5.h>
#include <string>
#include <vector>

namespace fsi::app::h5 {

[[noreturn]] void h5_fail(const std::filesystem::path& file, const std::string& what);
void check(herr_t status, const std::filesystem::path& file, const std::string& what);

/// Which part of a dataset this process writes: all of it (one process); collective, the rows
/// `rows` places, or (no rows) everything on rank 0 and nothing on the others.
struct Part {
  bool collective = false;
  bool root = true;
  const FileRows* rows = nullptr;
};

/// Creates dataset `name` of `dims` (float64 or int64 in the file as `mem_type`) under `parent`
/// and writes `part` of it from `data` (this process's rows, row-major).
void write_array(hid_t parent, const std::string& name, hid_t mem_type, const void* data,
                 std::vector<hsize_t> dims, const std::filesystem::path& file,
                 const Part& part = {});

} // namespace fsi::app::h5
