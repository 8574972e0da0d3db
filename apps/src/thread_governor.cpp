#include "fsi_app/thread_governor.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace fsi::app {

namespace {

/// The median of at most kWindow step times (a copy on the stack: no allocation per step).
double median(const std::vector<double>& steps) {
  std::array<double, ThreadGovernor::kWindow> v{};
  const auto end = std::copy(steps.begin(), steps.end(), v.begin());
  const auto mid = v.begin() + (end - v.begin()) / 2;
  std::nth_element(v.begin(), mid, end);
  return *mid;
}

} // namespace

ThreadGovernor::ThreadGovernor(int most)
    : most_(most), current_(most), steps_at_(static_cast<std::size_t>(std::max(most, 1)), 0) {
  if (most < 1) throw std::invalid_argument("ThreadGovernor: most < 1");
  reference_.reserve(kWindow);
  window_.reserve(kWindow);
}

void ThreadGovernor::record(double seconds) {
  ++steps_at_[static_cast<std::size_t>(threads() - 1)];
  if (most_ == 1) return;
  if (trial_) {
    window_.push_back(seconds);
    if (seconds > kAbort * median(reference_) || static_cast<int>(window_.size()) == kWindow)
      end_trial();
    return;
  }
  if (static_cast<int>(reference_.size()) == kWindow) reference_.erase(reference_.begin());
  reference_.push_back(seconds);
  if (++since_trial_ >= period_ && static_cast<int>(reference_.size()) == kWindow) start_trial();
}

void ThreadGovernor::start_trial() {
  // One thread fewer or more: down from the most, up from one, else alternately.
  trial_upward_ = current_ == 1 || (current_ < most_ && !trial_upward_);
  trial_threads_ = current_ + (trial_upward_ ? 1 : -1);
  trial_ = true;
  ++trials_;
  since_trial_ = 0;
  window_.clear();
}

void ThreadGovernor::end_trial() {
  trial_ = false;
  since_trial_ = 0;
  if (static_cast<int>(window_.size()) == kWindow &&
      median(window_) < (1.0 - kMargin) * median(reference_)) {
    current_ = trial_threads_;
    ++switches_;
    period_ = kFirstPeriod;
    reference_ = window_; // the new count's figure, measured
  } else {
    period_ = std::clamp(2 * period_, kFirstPeriod, kLongestPeriod);
  }
}

JsonObject ThreadGovernor::report() const {
  std::string steps = "[";
  for (std::size_t n = 0; n < steps_at_.size(); ++n)
    steps += (n ? ", " : "") + std::to_string(steps_at_[n]);
  JsonObject j;
  j.add("switches", static_cast<long long>(switches_))
      .add("trials", static_cast<long long>(trials_))
      .add_raw("steps_at", steps + "]");
  return j;
}

} // namespace fsi::app
