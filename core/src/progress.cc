#include "modaltyre/core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace modaltyre {

ProgressBar::ProgressBar(std::size_t total, std::string label, Mode mode, std::FILE* stream,
                         std::chrono::milliseconds min_interval)
    : total_(total),
      label_(std::move(label)),
      stream_(stream),
      enabled_(mode == Mode::always || (mode == Mode::automatic && is_terminal(stream))),
      start_(std::chrono::steady_clock::now()),
      min_interval_(min_interval) {
  if (enabled_) draw(false);
}

ProgressBar::~ProgressBar() { finish(); }

bool ProgressBar::is_terminal(std::FILE* stream) {
  return stream != nullptr && ::isatty(::fileno(stream)) == 1;
}

double ProgressBar::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::tick(std::size_t n) {
  done_.fetch_add(n, std::memory_order_relaxed);
  if (!enabled_) return;
  const long long now =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_)
          .count();
  long long due = next_draw_ns_.load(std::memory_order_relaxed);
  if (now < due) return;
  // One thread wins the right to draw this frame; the others carry on computing.
  if (!next_draw_ns_.compare_exchange_strong(due, now + min_interval_.count())) return;
  std::unique_lock<std::mutex> lock(draw_mutex_, std::try_to_lock);
  if (lock.owns_lock() && !finished_) draw(false);
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(draw_mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void ProgressBar::draw(bool final_frame) {
  const std::string frame = render(label_, done(), total_, elapsed_s());
  // \r returns to the start of the line, \033[K clears what a longer previous frame left.
  std::fprintf(stream_, "\r%s\033[K%s", frame.c_str(), final_frame ? "\n" : "");
  std::fflush(stream_);
}

std::string ProgressBar::format_duration(double s) {
  char b[64];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 10) {
    std::snprintf(b, sizeof b, "%.1f s", s);
  } else if (s < 60) {
    std::snprintf(b, sizeof b, "%.0f s", s);
  } else if (s < 3600) {
    const long t = std::lround(s);
    std::snprintf(b, sizeof b, "%ld min %02ld s", t / 60, t % 60);
  } else {
    const long t = std::lround(s / 60);
    std::snprintf(b, sizeof b, "%ld h %02ld min", t / 60, t % 60);
  }
  return b;
}

std::string ProgressBar::render(const std::string& label, std::size_t done, std::size_t total,
                                double elapsed_s, int width) {
  const double frac =
      total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
  const int filled = static_cast<int>(std::floor(frac * width));
  std::string out = label.empty() ? "" : label + " ";
  out += "[" + std::string(filled, '#') + std::string(width - filled, '-') + "]";
  char b[160];
  std::snprintf(b, sizeof b, " %3d%% %zu/%zu", static_cast<int>(std::floor(100 * frac)), done,
                total);
  out += b;
  if (done > 0 && elapsed_s > 0) {
    const double rate = static_cast<double>(done) / elapsed_s;
    std::snprintf(b, sizeof b, "  %.1f/s", rate);
    out += b;
    if (done < total) {
      out += "  left " + format_duration(static_cast<double>(total - done) / rate);
    } else {
      out += "  took " + format_duration(elapsed_s);
    }
  }
  return out;
}

}  // namespace modaltyre
