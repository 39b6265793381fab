// `auto`'s parameters (schema(), the constructor), its saved state (the memory over the
// solves of a run: state_fields(), save_state(), load_state()) and its registration as the
// solver "auto" of the library moreau_solver_auto: what the kernel sees of the plugin, apart
// from the solve itself (auto.hpp).
#include "auto.hpp"

namespace moreau::auto_solver {

Schema Auto::schema() {
  Schema s;
  s.number("tolerance", "target error (DESIGN §1; in a time step normalised by the approaching contacts)").gt(0).fallback(1e-3);
  s.integer("max_iterations", "maximum iterations of each member (NLGS sweeps, APGD, Newton or ADMM steps)").min(1).fallback(20000);
  s.integer("newton_max_iterations", "maximum steps of each of its Newton runs (as `newton`'s max_iterations; each step is a factorisation)").min(1).fallback(200);
  s.integer("nlgs_sweeps", "maximum sweeps of the first NLGS stage (0: start with the other members)").min(0).fallback(100000);
  s.integer("check_every", "NLGS sweeps between two evaluations of the error (as nlgs)").min(1).fallback(5);
  s.integer("direct_max_contacts", "above this many contacts, no sparse factorisation (Newton, ADMM)").min(0).fallback(1000);
  s.boolean("remember", "over the solves of a run, start with the member that was cheapest on the earlier ones (the memory is saved with every frame and restored on restart)").fallback(true);
  return s;
}

Auto::Auto(const Params& p, const BuildContext&)
    : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), nlgs_sweeps_(p.integer("nlgs_sweeps")),
      check_(p.integer("check_every")), direct_max_contacts_(p.integer("direct_max_contacts")),
      newton_max_it_(p.integer("newton_max_iterations")),
      remember_(p.boolean("remember")) {}

// With `remember`, the memory is part of the run's state (docs/output.md, "The solver's
// state"): written with every frame and restored by `--restart`, so a continuation is
// bit-identical. Per member, in the order nlgs, apgd, newton, newton from the best, admm.
std::vector<FieldSpec> Auto::state_fields(int) const {
  if (!remember_) return {};
  auto f = [](const char* name, int n, const char* units, const char* doc, FileType t) {
    return field_spec(sets::solver, name, n, n, 1, units, FieldOutput::frame, true, doc, t);
  };
  return {f("solves", 1, "1", "auto: solves of the run with contacts", FileType::int32),
          f("member_cost", member_count, "1", "auto: each member's remembered work per contact to converge from the warm start (0: unknown)", FileType::real),
          f("member_iteration", member_count, "1", "auto: each member's remembered work per contact of one iteration (0: unknown)", FileType::real),
          f("member_next_try", member_count, "1", "auto: the solve from which each member may be tried first again", FileType::int32),
          f("member_try_interval", member_count, "1", "auto: solves between two such tries", FileType::int32),
          f("at_rest", 1, "1", "auto: 1 when the last solve's warm start met the tolerance at its first check (a step at rest), else 0", FileType::int32)};
}

// Called after every step's solve: the six fields are resolved once (StateFields,
// moreau/field_cache.hpp), not looked up by name at each step (a map of strings each, two
// of the names beyond the short-string buffer: about 2·10³ instructions a step, more than a
// light solve's own bookkeeping on cannonball_3d; found by their index in the set and
// checked by name, still about 900 a step).
void Auto::save_state(EntitySet& set) const {
  if (!remember_) return;
  const StateFields& sf = resolved(state_fields_, set);
  std::array<double*, 6> f;
  for (std::size_t i = 0; i < 6; ++i) f[i] = sf.field[i]->data();
  f[0][0] = static_cast<double>(solve_index_);
  double *cost = f[1], *step = f[2], *next = f[3], *interval = f[4];
  for (int k = 0; k < member_count; ++k) {
    cost[k] = memory_[k].cost;
    step[k] = memory_[k].step;
    next[k] = static_cast<double>(memory_[k].next_probe);
    interval[k] = static_cast<double>(memory_[k].interval);
  }
  f[5][0] = at_rest_ ? 1.0 : 0.0;
}

void Auto::load_state(const EntitySet& set) {
  if (!remember_) return;
  std::array<const double*, 6> f;  // (once per run, on restart: by name)
  for (std::size_t i = 0; i < 6; ++i) f[i] = set.field(state_names[i]).data();
  solve_index_ = static_cast<long>(f[0][0]);
  const double *cost = f[1], *step = f[2], *next = f[3], *interval = f[4];
  for (int k = 0; k < member_count; ++k) {
    memory_[k].cost = cost[k];
    memory_[k].step = step[k];
    memory_[k].next_probe = static_cast<long>(next[k]);
    memory_[k].interval = std::max(1L, static_cast<long>(interval[k]));
  }
  at_rest_ = f[5][0] != 0;
}

Auto::StateFields Auto::StateFields::of(EntitySet& set) {
  StateFields s;
  for (std::size_t i = 0; i < 6; ++i) s.field[i] = &set.field(state_names[i]);  // (throws when the set lacks one)
  s.cache_key.take(set);
  return s;
}

MOREAU_REGISTER(Auto, "auto")
}  // namespace moreau::auto_solver
MOREAU_PLUGIN_LIBRARY("moreau_solver_auto")
