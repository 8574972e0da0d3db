#include "parallel/rcb_partition.hpp"

#include <zoltan.h>

#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fsi::parallel {

namespace {

// What Zoltan's query functions see: the local particles, numbered from `offset` globally, and
// their weights (empty: 1 each).
template <int D> struct Points {
  particles::Coords<D> x;
  std::size_t n = 0;
  std::span<const float> weight;
  ZOLTAN_ID_TYPE offset = 0;
};

template <int D> int count(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<Points<D>*>(data)->n);
}

template <int D>
void list(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int, float* weights,
          int* ierr) {
  const auto& p = *static_cast<Points<D>*>(data);
  for (std::size_t i = 0; i < p.n; ++i) {
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    gids[i] = p.offset + static_cast<ZOLTAN_ID_TYPE>(i);
    weights[i] = p.weight.empty() ? 1.0f : p.weight[i]; // OBJ_WEIGHT_DIM 1: one a particle
  }
  *ierr = ZOLTAN_OK;
}

template <int D> int dimension(void*, int* ierr) {
  return *ierr = ZOLTAN_OK, D;
}

template <int D>
void geometry(void* data, int, int, int n, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int, double* out,
              int* ierr) {
  const auto& p = *static_cast<Points<D>*>(data);
  for (int k = 0; k < n; ++k)
    for (std::size_t a = 0; a < D; ++a) out[static_cast<std::size_t>(k) * D + a] = p.x[a][lids[k]];
  *ierr = ZOLTAN_OK;
}

void check(int code, const char* what) {
  if (code != ZOLTAN_OK && code != ZOLTAN_WARN)
    throw std::runtime_error(std::string("Zoltan: ") + what + " failed");
}

// Zoltan_RCB_Box reports an unbounded side as ±DBL_MAX: stored as ±infinity.
double unbounded(double v) {
  constexpr double big = std::numeric_limits<double>::max();
  return v >= big    ? std::numeric_limits<double>::infinity()
         : v <= -big ? -std::numeric_limits<double>::infinity()
                     : v;
}

} // namespace

template <int D>
RcbPartition<D>::RcbPartition(const Communicator& comm, double tolerance) : comm_(comm) {
  static const bool initialised = [] {
    float version = 0;
    return Zoltan_Initialize(0, nullptr, &version) == ZOLTAN_OK;
  }();
  if (!initialised) throw std::runtime_error("Zoltan: Zoltan_Initialize failed");
  zz_ = Zoltan_Create(comm.comm());
  const std::string tol = std::to_string(tolerance);
  const std::initializer_list<std::pair<const char*, const char*>> params = {
      {"DEBUG_LEVEL", "0"}, // first: setting LB_METHOD at level 1 prints it
      {"LB_METHOD", "RCB"},
      {"NUM_GID_ENTRIES", "1"},
      {"NUM_LID_ENTRIES", "1"},
      {"OBJ_WEIGHT_DIM", "1"}, // a weight per particle, its load
      {"RETURN_LISTS", "EXPORT"},
      {"KEEP_CUTS", "1"}, // for owners() and the boxes
      {"RCB_REUSE", "1"}, // a repartition starts from the previous cuts
      {"IMBALANCE_TOL", tol.c_str()}};
  for (const auto& [key, value] : params) check(Zoltan_Set_Param(zz_, key, value), key);
  Zoltan_Set_Num_Obj_Fn(zz_, count<D>, nullptr);
  Zoltan_Set_Obj_List_Fn(zz_, list<D>, nullptr);
  Zoltan_Set_Num_Geom_Fn(zz_, dimension<D>, nullptr);
  Zoltan_Set_Geom_Multi_Fn(zz_, geometry<D>, nullptr);
}

template <int D> RcbPartition<D>::~RcbPartition() {
  Zoltan_Destroy(&zz_);
}

template <int D>
void RcbPartition<D>::partition(const particles::Coords<D>& x, std::size_t n,
                                std::span<const float> weight, std::vector<int>& dest) {
  Points<D> points{x, n, weight, 0};
  auto local = static_cast<unsigned long>(n), offset = 0ul;
  MPI_Exscan(&local, &offset, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm_.comm());
  points.offset = comm_.rank() == 0 ? 0 : static_cast<ZOLTAN_ID_TYPE>(offset);
  // The query functions read `points` during this call only.
  Zoltan_Set_Num_Obj_Fn(zz_, count<D>, &points);
  Zoltan_Set_Obj_List_Fn(zz_, list<D>, &points);
  Zoltan_Set_Geom_Multi_Fn(zz_, geometry<D>, &points);

  int changes = 0, gid_entries = 0, lid_entries = 0, n_import = 0, n_export = 0;
  ZOLTAN_ID_PTR import_gids = nullptr, import_lids = nullptr;
  ZOLTAN_ID_PTR export_gids = nullptr, export_lids = nullptr;
  int *import_procs = nullptr, *import_parts = nullptr;
  int *export_procs = nullptr, *export_parts = nullptr;
  check(Zoltan_LB_Partition(zz_, &changes, &gid_entries, &lid_entries, &n_import, &import_gids,
                            &import_lids, &import_procs, &import_parts, &n_export, &export_gids,
                            &export_lids, &export_procs, &export_parts),
        "Zoltan_LB_Partition");
  Zoltan_Set_Num_Obj_Fn(zz_, count<D>, nullptr); // `points` ends with this call
  Zoltan_Set_Obj_List_Fn(zz_, list<D>, nullptr);
  Zoltan_Set_Geom_Multi_Fn(zz_, geometry<D>, nullptr);
  dest.assign(n, comm_.rank());
  for (int k = 0; k < n_export; ++k) dest[export_lids[k]] = export_procs[k];
  Zoltan_LB_Free_Part(&import_gids, &import_lids, &import_procs, &import_parts);
  Zoltan_LB_Free_Part(&export_gids, &export_lids, &export_procs, &export_parts);

  // Zoltan_RCB_Box answers a zero box when there is no cut (one rank): all space instead.
  constexpr double inf = std::numeric_limits<double>::infinity();
  boxes_.assign(static_cast<std::size_t>(comm_.size()),
                {VecD<D>::Constant(-inf), VecD<D>::Constant(inf)});
  for (int r = 0; r < comm_.size() && comm_.size() > 1; ++r) {
    int ndim = 0;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    check(Zoltan_RCB_Box(zz_, r, &ndim, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]),
          "Zoltan_RCB_Box");
    auto& box = boxes_[static_cast<std::size_t>(r)];
    for (int a = 0; a < D; ++a) box.lo[a] = unbounded(lo[a]), box.hi[a] = unbounded(hi[a]);
  }
  ++partitions_;
}

template <int D>
void RcbPartition<D>::owners(const particles::Coords<D>& x, std::size_t n,
                             std::vector<int>& dest) const {
  dest.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    double p[3] = {0, 0, 0};
    for (std::size_t a = 0; a < D; ++a) p[a] = x[a][i];
    int proc = 0, part = 0;
    check(Zoltan_LB_Point_PP_Assign(zz_, p, &proc, &part), "Zoltan_LB_Point_PP_Assign");
    dest[i] = part; // one part per rank: the part is the rank
  }
}

double imbalance(const Communicator& comm, double load) {
  const double total = comm.sum(load), largest = comm.max(load);
  if (total == 0.0) return 1.0;
  return largest * comm.size() / total;
}

template class RcbPartition<2>;
template class RcbPartition<3>;

} // namespace fsi::parallel
