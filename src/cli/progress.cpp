#include "cli/progress.h"

#include <cmath>
#include <fmt/format.h>
#include <ostream>

namespace drt::cli {

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0)
        return "?";
    if (seconds < 1)
        return fmt::format("{:.0f} ms", seconds * 1000);
    if (seconds < 60)
        return fmt::format("{:.1f} s", seconds);
    const auto whole = static_cast<long long>(seconds);
    if (whole < 3600)
        return fmt::format("{} min {:02} s", whole / 60, whole % 60);
    return fmt::format("{} h {:02} min", whole / 3600, (whole % 3600) / 60);
}

ProgressLine::ProgressLine(std::ostream& err) : err_(err), start_(Clock::now()), lastDraw_(start_) {}

void ProgressLine::update(double fraction) {
    // Render threads call this often: skip rather than wait if another thread draws.
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock())
        return;
    const auto now = Clock::now();
    if (drawn_ && now - lastDraw_ < std::chrono::milliseconds(200))
        return;
    lastDraw_ = now;
    drawn_ = true;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // Linear extrapolation: remaining = elapsed * (1 - f) / f.
    const std::string eta = fraction > 0.001 ? formatDuration(elapsed * (1 - fraction) / fraction) : "?";
    err_ << fmt::format("\r\033[Kdrt: {:5.1f}%  elapsed {}  ETA {}", 100 * fraction, formatDuration(elapsed),
                        eta)
         << std::flush;
}

void ProgressLine::finish() {
    std::lock_guard lock(mutex_);
    if (drawn_)
        err_ << "\r\033[K" << std::flush;
    drawn_ = false;
}

} // namespace drt::cli
