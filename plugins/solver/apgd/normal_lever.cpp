#include "normal_lever.hpp"

namespace moreau::apgd {

double normal_lever(int dim, const BodyFactor& f) {
  const int d = dim, k = f.k;
  if (k <= d || d < 2 || d > 3) return 0;
  const std::size_t nc = f.body.size() / 2;
  if (nc == 0) return 0;
  double sum = 0;
  for (std::size_t a = 0; a < nc; ++a) {
    double nn = f.diagonal.empty() ? 0 : f.diagonal[a * d];
    double rot = 0;
    for (int s = 0; s < 2; ++s) {
      const int b = f.body[2 * a + s];
      if (b < 0) continue;
      const double* h = &f.H[(2 * a + s) * static_cast<std::size_t>(d * k)];  // its normal row
      const double* m = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const double t = h[i] * m[i * k + j] * h[j];
          nn += t;
          if (i >= d && j >= d) rot += t;
        }
    }
    if (nn > 0) sum += rot / nn;
  }
  return sum / static_cast<double>(nc);
}

}  // namespace moreau::apgd
