#pragma once
// The work of a solver stage, counted in nanosecond-equivalents of a cost model of its
// operations (products by W, error evaluations, NLGS sweeps, factorisations; constants
// fitted by `moreau_bench_portfolio`-style timings on the 2-core reference machine, see
// docs/solvers.md "auto"). `auto` shares counted work, not wall-clock time, between its
// members: counted work is the same on every run and machine, so the same input gives the
// same decisions and the same output (a restart stays bit-identical), while its ratios
// between members follow their wall times to about ±30 % (the stated purpose of the model).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau {

/// Nanosecond-equivalents of one operation on problem P (deterministic: sizes only).
struct WorkCosts {
  double product = 1;  ///< u = W x + q: by the matrix, or through the factor H M⁻¹ Hᵀ
  double error = 1;    ///< the natural-map error given u
  double vector = 1;   ///< one pass over the dim·nc unknowns (axpy, projection)
  double sweep = 1;    ///< one NLGS sweep (local solves included), through W's rows or the body records
  /// The extra per call of a Newton step and of an ADMM step in a time step, beyond what
  /// their sizes count (counted by `auto` only): newton_step_call through the bodies (of()
  /// through the factor), newton_step_call_with_w and admm_step_with_w given with W in a time
  /// step (with_w_in_step()); 0 elsewhere (FCLib problems, ADMM through the bodies).
  double newton_call = 0, admm_call = 0;

  /// The per-call parts of a product and of an error evaluation; the rest of each scales
  /// with what is read (w_rows_product(), error_contacts()), so a partial pass (auto's start
  /// check, start_check.hpp) counts its share of them and these once.
  static constexpr double product_call = 200, error_call = 100;
  /// u = W x + q over `rows` of W's rows holding `entries` stored entries.
  static double w_rows_product(double entries, double rows) { return 0.37 * entries + 0.9 * rows; }
  /// The natural-map error's part for `contacts` contacts.
  static double error_contacts(int d, double contacts) { return (d == 2 ? 6.5 : 8.5) * contacts; }

  static WorkCosts of(const LocalProblem& P, bool through_factor) {
    WorkCosts c;
    const double d = P.dim, nc = static_cast<double>(P.contacts()), n = d * nc;
    // A one-contact Coulomb solve: a few cases in 2D, a local Newton when sliding in 3D.
    const double local = d == 2 ? 8.0 : 60.0;
    c.vector = 1.0 * n + 50;
    c.error = error_contacts(P.dim, nc) + error_call;
    if (through_factor && P.factor.present()) {
      // Hᵀx and H Δv: 2 d k multiply-adds per contact side each way, k² per body.
      const double k = P.factor.k, nb = static_cast<double>(P.factor.inverse_mass.size()) / std::max(1.0, k * k);
      c.product = 0.5 * (nc * 2 * 2 * d * k + nb * k * k) + 1.0 * n + 200;
      c.sweep = nc * (0.3 * 2 * 2 * d * k + local / 4) + 200;  // a record read, the two Δv written
      c.newton_call = newton_step_call;
    } else {
      const double nnz = static_cast<double>(P.W.nonZeros());
      c.product = w_rows_product(nnz, n) + product_call;
      c.sweep = 0.73 * nnz + local * nc + 200;
    }
    return c;
  }

