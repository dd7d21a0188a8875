#include "penumbra/base/progress.h"

#include <unistd.h>

#include <cstdio>

namespace penumbra {

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), visible_(isatty(STDERR_FILENO) != 0) {}

Progress::~Progress() {
  if (!visible_) return;
  draw(done_.load());
  std::fputc('\n', stderr);
}

void Progress::advance(std::size_t steps) {
  const std::size_t done = done_.fetch_add(steps) + steps;
  if (!visible_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(done);
}

void Progress::draw(std::size_t done) {
  const double percent =
      total_ == 0 ? 100.0 : 100.0 * static_cast<double>(done) / static_cast<double>(total_);
  std::fprintf(stderr, "\r%s: %zu/%zu (%.0f%%)", label_.c_str(), done, total_, percent);
  std::fflush(stderr);
}

}  // namespace penumbra
