#pragma once
// The one-contact solvers NLGS can use at each contact (the `local_solver` parameter):
// given u = A r + b (A the contact's d×d block of W, b the rest of its velocity), find r
// on the Coulomb cone with the Coulomb law satisfied.
//  - exact:         case enumeration (local_coulomb.hpp): open, sticking, sliding in closed
//                   form (2D) or by a search on the sliding angle (3D).
//  - projection:    fixed point r ← P_K(r − ρ ũ(r)), ũ = u + μ‖u_T‖ e_n, iterated on the one
//                   contact until it settles, ρ scalar, halved when a step does not contract
//                   (Siconos' "projection on cone with local iteration").
//  - desaxce:       De Saxcé's bipotential augmented Lagrangian, prediction
//                   τ = r − ρ ũ(r), correction r = P_K(τ) (De Saxcé–Feng; eq. 15 of
//                   shared/papers/001), with a fixed ρ and a fixed number of steps per visit
//                   (1 by default: the Uzawa iteration interleaved with Gauss–Seidel).
//  - alart_curnier: semismooth Newton on the Alart–Curnier function of the one contact,
//                   with a backtracking line search on ½‖Φ‖².
// ρ is a scalar (a diagonal ρ would change the fixed point): 1 / the Gershgorin bound of A's
// largest eigenvalue, so that ρ λ_max(A) ≤ 1.
#include <string>
#include <vector>

#include "local_coulomb.hpp"

namespace moreau::nlgs {

enum class LocalMethod { exact, projection, desaxce, alart_curnier };

struct LocalOptions {
  LocalMethod method = LocalMethod::exact;
  int iterations = 0;        ///< steps per visit for the iterative methods (0: the method's default)
  double tolerance = 1e-14;  ///< relative change (projection) or ‖Φ‖ (alart_curnier) that ends a visit
};

/// The names of the `local_solver` parameter, in enum order.
const std::vector<std::string>& local_method_names();
LocalMethod local_method_named(const std::string& name);
/// Steps per visit when LocalOptions::iterations is 0.
int default_local_iterations(LocalMethod m);

/// 1 / (Gershgorin bound of the largest eigenvalue of the d×d block A).
double local_rho(int d, const double* A);

/// `r` holds the previous value on entry (the start of the iterative methods).
void solve_local_projection(int d, const double* A, const double* b, double mu, double* r, int iterations, double tolerance);
void solve_local_desaxce(int d, const double* A, const double* b, double mu, double* r, int iterations);
void solve_local_alart_curnier(int d, const double* A, const double* b, double mu, double* r, int iterations, double tolerance);

inline void solve_local(const LocalOptions& o, int d, const double* A, const double* b, double mu, double* r) {
  switch (o.method) {
    case LocalMethod::exact: solve_local(d, A, b, mu, r); return;
    case LocalMethod::projection: solve_local_projection(d, A, b, mu, r, o.iterations, o.tolerance); return;
    case LocalMethod::desaxce: solve_local_desaxce(d, A, b, mu, r, o.iterations); return;
    case LocalMethod::alart_curnier: solve_local_alart_curnier(d, A, b, mu, r, o.iterations, o.tolerance); return;
  }
}

}  // namespace moreau::nlgs
