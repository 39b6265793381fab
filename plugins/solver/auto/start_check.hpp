#pragma once
// auto's check of a warm start given with W (rule 0, docs/solvers.md), contact by contact:
// u_α = W_α r + q_α and the natural-map error of the contacts examined so far, which bounds
// the start's error from below (a sum of squares over the contacts). The check stops as
// soon as that bound exceeds what the caller asks about (the tolerance: the start is not
// the answer), and goes on from there when a rule later needs more (rule 2b: whether the
// start's error is within 1e-3). Contacts are examined last first: on the reduced corpus
// the contacts that miss the tolerance are more often the last ones (docs/solvers.md,
// branch i15-start: first-first stopped later, within 1.5× 110 / 96 → 109 / 95). Examined
// to the end it gives the start's u = W r + q and its error (summed in another order:
// equal to rounding).
#include <moreau/contact_error.hpp>
#include <moreau/contact_problem.hpp>

#include "../work.hpp"

namespace moreau::auto_start {

struct StartCheck {
  Eigen::VectorXd u;      ///< u = W r + q of the contacts examined (all of them once done)
  Eigen::Index done = 0;  ///< contacts examined
  double sum = 0;         ///< Σ over them of the squared natural-map residual
  double error = 0;       ///< the start's error, once done == contacts (else a lower bound)

  void reset(const LocalProblem& P) {
    u.resize(P.dim * P.contacts());
    done = 0;
    sum = 0;
    error = 0;
  }
  bool complete(const LocalProblem& P) const { return done == P.contacts(); }

  /// Examines contacts of x (the start) until the error of those examined exceeds `bound`
  /// or all are. Returns the counted work (work.hpp): the product's and the error's
  /// per-call parts in full, their per-row and per-contact parts for the rows examined;
  /// all rows from the first: exactly a product and an error, as rule 0 counted them.
  double examine(const LocalProblem& P, const Eigen::VectorXd& x, double bound) {
    const int d = P.dim;
    const Eigen::Index nc = P.contacts(), from = done;
    const double scale = error_denominator(P), limit = bound * scale;
    double entries = 0;
    while (done < nc && !(sum > limit * limit)) {
      const Eigen::Index a = nc - 1 - done;
      for (int k = 0; k < d; ++k) {
        const Eigen::Index i = a * d + k;
        double s = 0;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(P.W, i); it; ++it) s += it.value() * x[it.index()];
        u[i] = s + P.q[i];
        entries += static_cast<double>(P.W.outerIndexPtr()[i + 1] - P.W.outerIndexPtr()[i]);
      }
      sum += contact_natural_map_squared(d, P.mu[a], x.data() + a * d, u.data() + a * d);
      ++done;
    }
    error = std::sqrt(sum) / scale;
    if (from == 0 && done == nc) {
      const WorkCosts c = WorkCosts::of(P, false);
      return c.product + c.error;
    }
    return WorkCosts::product_call + WorkCosts::error_call + WorkCosts::w_rows_product(entries, static_cast<double>((done - from) * d)) +
           WorkCosts::error_contacts(d, static_cast<double>(done - from));
  }
};

}  // namespace moreau::auto_start
