#pragma once
// Training progress on a bar (iteration, loss, PSNR, Gaussians), for every command that trains.
#include <functional>
#include <iomanip>
#include <sstream>

#include "common/util/progress.hpp"

namespace chatsim::cli {

inline std::function<void(int, int, double, double, size_t)> train_progress(ProgressBar& bar) {
  return [&bar](int it, int total, double loss, double psnr, size_t n) {
    std::ostringstream what;
    what << "it " << it << "/" << total << " loss " << std::fixed << std::setprecision(4) << loss << " PSNR "
         << std::setprecision(1) << psnr << " dB, " << n << " Gaussians";
    bar.update(double(it) / total, what.str());
  };
}

}  // namespace chatsim::cli
