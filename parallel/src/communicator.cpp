#include "parallel/communicator.hpp"

namespace fsi::parallel {

namespace {
template <class T> T reduce(MPI_Comm comm, T v, MPI_Datatype type, MPI_Op op) {
  T out{};
  MPI_Allreduce(&v, &out, 1, type, op, comm);
  return out;
}
} // namespace

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

double Communicator::sum(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_SUM);
}
double Communicator::min(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_MIN);
}
double Communicator::max(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_MAX);
}
std::int64_t Communicator::sum(std::int64_t v) const {
  return reduce(comm_, v, MPI_INT64_T, MPI_SUM);
}
std::int64_t Communicator::min(std::int64_t v) const {
  return reduce(comm_, v, MPI_INT64_T, MPI_MIN);
}
std::int64_t Communicator::max(std::int64_t v) const {
  return reduce(comm_, v, MPI_INT64_T, MPI_MAX);
}
bool Communicator::all(bool v) const {
  return reduce(comm_, v ? 1 : 0, MPI_INT, MPI_LAND) != 0;
}

} // namespace fsi::parallel