  /// One NLGS sweep through the body records (plugins/solver/nlgs/nlgs_body_sweep.hpp) of
  /// `record` doubles per contact, as many per contact at every size. Records beyond the
  /// caches counted up to 4 times more until branch i15-costfit (measured then on 10⁴
  /// touching spheres: 4.3 ns per counted unit against APGD's 1.2). Since the records are laid
  /// out with the bodies numbered by first use, a sweep's time per contact no longer grows
  /// with their size: as a shadow of `apgd` (touching spheres, 10 steps at 1e-4, CPU,
  /// bench_spheres.py's scene) NLGS took 70, 70, 79 ns per contact and sweep at 10³, 3·10³,
  /// 10⁴ spheres (3200, 9424, 30894 contacts; 1.4, 4.0, 13 MB of records; the L2 holds 1 MB
  /// a core), and with the factor 0.66, 0.29, 0.21 ns per counted unit against APGD's
  /// 0.83–0.89: over-counted 3–4 times (without it 0.67, 0.68, 0.78).
  /// `nlgs` alone and `auto`'s NLGS count the same. `dense`: records with M⁻¹Hᵀ
  /// blocks (3D bodies whose inverse mass is not one scalar per block: boxes, clusters,
  /// convex grains; BodySweeper::dense_inverse_mass) cost more than their size says: measured
  /// in time steps (MOREAU_AUTO_TRACE, 150 steps at 1e-3), ns per counted unit of NLGS over
  /// APGD's: box_tower_3d 2.3, clusters_3d 1.7 (4.8 once dense), so such a sweep counted 2.5
  /// times. Measured alone (`nlgs` and `apgd` runs, 300 steps at 1e-3, solve-stage CPU over
  /// counted work, i15-count), every other record kind was under-counted as much: NLGS
  /// 1.8–2.4 ns per counted unit (disks, polygons, spheres alike) against APGD's 0.63–1.0,
  /// and dense records 0.37–0.95 with the 2.5 (a ratio of 2.3–3.0 where neither misses). So
  /// the other records count 3 times their record-size cost (2.5 left auto 1.2–1.6× APGD on
  /// brick_wall_2d, spheres_in_box_3d, silo_2d, silo_janssen_2d; 3 brings them to 1.04–1.16;
  /// dense ones at 3 moved box_tower_3d 0.97 → 1.07, so they stay at 2.5). The local solves
  /// are in it (perf, brick_wall_2d: ~40 % of a 2D sweep). Problems given with W (FCLib) do
  /// not sweep body records: their counts are unchanged.
  ///
  /// 3D dense records (i15-3d): in time steps (MOREAU_AUTO_TRACE, CPU ns per counted unit)
  /// NLGS's sweeps of dense records were still under-counted: clusters_3d (35 contacts,
  /// records of 85 doubles) 0.85–1.0 against APGD's 0.5 (whole run: auto 1.51× `apgd`), so
  /// in 3D a dense record counts 3 × (0.3 per double + 45 per contact): ×2.1, the dense
  /// M⁻¹Hᵀ products of the local solve that its size leaves out. (Spheres' records at the
  /// same 45 brought spheres_in_box_3d 1.68 → 1.36 but wet_pile_3d, where NLGS alone is
  /// 2.4× faster than APGD, 4.5 → 16.7: they stay as they were.)
  ///
  /// 2D contacts in pairs (i15-walls): a 2D contact that joins the same two bodies as the one
  /// before it (the two corners of a polygon's edge on another's: brick, mortar and masonry
  /// walls, half their contacts) counts 1.8 times. In time steps (MOREAU_AUTO_TRACE, 300 steps
  /// at 1e-3, CPU ns per counted unit) NLGS took 0.67–0.73 on those walls against 0.50–0.55 on
  /// the disk scenes, while APGD took 0.36–0.46 on both: with the same count `auto` took NLGS
  /// on 40 % of brick_wall_2d's steps, 1.5 times slower there than APGD (auto 1.25× `apgd`).
  /// Why such pairs cost more is not established (the second contact of a pair reads the
  /// bodies' Δv its neighbour has just written: one dependency chain through the local solve).
  ///
  /// Checked on every example scene (i15-costfit, docs/solvers.md "CPU time per counted unit
  /// by scene", scripts/slice_costs.py): fitted as fixed + per-unit over `auto`'s slices, NLGS's
  /// CPU ns per counted unit over APGD's is 0.4–1.7, as spread within one record kind as
  /// between kinds (dimension, size, dense or not, 8–778 contacts), so no form from sizes fits
  /// better than this one; what the count leaves out is a fixed cost per slice.
  static double body_sweep(const LocalProblem& P, double record, bool dense) {
    const double nc = static_cast<double>(P.contacts());
    const bool dense_3d = dense && P.dim == 3;
    const double local = P.dim == 2 ? 5.0 : dense_3d ? 45.0 : 15.0;
    double counted = nc;  // contacts, a paired 2D contact counting 1.8
    if (P.dim == 2 && P.factor.present()) {
      const std::vector<int>& b = P.factor.body;
      for (std::size_t a = 2; a + 1 < b.size(); a += 2)
        if (b[a] == b[a - 2] && b[a + 1] == b[a - 1]) counted += 0.8;
    }
    return (dense && !dense_3d ? 2.5 : 3.0) * (counted * (0.3 * record + local) + 200);
  }
  /// The records' size, and the cache they are compared with where `auto` decides whether to
  /// pack them before NLGS runs (auto/auto.hpp records_would_fit(): packing 10⁴ spheres' records
  /// cost 3 ms a step, for nothing when APGD finishes).
  static double record_bytes(const LocalProblem& P, double record) { return 8 * record * static_cast<double>(P.contacts()); }
  static constexpr double cache_bytes = 2e6;

