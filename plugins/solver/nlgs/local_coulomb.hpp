#pragma once
// The one-contact Coulomb problem NLGS solves at each contact: find r with
// u = A r + b (A the contact's d×d diagonal block of W), r ∈ K_μ, ũ ∈ K*_μ, r ⊥ ũ.
// Cases are tried in order: open (b_n ≥ 0), sticking (u = 0), sliding (2D: closed form
// for either direction; 3D: a checked local Newton step sequence, then a fixed point on
// the sliding direction, an angle search, and projected iterations on the cone).
namespace moreau::nlgs {

/// `r` holds the previous value on entry (a start for the 3D sliding iterations).
void solve_local(int dim, const double* A, const double* b, double mu, double* r);

}  // namespace moreau::nlgs
