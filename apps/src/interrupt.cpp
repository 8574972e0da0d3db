#include "fsi_app/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <fcntl.h>
#include <mutex>
#include <unistd.h>

namespace fsi::app {

namespace {

// The first signal received; one atomic exchange decides which signal is the first when two
// threads take two signals at the same instant (lock-free, so safe in a handler).
std::atomic<int> received_signal = 0;
static_assert(std::atomic<int>::is_always_lock_free);
// The guards alive (nested runs, e.g. a progress callback that runs another scene, or runs in two
// threads): the first installs the handlers and saves the previous ones, the last restores them
// (issue 41: a single saved pair let an inner guard's restore re-install fsi's own handler).
std::mutex guards_mutex;
int guards = 0;
struct sigaction previous_int, previous_term;

// The run.json to leave on a second signal: two buffers, the handler reads the active one while
// the driver fills the other (the handler may run on any thread).
struct LastWords {
  std::string path, tmp, text;
};
LastWords last_words[2];
volatile std::sig_atomic_t active = -1;

void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = write(fd, data, size);
    if (n <= 0) return;
    data += n, size -= static_cast<std::size_t>(n);
  }
}

void record(int signal) {
  int none = 0;
  if (received_signal.compare_exchange_strong(none, signal)) return;
  // Second signal: end now, but leave run.json saying "interrupted" (only async-signal-safe
  // calls: open, write, close, rename, _exit).
  const int a = active;
  if (a >= 0) {
    const LastWords& w = last_words[a];
    const int fd = open(w.tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd >= 0) {
      write_all(fd, w.text.data(), w.text.size());
      if (close(fd) == 0) rename(w.tmp.c_str(), w.path.c_str());
    }
  }
  const char note[] = "second signal: stopped at once (run.json: interrupted); continue from the "
                      "last checkpoint_*.h5, if any\n";
  write_all(STDERR_FILENO, note, sizeof note - 1);
  _exit(128 + signal);
}

} // namespace

InterruptGuard::InterruptGuard() {
  const std::lock_guard<std::mutex> lock(guards_mutex);
  if (guards++ > 0) return; // installed by an enclosing or concurrent run
  received_signal = 0;
  active = -1;
  struct sigaction action = {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = 0; // the handler stays: a second signal writes run.json and ends at once
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptGuard::~InterruptGuard() {
  const std::lock_guard<std::mutex> lock(guards_mutex);
  if (--guards > 0) return;
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  active = -1;
}

int InterruptGuard::received() const {
  return received_signal;
}

void InterruptGuard::set_last_words(const std::filesystem::path& file, const std::string& text) {
  const int next = active == 0 ? 1 : 0;
  last_words[next].path = file.string();
  last_words[next].tmp = file.string() + ".tmp";
  last_words[next].text = text;
  active = next;
}

} // namespace fsi::app