  /// u = W x + q through APGD's packed factor (plugins/solver/apgd/scaled_factor.hpp): two
  /// streaming passes over d k doubles per contact side, no pass over the bodies' inverses
  /// (fitted to APGD's CPU time per step on 10⁴ touching spheres: 0.37 ns per multiply-add,
  /// where the generic product through the factor costs 0.5 and a pass over the bodies).
  static double scaled_factor_product(const LocalProblem& P) {
    const double d = P.dim, nc = static_cast<double>(P.contacts()), k = P.factor.k;
    return 0.37 * nc * 2 * 2 * d * k + 1.0 * d * nc + 200;
  }

  /// APGD's operations through its packed factor (rigid frames or H̃: a time step): its
  /// product (scaled_factor_product), error and vector passes, all counted at
  /// `packed_discount`. In time steps APGD's iteration took 0.29–0.47 CPU ns per counted
  /// unit where NLGS's sweeps took 0.43–0.8 (spheres, clusters, disks, polygons; 0.2 on
  /// box_tower_3d), ADMM 0.34–0.63 and Newton 0.58–0.93 (shadow runs, 300 steps at 1e-3 and
  /// 1e-4, docs/solvers.md "Counted work in time steps"): its products and passes stream
  /// through a few contiguous arrays that stay in the caches, where the other members'
  /// operations (sparse factorisations, local solves) do not. Problems given with W
  /// (FCLib) do not pack the factor: their counts are unchanged.
  static WorkCosts packed(const LocalProblem& P) {
    WorkCosts c = of(P, true);
    c.product = packed_discount * scaled_factor_product(P);
    c.error *= packed_discount;
    c.vector *= packed_discount;
    return c;
  }
  static constexpr double packed_discount = 0.65;

  /// A Newton step's cost per call in a time step (W assembled from the factor, counted by
  /// `auto`): the sparse LU's symbolic analysis and allocations and the Jacobian's sparse
  /// products cost more than their sizes say on small problems. Measured as shadows of an
  /// `apgd` run (300 steps, CPU ns per counted unit): a Newton step took 0.64–0.75 on
  /// box_tower_3d (40 contacts) and 0.86–0.93 on clusters_3d (35), against APGD's (packed)
  /// 0.42–0.45 and 0.62–0.68, i.e. about 1.2·10⁵ and 0.9·10⁵ units short a step; on
  /// wet_pile_3d's 650 contacts (3·10⁷ units a step) it was not short. Problems given with W
  /// (FCLib) count as before.
  static constexpr double newton_step_call = 1e5;

  /// The same per call for a time step given with W (finite-element bodies, counted by
  /// `auto` only). Measured as a shadow of `auto`'s run of elastic_block_hit_by_spheres_3d
  /// (600 steps at its own 1e-6, CPU, i15-eblock): `newton` alone took 16.9 µs a step (0.79
  /// ns per counted unit, 2.1·10⁴ units a step on 4–5 contacts) against `apgd`'s 0.38: about
  /// 2.4·10⁴ units short a step (its sparse LU's analysis and allocations). Uncounted, Newton
  /// was `auto`'s remembered member on 27 of the run's 133 solves, 1.5× `apgd`'s time there.
  static constexpr double newton_step_call_with_w = 2.4e4;

  /// An ADMM step's extra in a time step given with W (counted by `auto` only), for the same
  /// reason: there, once Newton counted its call, ADMM became `auto`'s remembered member on
  /// elastic_block_hit_by_spheres_3d at 1e-6, its steps taking 0.8 CPU ns per counted unit
  /// (3.1 µs for 3.9·10³ units on 5 contacts) against `apgd`'s 0.38 (445 µs on a step that
  /// `apgd` finishes in 41): about 3–4·10³ units short a step.
  static constexpr double admm_step_with_w = 3e3;

