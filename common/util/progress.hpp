#pragma once
// A progress bar on stderr for long work: fraction, what is being done, elapsed time and ETA.
// On a terminal it redraws one line; otherwise (logs, CI) it prints a line every 10 %.
#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace chatsim {

class ProgressBar {
 public:
  explicit ProgressBar(std::string title) : title_(std::move(title)), tty_(isatty(fileno(stderr)) != 0) {}
  ~ProgressBar() { finish(); }

  void update(double fraction, const std::string& what = "") {
    fraction = fraction < 0 ? 0 : (fraction > 1 ? 1 : fraction);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = fraction > 0.01 ? elapsed * (1 - fraction) / fraction : -1;
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
      std::fprintf(stderr, "%s: %3.0f%% %s (%.0fs elapsed)\n", title_.c_str(), 100 * fraction, what.c_str(), elapsed);
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
