// FieldsFile's index: fields.xmf, the XDMF 3 file that names every frame's datasets in fields.h5
// (rank 0 writes it, replaced whole after every frame).
#include "fields_file_parts.hpp"

#include "fsi_app/output/text_file.hpp"

#include <algorithm>
#include <sstream>

namespace fsi::app {

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

} // namespace fsi::app
