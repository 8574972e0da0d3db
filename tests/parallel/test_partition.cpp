// Partition (Zoltan RCB), migration and the global reductions, under MPI on any rank count:
// every check is on values reduced over all ranks, so every rank asserts the same thing.
#include "cloud.hpp"
#include "parallel/migration.hpp"
#include "parallel/rcb_partition.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <type_traits>

using namespace fsi;
using namespace fsi::parallel;
using namespace fsi::parallel::test;

namespace {

constexpr std::uint32_t partition_cloud_size = 4000;

template <int D> std::uint32_t xor_of(const std::vector<std::uint32_t>& id, std::size_t n) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v ^= id[i];
  return v;
}

/// Every id 0..partition_cloud_size-1 held by exactly one rank, the count, the id sum and xor
/// exact.
template <int D> bool ids_conserved(const Communicator& comm, const Cloud<D>& c) {
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < c.size(); ++i) sum += c.id[i];
  std::uint32_t x = xor_of<D>(c.id, c.size()), all_x = 0, expect_x = 0;
  MPI_Allreduce(&x, &all_x, 1, MPI_UINT32_T, MPI_BXOR, comm.comm());
  for (std::uint32_t g = 0; g < partition_cloud_size; ++g) expect_x ^= g;
  const auto owner = owners_of(comm, c.id, c.size(), partition_cloud_size);
  const bool each_once = std::none_of(owner.begin(), owner.end(), [](int r) { return r < 0; });
  return comm.sum(static_cast<std::int64_t>(c.size())) == partition_cloud_size &&
         comm.sum(sum) == std::int64_t{partition_cloud_size} * (partition_cloud_size - 1) / 2 &&
         all_x == expect_x && each_once;
}

/// Every field of every local particle equals its reference (positions moved by `steps`
/// displacements), bit for bit, and the particle lies in this rank's box.
template <int D>
bool fields_exact(const Communicator& comm, const Cloud<D>& c, const std::vector<Box<D>>& boxes,
                  int steps) {
  bool ok = true;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const std::uint32_t g = c.id[i];
    for (int a = 0; a < D; ++a) {
      double xa = position<D>(g, a);
      for (int s = 0; s < steps; ++s) xa += displacement(g, a, s);
      ok = ok && c.x[a][i] == xa;
    }
    ok = ok && c.m[i] == mass(g) && c.flag[i] == tag(g);
    ok = ok && boxes[static_cast<std::size_t>(comm.rank())].contains(c.at(i));
  }
  return comm.all(ok);
}

template <int D> void displace(Cloud<D>& c, int step) {
  for (std::size_t i = 0; i < c.size(); ++i)
    for (int a = 0; a < D; ++a) c.x[a][i] += displacement(c.id[i], a, step);
}

} // namespace

TEMPLATE_TEST_CASE("RCB partition and migration keep every particle and field exactly",
                   "[parallel]", (std::integral_constant<int, 2>),
                   (std::integral_constant<int, 3>)) {
  constexpr int D = TestType::value;
  const Communicator comm;
  Cloud<D> c(partition_cloud_size, comm.rank(), comm.size());
  RcbPartition<D> rcb(comm, 1.01);
  Migration migration;
  std::vector<int> dest;

  rcb.partition(c.x.coords(), c.size(), {}, dest);
  migration.migrate(comm, c.fields, dest);
  REQUIRE(rcb.boxes().size() == static_cast<std::size_t>(comm.size()));
  CHECK(ids_conserved(comm, c));
  CHECK(fields_exact(comm, c, rcb.boxes(), 0));
  const double first = imbalance(comm, static_cast<double>(c.size()));
  CHECK(first <= 1.01); // the tolerance asked of RCB (measured: 1.0000 at np = 4, 1.0005 at 3)
  CHECK(first >= 1.0);

  // Two random displacements of up to 0.05 per axis, each followed by a migration to the
  // owners under the unchanged cuts (the LAMMPS way: no repartition).
  for (int step = 0; step < 2; ++step) {
    displace(c, step);
    rcb.owners(c.x.coords(), c.size(), dest);
    migration.migrate(comm, c.fields, dest);
    CHECK(ids_conserved(comm, c));
    CHECK(fields_exact(comm, c, rcb.boxes(), step + 1));
  }
  const double drifted = imbalance(comm, static_cast<double>(c.size()));

  // A repartition from the previous cuts (RCB_REUSE): balanced again, few particles move.
  rcb.partition(c.x.coords(), c.size(), {}, dest);
  std::int64_t moving = 0;
  for (const int r : dest) moving += r != comm.rank() ? 1 : 0;
  moving = comm.sum(moving);
  migration.migrate(comm, c.fields, dest);
  CHECK(ids_conserved(comm, c));
  CHECK(fields_exact(comm, c, rcb.boxes(), 2));
  const double again = imbalance(comm, static_cast<double>(c.size()));
  CHECK(again <= 1.01);
  CHECK(rcb.partitions() == 2);
  CHECK(moving <= partition_cloud_size /
                      20); // incremental: most stay (measured: 8 to 31 of 4000 at np = 3, 4)
  if (comm.rank() == 0)
    std::printf("rcb D=%d np=%d: imbalance %.4f, after drift %.4f, repartitioned %.4f moving "
                "%lld of %u\n",
                D, comm.size(), first, drifted, again, static_cast<long long>(moving),
                partition_cloud_size);
}

TEMPLATE_TEST_CASE("Global reductions equal the serial values", "[parallel]",
                   (std::integral_constant<int, 2>), (std::integral_constant<int, 3>)) {
  constexpr int D = TestType::value;
  const Communicator comm;
  Cloud<D> c(partition_cloud_size, comm.rank(), comm.size());
  RcbPartition<D> rcb(comm);
  Migration migration;
  std::vector<int> dest;
  rcb.partition(c.x.coords(), c.size(), {}, dest);
  migration.migrate(comm, c.fields, dest);

  // Serial references from the ids alone, summed in id order.
  double m_sum = 0, x_min = 1e300, x_max = -1e300;
  std::int64_t id_sum = 0;
  for (std::uint32_t g = 0; g < partition_cloud_size; ++g) {
    m_sum += mass(g), id_sum += g;
    x_min = std::min(x_min, position<D>(g, D - 1)), x_max = std::max(x_max, position<D>(g, D - 1));
  }
  double local_m = 0, local_min = 1e300, local_max = -1e300;
  std::int64_t local_id = 0, local_id_min = partition_cloud_size, local_id_max = -1;
  for (std::size_t i = 0; i < c.size(); ++i) {
    local_m += c.m[i], local_id += c.id[i];
    local_min = std::min(local_min, c.x[D - 1][i]), local_max = std::max(local_max, c.x[D - 1][i]);
    local_id_min = std::min<std::int64_t>(local_id_min, c.id[i]);
    local_id_max = std::max<std::int64_t>(local_id_max, c.id[i]);
  }
  // A sum of partition_cloud_size doubles in another order: within partition_cloud_size ulps of the
  // sum (each term in [1, 2)).
  CHECK_THAT(comm.sum(local_m), Catch::Matchers::WithinRel(m_sum, partition_cloud_size * 2.3e-16));
  CHECK(comm.min(local_min) == x_min);
  CHECK(comm.max(local_max) == x_max);
  CHECK(comm.sum(local_id) == id_sum);
  CHECK(comm.min(local_id_min) == 0);
  CHECK(comm.max(local_id_max) == partition_cloud_size - 1);
  CHECK(comm.all(comm.rank() >= 0));
  CHECK_FALSE(comm.all(comm.rank() != comm.size() - 1));
}
