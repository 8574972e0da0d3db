#pragma once
// interface.h5: the interface history of a coupled run, one row per coupling step, for the
// one-way verification modes (fluid against a recorded motion, structure under recorded loads)
// and for the loads per point. D = 2 or 3 (BasicInterfaceHistoryWriter<D>,
// BasicInterfaceHistory<D>).
//
// HDF5 layout, n interface nodes, N rows (row 0 is the initial state at t = 0, loads zero):
//   /time          float64 [N]        s, strictly increasing
//   /position      float64 [N x n x D] m    the wall motion the fluid used for the step ending
//   /velocity      float64 [N x n x D] m/s  at time[k] (for css without predictor: the structure
//   /acceleration  float64 [N x n x D] m/s^2 at the step's start, eqs. 60-62)
//   /load          float64 [N x n x D] N/m (2-D), N (3-D): the loads the structure took for that
//                                      step (eq. 59)
//   /faces         int64 [m x 6]      3-D only: the interfaces' 6-node faces, node indices into
//                                      the rows (corners, then mid-sides 0-1, 1-2, 2-0: XDMF's
//                                      Triangle_6), the structures in scene order
// Datasets are chunked and extendible; rows are appended and the file flushed every
// kFlushRows rows and by flush().
#include "coupling/interface.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::app {

template <int D> class BasicInterfaceHistoryWriter {
public:
  static constexpr int kFlushRows = 100;
  using Faces = std::vector<std::array<std::size_t, 6>>;
  /// Creates (truncates) `h5` for `nodes` interface nodes (3-D: and its `faces`; none in 2-D);
  /// throws RunError if it cannot.
  BasicInterfaceHistoryWriter(const std::filesystem::path& h5, std::size_t nodes,
                              const Faces& faces = {});
  ~BasicInterfaceHistoryWriter();
  BasicInterfaceHistoryWriter(const BasicInterfaceHistoryWriter&) = delete;
  BasicInterfaceHistoryWriter& operator=(const BasicInterfaceHistoryWriter&) = delete;

  void append(double time, const coupling::BasicInterfaceMotion<D>& motion,
              const coupling::BasicInterfaceLoads<D>& loads);
  /// Flushes the rows appended so far to disk.
  void flush();

private:
  void append_rows(std::int64_t set, const std::vector<VecD<D>>& values);

  std::filesystem::path path_;
  std::size_t nodes_;
  std::int64_t file_ = -1;
  std::int64_t time_ = -1, position_ = -1, velocity_ = -1, acceleration_ = -1, load_ = -1;
  std::uint64_t rows_ = 0;
};

/// A recorded interface.h5 opened for replay: motion and loads linearly interpolated in time
/// (exact at the recorded times). Rows are read on demand (two kept).
template <int D> class BasicInterfaceHistory {
public:
  /// Opens and validates the layout above; throws InputError with a bare message (no location).
  explicit BasicInterfaceHistory(const std::filesystem::path& h5);
  ~BasicInterfaceHistory();
  BasicInterfaceHistory(const BasicInterfaceHistory&) = delete;
  BasicInterfaceHistory& operator=(const BasicInterfaceHistory&) = delete;

  std::size_t nodes() const { return nodes_; }
  double first_time() const { return time_.front(); }
  double last_time() const { return time_.back(); }
  /// Throw RunError for t outside [first_time, last_time].
  coupling::BasicInterfaceMotion<D> motion_at(double t);
  coupling::BasicInterfaceLoads<D> loads_at(double t);

private:
  struct Row {
    std::size_t index = 0;
    coupling::BasicInterfaceMotion<D> motion;
    coupling::BasicInterfaceLoads<D> loads;
  };
  /// Rows bracketing t and the weight s of the later one.
  void bracket(double t, const Row*& a, const Row*& b, double& s);
  /// Row k, read into a cache slot that does not hold row `keep`.
  const Row& row(std::size_t k, std::size_t keep);

  std::filesystem::path path_;
  std::int64_t file_ = -1;
  std::vector<double> time_;
  std::size_t nodes_ = 0;
  std::array<Row, 2> cache_;
  std::array<bool, 2> filled_ = {false, false};
};

extern template class BasicInterfaceHistoryWriter<2>;
extern template class BasicInterfaceHistoryWriter<3>;
extern template class BasicInterfaceHistory<2>;
extern template class BasicInterfaceHistory<3>;
using InterfaceHistoryWriter = BasicInterfaceHistoryWriter<2>;
using InterfaceHistoryWriter3 = BasicInterfaceHistoryWriter<3>;
using InterfaceHistory = BasicInterfaceHistory<2>;
using InterfaceHistory3 = BasicInterfaceHistory<3>;

} // namespace fsi::app
