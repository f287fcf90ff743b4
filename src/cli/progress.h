// A progress line on a terminal: percentage, elapsed time and ETA, redrawn in
// place at most a few times a second. Safe to call from render threads.
#pragma once

#include <chrono>
#include <iosfwd>
#include <mutex>
#include <string>

namespace drt::cli {

class ProgressLine {
  public:
    explicit ProgressLine(std::ostream& err);
    void update(double fraction); // fraction of the work done, in [0, 1]
    void finish();                // clears the line

  private:
    using Clock = std::chrono::steady_clock;
    std::ostream& err_;
    std::mutex mutex_;
    Clock::time_point start_;
    Clock::time_point lastDraw_;
    bool drawn_ = false;
};

// "34 ms", "1.2 s", "3 min 04 s", "1 h 02 min".
std::string formatDuration(double seconds);

} // namespace drt::cli
