#include "parallel/communicator.hpp"

namespace fsi::parallel {

namespace {
double collective_seconds_ = 0.0; // MPI calls come from one thread (MPI_THREAD_FUNNELED)

template <class T> T reduce(MPI_Comm comm, T v, MPI_Datatype type, MPI_Op op) {
  const CollectiveTimer timer;
  T out{};
  MPI_Allreduce(&v, &out, 1, type, op, comm);
  return out;
}
// value op, and the flag as max: {v, failed} (min: {v, -failed}).
Communicator::Flagged flagged(MPI_Comm comm, double v, bool failed, MPI_Op op) {
  const double sign = op == MPI_MIN ? -1.0 : 1.0;
  const double in[2] = {v, failed ? sign : 0.0};
  double out[2] = {0.0, 0.0};
  const CollectiveTimer timer;
  MPI_Allreduce(in, out, 2, MPI_DOUBLE, op, comm);
  return {out[0], out[1] != 0.0};
}
} // namespace

double collective_seconds() {
  return collective_seconds_;
}

CollectiveTimer::~CollectiveTimer() {
  collective_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

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

Communicator::Flagged Communicator::sum(double v, bool failed) const {
  return flagged(comm_, v, failed, MPI_SUM);
}
Communicator::Flagged Communicator::min(double v, bool failed) const {
  return flagged(comm_, v, failed, MPI_MIN);
}
Communicator::Flagged Communicator::max(double v, bool failed) const {
  return flagged(comm_, v, failed, MPI_MAX);
}

bool Communicator::sum(std::vector<double>& values, bool failed) const {
  values.push_back(failed ? 1.0 : 0.0);
  const CollectiveTimer timer;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  const bool any = values.back() != 0.0;
  values.pop_back();
  return any;
}

std::string Communicator::first_failure(const std::string& message, bool failed) const {
  const int first = reduce(comm_, failed ? rank_ : size_, MPI_INT, MPI_MIN);
  if (first == size_) return {}; // nobody failed: not called so
  return broadcast_text(message, first) + " (rank " + std::to_string(first) + " of " +
         std::to_string(size_) + ")";
}

std::string Communicator::first_message(const std::string& message, bool failed) const {
  const int first = reduce(comm_, failed ? rank_ : size_, MPI_INT, MPI_MIN);
  return first == size_ ? std::string() : broadcast_text(message, first);
}

std::string Communicator::broadcast_text(const std::string& message, int from) const {
  int length = rank_ == from ? static_cast<int>(message.size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, from, comm_);
  std::string text = rank_ == from ? message : std::string(static_cast<std::size_t>(length), ' ');
  MPI_Bcast(text.data(), length, MPI_CHAR, from, comm_);
  return text;
}

void Communicator::gather(const std::vector<double>& local, std::vector<double>& all) const {
  const CollectiveTimer timer;
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(counts.size(), 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = static_cast<int>(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  all.resize(rank_ == 0 ? total : 0);
  MPI_Gatherv(local.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
              MPI_DOUBLE, 0, comm_);
}

void Communicator::exchange(const std::vector<double>& send, const std::vector<int>& counts,
                            std::vector<double>& received) const {
  const CollectiveTimer timer;
  const auto n = static_cast<std::size_t>(size_);
  std::vector<int> from(n), send_at(n, 0), from_at(n, 0);
  MPI_Alltoall(counts.data(), 1, MPI_INT, from.data(), 1, MPI_INT, comm_);
  for (std::size_t r = 1; r < n; ++r) {
    send_at[r] = send_at[r - 1] + counts[r - 1];
    from_at[r] = from_at[r - 1] + from[r - 1];
  }
  received.resize(static_cast<std::size_t>(from_at[n - 1] + from[n - 1]));
  MPI_Alltoallv(send.data(), counts.data(), send_at.data(), MPI_DOUBLE, received.data(),
                from.data(), from_at.data(), MPI_DOUBLE, comm_);
}

} // namespace fsi::parallel
