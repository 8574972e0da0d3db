// Halo (ghost) particles under MPI: the ghost set of every rank against a brute-force search
// over every particle, and update() refreshing the ghosts bit for bit.
#include "cloud.hpp"
#include "parallel/halo.hpp"
#include "parallel/migration.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

using namespace fsi;
using namespace fsi::parallel;
using namespace fsi::parallel::test;

namespace {

constexpr std::uint32_t halo_cloud_size = 3000;

/// Distance from p to the box [lo, hi], written out (not Box::distance).
template <int D> double box_distance(const Box<D>& b, const VecD<D>& p) {
  double d2 = 0;
  for (int a = 0; a < D; ++a) {
    const double out = p[a] < b.lo[a] ? b.lo[a] - p[a] : p[a] > b.hi[a] ? p[a] - b.hi[a] : 0.0;
    d2 += out * out;
  }
  return std::sqrt(d2);
}

/// The new value of the mass the owners write before an update.
double changed_mass(std::uint32_t g) {
  return 3.0 * mass(g) + 1e-3 * g;
}

} // namespace

TEMPLATE_TEST_CASE("Halo particles are exactly the other ranks' particles near the region",
                   "[parallel]", (std::integral_constant<int, 2>),
                   (std::integral_constant<int, 3>)) {
  constexpr int D = TestType::value;
  const double r_halo = D == 2 ? 0.06 : 0.1; // interaction radius + skin
  const Communicator comm;
  const auto me = static_cast<std::size_t>(comm.rank());
  Cloud<D> c(halo_cloud_size, comm.rank(), comm.size());
  RcbPartition<D> rcb(comm);
  Migration migration;
  Halo<D> halo;
  std::vector<int> dest;
  rcb.partition(c.x.coords(), c.size(), {}, dest);
  migration.migrate(comm, c.fields, dest);
  const std::size_t owned = c.size();
  const auto owner = owners_of(comm, c.id, owned, halo_cloud_size);

  halo.build(comm, c.fields, c.x, rcb.boxes(), r_halo);
  CHECK(halo.owned() == owned);
  CHECK(c.size() == owned + halo.ghosts());

  // Brute force: every particle (its reference position) of another rank near my box.
  const Box<D>& mine = rcb.boxes()[me];
  std::vector<std::uint32_t> expected;
  for (std::uint32_t g = 0; g < halo_cloud_size; ++g) {
    VecD<D> p;
    for (int a = 0; a < D; ++a) p[a] = position<D>(g, a);
    if (owner[g] != comm.rank() && box_distance(mine, p) <= r_halo) expected.push_back(g);
  }
  std::vector<std::uint32_t> got(c.id.begin() + static_cast<std::ptrdiff_t>(owned), c.id.end());
  // Ordered by owner rank, then by the index on the owner.
  std::vector<int> index_on_owner(halo_cloud_size, 0);
  for (std::size_t i = 0; i < owned; ++i) index_on_owner[c.id[i]] = static_cast<int>(i);
  MPI_Allreduce(MPI_IN_PLACE, index_on_owner.data(), halo_cloud_size, MPI_INT, MPI_SUM,
                comm.comm());
  bool ordered = true;
  for (std::size_t k = 1; k < got.size(); ++k) {
    const std::uint32_t a = got[k - 1], b = got[k];
    ordered = ordered && (owner[a] < owner[b] ||
                          (owner[a] == owner[b] && index_on_owner[a] < index_on_owner[b]));
  }
  std::sort(got.begin(), got.end());
  CHECK(comm.all(got == expected));
  CHECK(comm.all(ordered));
  CHECK(comm.all(std::all_of(owner.begin(), owner.end(), [](int r) { return r >= 0; })));

  // The ghosts carry their owners' values of every field, bit for bit.
  bool copied = true;
  for (std::size_t i = owned; i < c.size(); ++i) {
    const std::uint32_t g = c.id[i];
    for (int a = 0; a < D; ++a) copied = copied && c.x[a][i] == position<D>(g, a);
    copied = copied && c.m[i] == mass(g) && c.flag[i] == tag(g);
  }
  CHECK(comm.all(copied));

  // Owners change two fields; update() refreshes the ghosts in place, same order.
  for (std::size_t i = 0; i < owned; ++i)
    c.m[i] = changed_mass(c.id[i]), c.flag[i] = static_cast<std::uint8_t>(c.flag[i] + 1);
  const std::vector<std::uint32_t> ids_before(c.id.begin(), c.id.end());
  halo.update(comm, c.fields);
  bool updated = std::equal(ids_before.begin(), ids_before.end(), c.id.begin());
  for (std::size_t i = owned; i < c.size(); ++i)
    updated = updated && c.m[i] == changed_mass(c.id[i]) && c.flag[i] == tag(c.id[i]) + 1;
  CHECK(comm.all(updated));

  const auto ghosts = comm.sum(static_cast<std::int64_t>(halo.ghosts()));
  CHECK(comm.sum(static_cast<std::int64_t>(halo.sent())) == ghosts);
  if (comm.rank() == 0)
    std::printf("halo D=%d np=%d: r_halo %.2f, %lld ghosts for %u particles (%.1f %%)\n", D,
                comm.size(), r_halo, static_cast<long long>(ghosts), halo_cloud_size,
                100.0 * ghosts / halo_cloud_size);

  // Ghosts dropped, the owned set migrates as before.
  halo.drop(c.fields);
  CHECK(comm.sum(static_cast<std::int64_t>(c.size())) == halo_cloud_size);
}
