#pragma once
// Progress of long work on stderr, shown only when stderr is a terminal (DESIGN.md:
// "Long work shows progress on a terminal and stays quiet otherwise"). Safe to
// advance from several threads.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace penumbra {

class Progress {
 public:
  // starts a progress line labelled label for total steps.
  Progress(std::string label, std::size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // records steps more finished steps; redraws at most ten times a second.
  void advance(std::size_t steps = 1);

  // true when progress is being drawn (stderr is a terminal).
  bool visible() const { return visible_; }

 private:
  void draw(std::size_t done);

  std::string label_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  bool visible_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace penumbra
