#include "fsi_app/progress.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace fsi::app {

namespace {
double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
} // namespace

Progress::Progress(double end_time, bool terminal, std::ostream& out, long first_step,
                   double first_time)
    : end_(end_time), first_step_(first_step), first_time_(first_time), terminal_(terminal),
      out_(out), start_(std::chrono::steady_clock::now()), last_(start_) {}

std::string Progress::line(double time, long steps) const {
  const double wall = seconds(std::chrono::steady_clock::now() - start_);
  // Progress in [0, 100] %, an ETA that is never negative and says "unknown" rather than
  // overflowing (a step so small that the end is out of reach).
  const double fraction = end_ > 0 ? std::clamp(time / end_, 0.0, 1.0) : 1.0;
  const double rate = wall > 0 ? static_cast<double>(steps - first_step_) / wall : 0.0;
  const double done = time - first_time_;
  const double eta = done > 0 ? std::max(0.0, wall * (end_ - time) / done) : 0.0;
  char eta_text[48];
  if (!(eta < 1e7)) // about 116 days
    std::snprintf(eta_text, sizeof eta_text, "ETA > 100 days");
  else
    std::snprintf(eta_text, sizeof eta_text, "ETA %lldm%02llds", static_cast<long long>(eta) / 60,
                  static_cast<long long>(eta) % 60);
  char buf[200];
  std::snprintf(buf, sizeof buf, "t = %.5g s  %5.1f %%  %.0f steps/s  %s", time, 100.0 * fraction,
                rate, eta_text);
  return buf;
}

void Progress::update(double time, long steps) {
  const auto now = std::chrono::steady_clock::now();
  const double since = seconds(now - last_);
  if (since < (terminal_ ? 0.2 : 5.0)) return;
  last_ = now;
  if (terminal_)
    out_ << '\r' << line(time, steps) << "   " << std::flush;
  else
    out_ << "progress: " << line(time, steps) << '\n' << std::flush;
}

void Progress::finish(double time, long steps) {
  if (terminal_) out_ << '\r';
  out_ << "done: " << line(time, steps) << '\n' << std::flush;
}

} // namespace fsi::app
