#include <cmath>
#include <moreau/contact_error.hpp>
#include <stdexcept>

#include "local_solvers.hpp"

namespace moreau::nlgs {

const std::vector<std::string>& local_method_names() {
  static const std::vector<std::string> names{"exact", "projection", "desaxce", "alart_curnier"};
  return names;
}

LocalMethod local_method_named(const std::string& name) {
  const auto& n = local_method_names();
  for (std::size_t i = 0; i < n.size(); ++i)
    if (n[i] == name) return static_cast<LocalMethod>(i);
  throw std::invalid_argument("unknown local solver \"" + name + "\"");
}

int default_local_iterations(LocalMethod m) {
  switch (m) {
    case LocalMethod::exact: return 0;
    case LocalMethod::projection: return 100;
    case LocalMethod::desaxce: return 1;
    case LocalMethod::alart_curnier: return 20;
  }
  return 0;
}

double local_rho(int d, const double* A) {
  double bound = 0;
  for (int i = 0; i < d; ++i) {
    double s = 0;
    for (int j = 0; j < d; ++j) s += std::fabs(A[i * d + j]);
    bound = std::fmax(bound, s);
  }
  return bound > 0 ? 1 / bound : 1.0;
}

namespace {
/// One prediction/correction: out = P_K(r − ρ ũ(r)), ũ = A r + b + μ‖u_T‖ e_n.
inline void project_step(int d, const double* A, const double* b, double mu, double rho, const double* r, double* out) {
  double u[3], y[3];
  for (int i = 0; i < d; ++i) {
    u[i] = b[i];
    for (int j = 0; j < d; ++j) u[i] += A[i * d + j] * r[j];
  }
  const double ut = d == 2 ? std::fabs(u[1]) : std::hypot(u[1], u[2]);
  y[0] = r[0] - rho * (u[0] + mu * ut);
  for (int k = 1; k < d; ++k) y[k] = r[k] - rho * u[k];
  project_on_cone(d, mu, y, out);
}
}  // namespace

void solve_local_desaxce(int d, const double* A, const double* b, double mu, double* r, int iterations) {
  const double rho = local_rho(d, A);
  const int n = iterations > 0 ? iterations : default_local_iterations(LocalMethod::desaxce);
  double next[3];
  for (int it = 0; it < n; ++it) {
    project_step(d, A, b, mu, rho, r, next);
    for (int k = 0; k < d; ++k) r[k] = next[k];
  }
}

void solve_local_projection(int d, const double* A, const double* b, double mu, double* r, int iterations, double tolerance) {
  double rho = local_rho(d, A);
  const int n = iterations > 0 ? iterations : default_local_iterations(LocalMethod::projection);
  double next[3], last_step = INFINITY;
  for (int it = 0; it < n; ++it) {
    project_step(d, A, b, mu, rho, r, next);
    double step = 0, size = 0;
    for (int k = 0; k < d; ++k) {
      step += (next[k] - r[k]) * (next[k] - r[k]);
      size += next[k] * next[k];
    }
    // The De Saxcé map is not monotone: when a step is longer than the last, ρ was too
    // large for this block; halve it and retry from the same point.
    if (step > last_step && rho > 1e-6 * local_rho(d, A)) {
      rho *= 0.5;
      continue;
    }
    last_step = step;
    for (int k = 0; k < d; ++k) r[k] = next[k];
    if (step <= tolerance * tolerance * size || size == 0) return;
  }
}

}  // namespace moreau::nlgs
