#pragma once
// fields.h5 + fields.xmf: a time series of grids (particle clouds, T6 and T10 meshes) that ParaView
// opens through the XDMF file. Each finished frame is flushed to disk and the XDMF rewritten
// (to a temporary name, then renamed), so a killed run leaves every finished frame readable and
// the XDMF names only datasets that exist. A full disk stops the run between frames (each frame
// first checks for room: twice the largest frame so far); a write that fails all the same marks
// the file broken: nothing more is written to it, and it is closed as its last flush left it.
// (The room check is a rule of thumb; the broken-file path is what keeps the frames safe.)
// Every failure throws RunError `output: FILE: what`.
//
// Collective (under mpirun, built with parallel HDF5: writes_collectively): every rank opens the
// one file through MPI-IO and makes every call in the same order; a particle grid's rows come
// from every rank (FileRows: each rank a block of the rows of a one-process file), any other
// grid (a mesh, a structure) from rank 0's data; rank 0 alone writes the XDMF. The data
// transfers are independent; success is agreed after each dataset and each call (agreed): a
// failure on some ranks throws AgreedError on every rank and breaks the file on every rank.
//
// A restart reopens the pair, keeps the first frames (those before its checkpoint), deletes the
// others and rewrites the XDMF; groups track creation order so the index comes out the same.
//
// HDF5 layout:
//   /meshes/<grid>/t6            int64 [elements x 6], written once per 2-D mesh grid (Triangle_6)
//   /meshes/<grid>/t10           int64 [elements x 10], once per 3-D mesh grid (Tetrahedron_10):
//                                edge nodes in XDMF/VTK order 0-1, 1-2, 2-0, 0-3, 1-3, 2-3 (Gmsh's
//                                last two, 3-2 and 3-1, swapped)
//   /meshes/vertices             int64 [n]: 0 .. n-1, n the largest particle count so far; a
//                                particle grid's vertex cells (XDMF Polyvertex, one node each)
//   /frames/<k>                  attribute `time` (s)
//   /frames/<k>/<grid>/position  float64 [points x D], D = 2 (XDMF XY) or 3 (XYZ)
//   /frames/<k>/<grid>/<field>   float64 [points] or [points x components]
#include "fsi/core/types.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::app {

class Ranks;

/// This process's rows of a grid written collectively: one block, its `count` rows the file's
/// rows first .. first + count - 1, of `total` rows over every process.
struct FileRows {
  std::size_t total = 0;
  std::size_t first = 0;
  std::size_t count = 0;
};

/// Whether a run over `ranks` writes fields.h5 collectively: decomposed (under mpirun) and built
/// with parallel HDF5 (H5_HAVE_PARALLEL); otherwise rank 0 writes it alone.
bool writes_collectively(const Ranks& ranks);

struct GridField {
  std::string name;
  int components = 1;           ///< 1 (scalar), 2 or 3 (vector)
  const double* data = nullptr; ///< points x components, row-major
};

/// The fields of `available` that `requested` names, in the order of `available`.
std::vector<GridField> select_fields(const std::vector<std::string>& requested,
                                     std::vector<GridField> available);

class FieldsFile {
public:
  /// Creates (truncates) `h5` and writes `xmf` beside it; with `collective`, on every one of
  /// its ranks (writes_collectively).
  FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf,
             const Ranks* collective = nullptr);
  /// Reopens the pair of an earlier run and keeps its first `keep_frames` frames (a restart).
  /// Throws InputError when the file is missing or has fewer frames.
  FieldsFile(const std::filesystem::path& h5, const std::filesystem::path& xmf, int keep_frames,
             const Ranks* collective = nullptr);
  ~FieldsFile();
  FieldsFile(const FieldsFile&) = delete;
  FieldsFile& operator=(const FieldsFile&) = delete;

  /// Declares a T6 mesh grid; connectivity is 6 node indices per element.
  void add_mesh(const std::string& grid, const std::vector<std::int64_t>& t6);
  /// Declares a T10 mesh grid: 10 node indices per element in Gmsh's order (structure_fem's
  /// shape_t10.hpp), stored in XDMF's Tetrahedron_10 order.
  void add_mesh_t10(const std::string& grid, const std::vector<std::int64_t>& t10);

  void begin_frame(double time);
  /// Writes one grid of the current frame: points (dim = 2 or 3 coordinates interleaved) and
  /// its fields. Collective: `rows` places this rank's points; without, rank 0's are written.
  void write_grid(const std::string& grid, const std::vector<double>& points,
                  const std::vector<GridField>& fields, int dim = 2,
                  const FileRows* rows = nullptr);
  /// Flushes the HDF5 file and rewrites the XDMF index.
  void end_frame();

  int frames() const { return static_cast<int>(frames_.size()); }

private:
  struct GridRecord {
    std::string grid;
    std::size_t points = 0;
    std::vector<std::pair<std::string, int>> fields;
    int dim = 2;
  };
  struct FrameRecord {
    double time = 0.0;
    std::vector<GridRecord> grids;
  };
  struct MeshRecord {
    std::string grid;
    std::size_t elements = 0;
    int nodes = 6; ///< 6 (T6) or 10 (T10)
  };
  void declare_mesh(const std::string& grid, const std::vector<std::int64_t>& connectivity,
                    int nodes);
  void write_xdmf() const;
  /// Runs `body` (a phase); after any exception the file is broken and every later call throws.
  template <class F> void guarded(F&& body);
  /// Runs `body`, one collective phase; collective, its success agreed over the ranks (agreed).
  template <class F> void phase(F&& body);
  /// The same in a constructor: on an exception the file is closed before it propagates.
  template <class F> void opened(F&& body);
  void close() noexcept;
  void ensure_vertices(std::size_t n);
  /// Opens the file's access: MPI-IO on every rank when collective.
  std::int64_t file_access() const;
  bool root() const;

  std::filesystem::path h5_path_, xmf_path_;
  const Ranks* ranks_ = nullptr; ///< collective over these ranks, or one process
  std::int64_t file_ = -1;
  std::int64_t frame_group_ = -1;
  std::vector<FrameRecord> frames_;
  std::vector<MeshRecord> meshes_;
  std::size_t vertices_ = 0;       ///< entries of /meshes/vertices
  std::uintmax_t frame_bytes_ = 0; ///< largest growth of fields.h5 by one frame
  std::uintmax_t frame_start_size_ = 0;
  bool broken_ = false;   ///< a write failed or a frame was refused: nothing more is written
  bool refused_ = false;  ///< a frame was refused for want of room (nothing of it written)
  bool poisoned_ = false; ///< a write failed inside HDF5 (see close())
  bool restarted_ = false;
};

/// Reads one float64 or int64 dataset back (tests, restart tools): values and dimensions.
struct Dataset {
  std::vector<double> values;
  std::vector<std::size_t> dims;
};
Dataset read_dataset(const std::filesystem::path& h5, const std::string& name);
double read_frame_time(const std::filesystem::path& h5, int frame);
/// The same from an open HDF5 file id.
double read_frame_time(const std::filesystem::path& h5, std::int64_t file, int frame);

} // namespace fsi::app
