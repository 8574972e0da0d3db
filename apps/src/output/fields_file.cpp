#include "fsi_app/output/fields_file.hpp"

#include "fsi/core/error.hpp"

#include <fstream>
#include <hdf5.h>
#include <sstream>

namespace fsi::app {

namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is stored as int64");

[[noreturn]] void h5_fail(const std::filesystem::path& file, const std::string& what) {
  throw RunError("output: " + file.string() + ": " + what);
}

void check(herr_t status, const std::filesystem::path& file, const std::string& what) {
  if (status < 0) h5_fail(file, what);
}

void write_array(hid_t parent, const std::string& name, hid_t mem_type, const void* data,
                 std::vector<hsize_t> dims, const std::filesystem::path& file) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t file_type = mem_type == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : H5T_STD_I64LE;
  const hid_t set =
      H5Dcreate2(parent, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) h5_fail(file, "cannot create dataset " + name);
  const bool empty = dims.front() == 0;
  const herr_t status = empty ? 0 : H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(set);
  H5Sclose(space);
  check(status, file, "cannot write dataset " + name);
}

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

FieldsFile::FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf)
    : h5_path_(h5), xmf_path_(xmf) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(h5.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) h5_fail(h5, "cannot create file");
  H5Gclose(make_group(file_, "meshes", h5));
  H5Gclose(make_group(file_, "frames", h5));
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5, "flush failed");
  write_xdmf();
}

FieldsFile::FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf,
                       int keep_frames)
    : h5_path_(h5), xmf_path_(xmf) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file_ < 0)
    throw InputError(h5.string() + ": cannot open (a restart continues the files of its run)");
  for (const auto& grid : children(file_, "meshes", h5))
    meshes_.push_back({grid, dims_of(file_, "meshes/" + grid + "/t6", h5).front()});
  const auto count = static_cast<int>(children(file_, "frames", h5).size());
  if (count < keep_frames)
    throw InputError(h5.string() + ": has " + std::to_string(count) +
                     " frames, the checkpoint needs " + std::to_string(keep_frames));
  for (int k = keep_frames; k < count; ++k) // frames after the checkpoint
    check(H5Ldelete(file_, ("frames/" + std::to_string(k)).c_str(), H5P_DEFAULT), h5,
          "cannot delete frame " + std::to_string(k));
  for (int k = 0; k < keep_frames; ++k) {
    const std::string frame = "frames/" + std::to_string(k);
    FrameRecord record{read_frame_time(h5, file_, k), {}};
    for (const auto& grid : children(file_, frame, h5)) {
      GridRecord g{grid, dims_of(file_, frame + "/" + grid + "/position", h5).front(), {}};
      for (const auto& field : children(file_, frame + "/" + grid, h5)) {
        if (field == "position") continue;
        const auto dims = dims_of(file_, frame + "/" + grid + "/" + field, h5);
        g.fields.emplace_back(field, dims.size() > 1 ? static_cast<int>(dims[1]) : 1);
      }
      record.grids.push_back(std::move(g));
    }
    frames_.push_back(std::move(record));
  }
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5, "flush failed");
  write_xdmf();
}

FieldsFile::~FieldsFile() {
  if (frame_group_ >= 0) H5Gclose(frame_group_);
  if (file_ >= 0) H5Fclose(file_);
}

void FieldsFile::add_mesh(const std::string& grid, const std::vector<std::int64_t>& t6) {
  const hid_t g = make_group(file_, "meshes/" + grid, h5_path_);
  write_array(g, "t6", H5T_NATIVE_INT64, t6.data(), {t6.size() / 6, 6}, h5_path_);
  H5Gclose(g);
  meshes_.push_back({grid, t6.size() / 6});
}

void FieldsFile::begin_frame(double time) {
  const std::string name = "frames/" + std::to_string(frames_.size());
  frame_group_ = make_group(file_, name, h5_path_);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr =
      H5Acreate2(frame_group_, "time", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &time), h5_path_, "cannot write frame time");
  H5Aclose(attr);
  H5Sclose(space);
  frames_.push_back({time, {}});
}

void FieldsFile::write_grid(const std::string& grid, const std::vector<double>& xy,
                            const std::vector<GridField>& fields) {
  const hid_t g = make_group(frame_group_, grid, h5_path_);
  const hsize_t n = xy.size() / 2;
  write_array(g, "position", H5T_NATIVE_DOUBLE, xy.data(), {n, 2}, h5_path_);
  GridRecord record{grid, n, {}};
  for (const auto& f : fields) {
    std::vector<hsize_t> dims = {n};
    if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
    write_array(g, f.name, H5T_NATIVE_DOUBLE, f.data, dims, h5_path_);
    record.fields.emplace_back(f.name, f.components);
  }
  H5Gclose(g);
  frames_.back().grids.push_back(std::move(record));
}

void FieldsFile::end_frame() {
  H5Gclose(frame_group_);
  frame_group_ = -1;
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), h5_path_, "flush failed");
  write_xdmf();
}

void FieldsFile::write_xdmf() const {
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
      if (mesh != meshes_.end())
        x << "   <Topology TopologyType=\"Triangle_6\" NumberOfElements=\"" << mesh->elements
          << "\">\n    <DataItem Dimensions=\"" << mesh->elements
          << " 6\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/meshes/"
          << g.grid << "/t6</DataItem>\n   </Topology>\n";
      else
        x << "   <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << g.points << "\"/>\n";
      x << "   <Geometry GeometryType=\"XY\">\n    <DataItem Dimensions=\"" << g.points
        << " 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base << g.grid
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
  const std::filesystem::path tmp = xmf_path_.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << x.str();
    if (!out) h5_fail(xmf_path_, "cannot write XDMF index");
  }
  std::filesystem::rename(tmp, xmf_path_);
}

Dataset read_dataset(const std::filesystem::path& h5, const std::string& name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw InputError(h5.string() + ": cannot open HDF5 file");
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
  if (file < 0) throw InputError(h5.string() + ": cannot open HDF5 file");
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
