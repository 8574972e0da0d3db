// Checkpoint/restart and save/restore continue bitwise; two threads give the sequential run.
#include <catch2/catch.hpp>

#include <cstring>

#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"
#include "plate.hpp"

using namespace tlsph_test;

namespace {

bool same_bits(const TlsphSolid& a, const TlsphSolid& b) {
  if (a.size() != b.size() || a.step() != b.step()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 xa = a.position(i), xb = b.position(i), va = a.velocity(i), vb = b.velocity(i);
    if (std::memcmp(xa.data(), xb.data(), sizeof(double) * 2) != 0) return false;
    if (std::memcmp(va.data(), vb.data(), sizeof(double) * 2) != 0) return false;
  }
  return a.time() == b.time();
}

/// The plate at H/dp = 4 with a tip load on the interface, damping on (every term active).
std::unique_ptr<TlsphSolid> loaded_plate(bool paper = false) {
  const Beam b = paper ? plate(4).paper() : plate(4);
  auto o = beam_options(b);
  o.pair_damping = 0.1, o.mass_damping = 0.5, o.gravity = {0.0, -9.81};
  auto s = plate_solid(b, 0.01, o);
  s->set_interface_loads(std::vector<Vec2>(s->interface_particles().size(), Vec2(0.0, -0.2)));
  return s;
}

} // namespace

TEST_CASE("tlsph: checkpoint and save/restore continue bitwise", "[solid_tlsph][restart]") {
  auto a = loaded_plate();
  a->advance(0.0, 0.02);
  fsi::StateArchive archive;
  a->write_state(archive, "structure/plate/");
  const auto saved = a->save();
  a->advance(a->time(), 0.02);

  auto b = loaded_plate(); // a fresh solid from the same scene, then the checkpoint
  b->read_state(archive, "structure/plate/");
  b->advance(b->time(), 0.02);
  CHECK(a->step() > 100);
  CHECK(same_bits(*a, *b));

  auto c = loaded_plate();
  c->advance(0.0, 0.02);
  c->advance(c->time(), 0.01);
  c->restore(saved);
  c->advance(c->time(), 0.02);
  CHECK(same_bits(*a, *c));

  // Another particle count is an InputError naming the key.
  const Beam fine = plate(6);
  TlsphSolid other(beam_geometry(fine), beam_options(fine));
  CHECK_THROWS_WITH(other.read_state(archive, "structure/plate/"),
                    Catch::Contains("structure/plate/particles/x"));
}

TEST_CASE("tlsph: two threads give the sequential run bitwise", "[solid_tlsph][threads]") {
  REQUIRE(fsi::num_threads() >= 2); // OMP_NUM_THREADS=1 would make this test empty
  fsi::set_sequential(true);
  auto a = loaded_plate();
  a->advance(0.0, 0.02);
  fsi::set_sequential(false);
  auto b = loaded_plate();
  b->advance(0.0, 0.02);
  CHECK(same_bits(*a, *b));
}

TEST_CASE("tlsph: restore then new loads equals a run with those loads (iterative coupling)",
          "[solid_tlsph][restart]") {
  const std::vector<Vec2> first(loaded_plate()->interface_particles().size(), Vec2(0.1, -0.3));
  const std::vector<Vec2> second(first.size(), Vec2(-0.2, 0.4));
  auto a = loaded_plate();
  a->advance(0.0, 0.01);
  const auto saved = a->save();
  a->set_interface_loads(first); // a rejected coupling iterate
  a->advance(a->time(), 0.01);
  a->restore(saved);
  a->set_interface_loads(second);
  a->advance(a->time(), 0.01);

  auto b = loaded_plate();
  b->advance(0.0, 0.01);
  b->set_interface_loads(second);
  b->advance(b->time(), 0.01);
  CHECK(same_bits(*a, *b));
}

TEST_CASE("tlsph paper form: checkpoint continues bitwise, two threads give the sequential run",
          "[solid_tlsph][threads][restart][paper]") {
  auto a = loaded_plate(true);
  a->advance(0.0, 0.01);
  fsi::StateArchive archive;
  a->write_state(archive, "solid/");
  a->advance(a->time(), 0.01);
  auto b = loaded_plate(true);
  b->read_state(archive, "solid/");
  b->advance(b->time(), 0.01);
  CHECK(same_bits(*a, *b));
  REQUIRE(fsi::num_threads() >= 2);
  fsi::set_sequential(true);
  auto c = loaded_plate(true);
  c->advance(0.0, 0.01);
  c->advance(c->time(), 0.01);
  fsi::set_sequential(false);
  CHECK(same_bits(*a, *c));
}
