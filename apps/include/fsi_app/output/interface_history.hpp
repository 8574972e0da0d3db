#pragma once
// interface.h5: the interface history of a coupled run, one row per coupling step, for the
// one-way verification modes (fluid against a recorded motion, structure under recorded loads).
//
// HDF5 layout, n interface nodes, N rows (row 0 is the initial state at t = 0, loads zero):
//   /time          float64 [N]        s, strictly increasing
//   /position      float64 [N x n x 2] m    the wall motion the fluid used for the step ending
//   /velocity      float64 [N x n x 2] m/s  at time[k] (for css without predictor: the structure
//   /acceleration  float64 [N x n x 2] m/s^2 at the step's start, eqs. 60-62)
//   /load          float64 [N x n x 2] N/m  the loads the structure took for that step (eq. 59)
// Datasets are chunked and extendible; rows are appended and the file flushed every
// kFlushRows rows and on close.
#include "coupling/interface.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::app {

class InterfaceHistoryWriter {
public:
  static constexpr int kFlushRows = 100;
  /// Creates (truncates) `h5` for `nodes` interface nodes; throws RunError if it cannot.
  InterfaceHistoryWriter(const std::filesystem::path& h5, std::size_t nodes);
  ~InterfaceHistoryWriter();
  InterfaceHistoryWriter(const InterfaceHistoryWriter&) = delete;
  InterfaceHistoryWriter& operator=(const InterfaceHistoryWriter&) = delete;

  void append(double time, const coupling::InterfaceMotion& motion,
              const coupling::InterfaceLoads& loads);

private:
  void append_rows(std::int64_t set, const std::vector<Vec2>& values);

  std::filesystem::path path_;
  std::size_t nodes_;
  std::int64_t file_ = -1;
  std::int64_t time_ = -1, position_ = -1, velocity_ = -1, acceleration_ = -1, load_ = -1;
  std::uint64_t rows_ = 0;
};

/// A recorded interface.h5 opened for replay: motion and loads linearly interpolated in time
/// (exact at the recorded times). Rows are read on demand (two kept).
class InterfaceHistory {
public:
  /// Opens and validates the layout above; throws InputError with a bare message (no location).
  explicit InterfaceHistory(const std::filesystem::path& h5);
  ~InterfaceHistory();
  InterfaceHistory(const InterfaceHistory&) = delete;
  InterfaceHistory& operator=(const InterfaceHistory&) = delete;

  std::size_t nodes() const { return nodes_; }
  double first_time() const { return time_.front(); }
  double last_time() const { return time_.back(); }
  /// Throw RunError for t outside [first_time, last_time].
  coupling::InterfaceMotion motion_at(double t);
  coupling::InterfaceLoads loads_at(double t);

private:
  struct Row {
    std::size_t index = 0;
    coupling::InterfaceMotion motion;
    coupling::InterfaceLoads loads;
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

} // namespace fsi::app
