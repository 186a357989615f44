#pragma once
// A progress bar on stderr for long work: fraction, what is being done, elapsed time and ETA.
// On a terminal it redraws one line; otherwise (logs, CI) it prints a line every 10 %, with the
// ETA too.
#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace chatsim {

// Seconds left at this pace, or -1 before 1 % is done (too early to tell).
inline double progress_eta_s(double fraction, double elapsed_s) {
  return fraction > 0.01 ? elapsed_s * (1 - fraction) / fraction : -1;
}

// The line printed where stderr is not a terminal, e.g. "train:  40% iteration 600 (116s elapsed, ETA 174s)".
inline std::string progress_log_line(const std::string& title, double fraction, const std::string& what, double elapsed_s) {
  const double eta = progress_eta_s(fraction, elapsed_s);
  char line[160];
  std::snprintf(line, sizeof line, ": %3.0f%% ", 100 * fraction);
  std::string out = title + line + what;
  std::snprintf(line, sizeof line, " (%.0fs elapsed", elapsed_s);
  out += line;
  if (eta >= 0 && fraction < 1) out += ", ETA " + std::to_string(int(eta + 0.5)) + "s";
  return out + ")";
}

class ProgressBar {
 public:
  explicit ProgressBar(std::string title) : title_(std::move(title)), tty_(isatty(fileno(stderr)) != 0) {}
  ~ProgressBar() { finish(); }

  void update(double fraction, const std::string& what = "") {
    fraction = fraction < 0 ? 0 : (fraction > 1 ? 1 : fraction);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = progress_eta_s(fraction, elapsed);
    if (tty_) {
      const int width = 30, filled = int(fraction * width);
      std::string bar(size_t(filled), '#');
      bar.resize(size_t(width), '.');
      std::fprintf(stderr, "\r%s [%s] %5.1f%%  %s  %.0fs elapsed%s%s\x1b[K", title_.c_str(), bar.c_str(), 100 * fraction,
                   what.c_str(), elapsed, eta >= 0 ? ", ETA " : "", eta >= 0 ? (std::to_string(int(eta)) + "s").c_str() : "");
      std::fflush(stderr);
      drawn_ = true;
    } else if (int(fraction * 10) > last_decile_) {
      last_decile_ = int(fraction * 10);
      std::fprintf(stderr, "%s\n", progress_log_line(title_, fraction, what, elapsed).c_str());
    }
  }
  void finish() {
    if (tty_ && drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }

 private:
  std::string title_;
  bool tty_;
  bool drawn_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace chatsim
