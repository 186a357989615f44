#include "render/gs/ssim_loss.hpp"

#include "render/image_metrics.hpp"

namespace chatsim::render::gs {
namespace {

void blur(const cv::Mat& m, cv::Mat& out) { ssim_window_mean(m, out); }

}  // namespace

// With S = A1 A2 / (B1 B2), A1 = 2 mx my + C1, A2 = 2 sxy + C2, B1 = mx^2 + my^2 + C1,
// B2 = sx^2 + sy^2 + C2 over a window w, and dmx/dx_q = w, dsx^2/dx_q = 2 w (x_q - mx),
// dsxy/dx_q = w (y_q - my), the sum over windows p of dS_p/dx_q is
//   blur(alpha)_q + y_q blur(beta)_q - x_q blur(gamma)_q
// with alpha = 2 (my (A2 - A1) - S mx (B2 - B1)) / (B1 B2), beta = 2 A1 / (B1 B2),
// gamma = 2 S / B2 (the window, reflected at the border, is symmetric: its transpose is itself).
double SsimLoss::value_and_gradient(const cv::Mat& pred, const cv::Mat& target, cv::Mat& d_pred) {
  CV_Assert(pred.type() == target.type() && pred.size() == target.size() && pred.isContinuous() && target.isContinuous());
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const cv::Mat &x = pred, &y = target;
  // The windowed sums, then alpha, beta and gamma in one pass: OpenCV's blur is fast, its
  // matrix expressions (a temporary per operation) took 60 of 70 ms per 640x426 image.
  blur(x, mx_), blur(y, my_);
  cv::multiply(x, x, product_), blur(product_, xx_);
  cv::multiply(y, y, product_), blur(product_, yy_);
  cv::multiply(x, y, product_), blur(product_, xy_);
  alpha_.create(x.size(), x.type()), beta_.create(x.size(), x.type()), gamma_.create(x.size(), x.type());
  d_pred.create(x.size(), x.type());
  const size_t n = x.total() * size_t(x.channels());
  double sum = 0;
  auto run = [&](auto zero) {
    using T = decltype(zero);
    const T *pmx = mx_.ptr<T>(), *pmy = my_.ptr<T>(), *pxx = xx_.ptr<T>(), *pyy = yy_.ptr<T>(), *pxy = xy_.ptr<T>();
    T *pa = alpha_.ptr<T>(), *pb = beta_.ptr<T>(), *pg = gamma_.ptr<T>();
    for (size_t i = 0; i < n; ++i) {
      const double ux = pmx[i], uy = pmy[i];
      const double a1 = 2 * ux * uy + c1, a2 = 2 * (pxy[i] - ux * uy) + c2;
      const double b1 = ux * ux + uy * uy + c1, b2 = (pxx[i] - ux * ux) + (pyy[i] - uy * uy) + c2;
      const double inv = 1 / (b1 * b2), s = a1 * a2 * inv;
      sum += s;
      pa[i] = T(2 * (uy * (a2 - a1) - s * ux * (b2 - b1)) * inv);
      pb[i] = T(2 * a1 * inv);
      pg[i] = T(2 * s / b2);
    }
    blur(alpha_, blurred_alpha_), blur(beta_, blurred_beta_), blur(gamma_, blurred_gamma_);
    const T *px = x.ptr<T>(), *py = y.ptr<T>(), *ba = blurred_alpha_.ptr<T>(), *bb = blurred_beta_.ptr<T>(), *bg = blurred_gamma_.ptr<T>();
    T* out = d_pred.ptr<T>();
    for (size_t i = 0; i < n; ++i) out[i] = T((ba[i] + py[i] * bb[i] - px[i] * bg[i]) / double(n));
  };
  if (x.depth() == CV_64F) run(0.0);
  else run(0.0f);
  return sum / double(n);
}

}  // namespace chatsim::render::gs
