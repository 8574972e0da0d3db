#pragma once
// What the files of FieldsFile share (fields_file.cpp: open and close; fields_frames.cpp: meshes
// and frames; fields_xdmf.cpp: the index): groups, the names of a mesh's topology, and the
// guards every write runs under.
#include "fsi_app/output/fields_file.hpp"

#include "dataset_part.hpp"

#include "fsi_app/ranks.hpp"

#include <hdf5.h>
#include <string>

namespace fsi::app {

using h5::h5_fail;

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is stored as int64");

/// Group `name` of `parent`, its children listed in creation order.
inline hid_t make_group(hid_t parent, const std::string& name, const std::filesystem::path& file) {
  const hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE); // children listed in creation order on restart
  H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  const hid_t g = H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT);
  H5Pclose(gcpl);
  if (g < 0) h5_fail(file, "cannot create group " + name);
  return g;
}

/// The XDMF topology and the /meshes/<grid> dataset of a mesh of 6- or 10-node elements.
inline const char* topology_name(int nodes) {
  return nodes == 6 ? "Triangle_6" : "Tetrahedron_10";
}
inline const char* connectivity_name(int nodes) {
  return nodes == 6 ? "t6" : "t10";
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

} // namespace fsi::app
