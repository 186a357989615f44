#pragma once
// Training progress on a bar (iteration, loss, PSNR, Gaussians), for every command that trains.
#include <functional>
#include <iomanip>
#include <sstream>

#include "common/util/progress.hpp"
#include "render/gs/trainer.hpp"

namespace chatsim::cli {

// `coarse_share`: the options' share of iterations trained at half resolution, which go faster.
inline std::function<void(int, int, double, double, size_t)> train_progress(ProgressBar& bar, float coarse_share) {
  return [&bar, coarse_share](int it, int total, double loss, double psnr, size_t n) {
    std::ostringstream what;
    what << "it " << it << "/" << total << " loss " << std::fixed << std::setprecision(4) << loss << " PSNR "
         << std::setprecision(1) << psnr << " dB, " << n << " Gaussians";
    bar.update(render::gs::training_work_done(it, total, coarse_share), what.str());
  };
}

}  // namespace chatsim::cli
