#pragma once
// A small terminal progress bar for long batch runs (sweeps): done/total, percentage, rate and
// time left, redrawn at most every `min_interval` on one line of a stream (stderr by default).
// It draws only when enabled, which by default means "the stream is a terminal": in pipes, logs
// and tests it stays quiet. tick() may be called from any thread.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

namespace modaltyre {

class ProgressBar {
 public:
  enum class Mode { automatic, always, never };

  /// `label` is printed before the bar (e.g. "sweep").
  ProgressBar(std::size_t total, std::string label = "", Mode mode = Mode::automatic,
              std::FILE* stream = stderr,
              std::chrono::milliseconds min_interval = std::chrono::milliseconds(100));
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Counts n more items done (thread-safe, cheap; redraws when the interval has passed).
  void tick(std::size_t n = 1);
  /// Draws the final state and ends the line (idempotent; also done by the destructor).
  void finish();

  bool enabled() const { return enabled_; }
  std::size_t done() const { return done_.load(std::memory_order_relaxed); }
  std::size_t total() const { return total_; }
  double elapsed_s() const;

  /// The text of one frame, e.g. "sweep [#####-----]  50% 500/1000  312.4/s  left 1.6 s".
  /// `width` is the number of characters of the bar itself.
  static std::string render(const std::string& label, std::size_t done, std::size_t total,
                            double elapsed_s, int width = 30);
  /// Human-readable duration: "0.4 s", "12 s", "3 min 05 s", "2 h 07 min".
  static std::string format_duration(double seconds);
  /// True when `stream` is attached to a terminal.
  static bool is_terminal(std::FILE* stream);

 private:
  void draw(bool final_frame);

  std::size_t total_;
  std::string label_;
  std::FILE* stream_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::nanoseconds min_interval_;
  std::atomic<std::size_t> done_{0};
  std::atomic<long long> next_draw_ns_{0};  ///< since start_
  std::mutex draw_mutex_;
  bool finished_ = false;
};

}  // namespace modaltyre