  /// NLGS's sweep over W's rows in a 3D time step whose problem comes with W (finite-element
  /// bodies: no rigid factor, no body records), as `auto` counts it: `w_rows_step` times the
  /// sweep of `of()`. Measured as shadows of an `apgd` run (300 steps at 1e-3, CPU ns per
  /// counted unit, `nlgs` and `apgd` alone, i15-fe): NLGS over APGD 2.7 on
  /// elastic_block_hit_by_spheres_3d (5 contacts: 1.08 against 0.40; the 3D local solves,
  /// 60 units a contact, are most of its count), 0.86 on blocks_on_elastic_slab_3d (26
  /// contacts, W dense: W's rows are most of it). With the same count `auto` took NLGS
  /// first and interleaved it with APGD on elastic_block_hit_by_spheres_3d, 2.2–2.5× `apgd`
  /// there; at 2 1.2–1.35×. 2D counts as before: on elastic_bar_on_wall_2d,
  /// elastic_disk_on_plane_2d and grains_on_elastic_beam_2d the ratio was 1.8–3.1 too, but
  /// `auto` was within 1.1 of the best member there, and at 2 on grains_on_elastic_beam_2d
  /// (where `nlgs` is the fastest member) it took 7–10 % more (NLGS's first stage left
  /// sooner). Only in a time step (the time-stepper's LocalProblem::error_scale set):
  /// problems given with W outside one (FCLib, the guarantee's corpus) and `nlgs` alone
  /// count as before.
  /// 3 since branch i15-tiny: at 2 NLGS's slices in `auto`'s run of
  /// elastic_block_hit_by_spheres_3d (300 steps at 1e-3, MOREAU_AUTO_TRACE) still took 0.81
  /// CPU ns per counted unit against APGD's 0.35, a fifth of `auto`'s time there; as shadows of
  /// an `apgd` run (the same problems, medians of 3 runs) `auto` / `apgd` went 1.35 → 1.24 at
  /// 1e-3 (blocks_on_elastic_slab_3d 1.06 → 1.00), 1.27 → 1.26 at the scenes' own 1e-6
  /// (the slab 0.209 → 0.198 ms a step for `auto`); 4 and 5 gained no more at 1e-3 and 4 cost
  /// the slab 0.30 ms a step at 1e-6.
  static constexpr double w_rows_step = 3.0;
  static WorkCosts with_w_in_step(const LocalProblem& P) {
    WorkCosts c = of(P, false);
    if (P.error_scale > 0 && P.dim == 3) c.sweep *= w_rows_step;
    if (P.error_scale > 0) {  // a time step (finite-element bodies): Newton's and ADMM's calls
      c.newton_call = newton_step_call_with_w;
      c.admm_call = admm_step_with_w;
    }
    return c;
  }

  /// A sparse LU (or LDLᵀ) factorisation with these factors of an n × n matrix (Eigen's
  /// supernodal LU: a cost per column besides the fill and the flops).
  static double factorisation(double nnz_l, double nnz_u, double n) {
    return 12.0 * (nnz_l + nnz_u) + 0.35 * nnz_l * nnz_u / std::max(n, 1.0) + 100 * n + 6000;
  }
  /// Assembling an n × n matrix of W's pattern from W (Newton's Jacobian A + B W + λI).
  static double assembly(double nnz, double n) { return 15.0 * nnz + 100 * n + 6000; }
  static double triangular_solves(double nnz_l, double nnz_u) { return 2.0 * (nnz_l + nnz_u); }
  /// A Newton step as `auto` estimates it before one is measured (newton_core.cpp counts the
  /// Jacobian's assembly, the factorisation and its solves, and the line search's products):
  /// W of nnz_w entries, n unknowns, factors of nnz_l and nnz_u entries (lu_fill.hpp), `product`
  /// one product by W; the solves and the passes over the unknowns are within the products.
  static double newton_step(double nnz_w, double n, double nnz_l, double nnz_u, double product) {
    return assembly(nnz_w, n) + factorisation(nnz_l, nnz_u, n) + 3 * product;
  }
};

class WorkMeter {
 public:
  /// `max`: the stage's budget (0: none); `total`: where the work is also added (may be null).
  WorkMeter(double max, double* total) : max_(max), total_(total) {}
  void add(double units) {
    spent_ += units;
    if (total_) *total_ += units;
  }
  bool exhausted() const { return max_ > 0 && spent_ >= max_; }
  double spent() const { return spent_; }

 private:
  double max_, spent_ = 0;
  double* total_;
};

/// A member run alone (`newton`, `admm`, `apgd`): `solve()` with its options `o` counting
/// into the report's `work`, as the same core counts inside `auto`, so that the guarantee's
/// test compares auto's work with each member's.
template <class Options, class Solve>
SolverReport counted(Options& o, Solve&& solve) {
  double work = 0;
  o.work = &work;
  SolverReport rep = solve();
  o.work = nullptr;
  rep.work = work;
  return rep;
}

}  // namespace moreau
