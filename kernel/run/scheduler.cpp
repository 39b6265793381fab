#include "scheduler.hpp"

#include <algorithm>
#include <cmath>
#include <moreau/error.hpp>
#include <moreau/node_fields.hpp>
#include <ostream>

#include "../plugin/boundary.hpp"
#include "console.hpp"
#include "progress.hpp"

namespace moreau::kernel {

namespace {

class Context : public HookContext {
 public:
  Context(StepContext& step, Stage stage, When when, std::string& stop, const std::function<void()>& refresh)
      : step_(step), stage_(stage), when_(when), stop_(stop), refresh_(refresh) {}
  Stage stage() const override { return stage_; }
  When when() const override { return when_; }
  long step() const override { return step_.step; }
  double time() const override { return step_.time; }
  double time_step() const override { return step_.h; }
  const std::vector<double>& gravity() const override { return step_.gravity; }
  // A hook may read any field: the derived ones are brought up to date first.
  const State& state() const override {
    refresh_();
    return step_.state;
  }
  State& steer() override {
    if (static_cast<int>(stage_) >= static_cast<int>(Stage::solve))
      throw RunError("a hook may change the state only before the solve stage (it ran " +
                     std::string(when_ == When::before ? "before " : "after ") + std::string(stage_name(stage_)) + ")");
    refresh_();
    return step_.state;
  }
  void request_stop(const std::string& reason) override {
    if (stop_.empty()) stop_ = reason.empty() ? "stop requested by a hook" : reason;
  }

 private:
  StepContext& step_;
  Stage stage_;
  When when_;
  std::string& stop_;
  const std::function<void()>& refresh_;
};

}  // namespace

Scheduler::Scheduler(World& world) : w_(world) {
  build_stages();
  for (auto& h : w_.hooks)
    for (auto [stage, when] : plugin_call(h.label(), "while listing its stages", [&] { return h->points(); }))
      hooks_[static_cast<int>(stage)][static_cast<int>(when)].push_back(&h);
}

void Scheduler::build_stages() {
  if (!w_.drivers.empty()) stages_[static_cast<int>(Stage::begin_step)] = [this](StepContext& c) { apply_drivers(c); };
  if (!w_.forces.empty()) {
    stages_[static_cast<int>(Stage::external_forces)] = [this](StepContext& c) {
      // The loads of the step (fields allocated only with force plugins) start from zero.
      for (auto& set : c.state.sets())
        for (auto& f : set.fields())
          if (f.spec().needed == Needed::forces) std::fill(f.data(), f.data() + f.rows() * f.components(), 0.0);
      for (auto& f : w_.forces) f->apply(c);
    };
  }
  // Each modelization's stages, paired with its integrator's, in the order of the models.
  bool bulk = false;
  for (const auto& m : w_.models) bulk = bulk || m.modelization->has_bulk();
  if (bulk)
    stages_[static_cast<int>(Stage::bulk)] = [this](StepContext& c) {
      for (auto& m : w_.models)
        if (m.modelization->has_bulk()) m.modelization->bulk(c);
    };
  stages_[static_cast<int>(Stage::free_velocity)] = [this](StepContext& c) {
    for (auto& m : w_.models) m.integrator->free_velocity(c);
  };
  if (w_.contacts) {
    ContactStages& c = *w_.contacts;
    stages_[static_cast<int>(Stage::detection_configuration)] = [this, &c](StepContext& x) {
      for (auto& m : w_.models) m.integrator->detection_configuration(x);
      c.detection_configuration(x);
    };
    stages_[static_cast<int>(Stage::broad_phase)] = [&c](StepContext& x) { c.broad_phase(x); };
    stages_[static_cast<int>(Stage::narrow_phase)] = [&c](StepContext& x) { c.narrow_phase(x); };
    stages_[static_cast<int>(Stage::warm_start)] = [&c](StepContext& x) { c.warm_start(x); };
    stages_[static_cast<int>(Stage::solve)] = [&c](StepContext& x) { c.solve(x); };
    stages_[static_cast<int>(Stage::store_reactions)] = [&c](StepContext& x) { c.store_reactions(x); };
  }
  stages_[static_cast<int>(Stage::update_dofs)] = [this](StepContext& c) {
    for (auto& m : w_.models) m.integrator->update_dofs(c);
    // What each modelization derives from the ⁺ values (stresses) waits until it is read.
    derived_stale_ = true;
    derived_depth_ = Depth::end;
  };
  stages_[static_cast<int>(Stage::end_step)] = [this](StepContext& c) {
    c.state.swap_depths();
    derived_depth_ = Depth::begin;
  };
}

void Scheduler::refresh_derived_fields() {
  if (!derived_stale_) return;
  derived_stale_ = false;
  for (auto& m : w_.models)
    if (m.modelization->has_derived_fields())
      plugin_call(m.modelization.label(), "while deriving its fields",
                  [&] { m.modelization->derived_fields(w_.state, derived_depth_); });
}

std::string Scheduler::stage_owner(Stage s) const {
  // The plugin whose code a stage runs, for the message of an exception that is not a
  // moreau error (moreau errors keep their own text).
  const std::string stage = "stage " + std::string(stage_name(s));
  switch (s) {
    case Stage::bulk:
      return (w_.models.size() == 1 ? w_.models[0].modelization.label() : "a modelization plugin") + " (" + stage + ")";
    case Stage::free_velocity:
    case Stage::update_dofs:
      return (w_.models.size() == 1 ? w_.models[0].integrator.label() : "an integrator plugin") + " (" + stage + ")";
    case Stage::broad_phase: return w_.contacts->broadphase.label() + " (" + stage + ")";
    case Stage::solve: return w_.contacts->solver.label() + " (" + stage + ")";
    case Stage::external_forces: return "a force plugin (" + stage + ")";
    case Stage::detection_configuration: return "a shape plugin (" + stage + ")";
    case Stage::narrow_phase: return "a detector plugin (" + stage + ")";
    default: return stage;
  }
}

void Scheduler::apply_drivers(StepContext& ctx) {
  // A driver imposes v⁺, the velocity at the end of the step, while start ≤ t⁺ ≤ end, on
  // its rows (a one-node body's node, or a node group of a mesh: the builder resolved them).
  const double t_end = static_cast<double>(ctx.step + 1) * ctx.h;
  auto field = [&](const Driver& d) {
    return ctx.state.field(ctx.state.model_of(static_cast<std::size_t>(d.body)).nodes, node_fields::imposed_velocity).data();
  };
  // Reset the driven rows first: several drivers may share one (different windows).
  for (const auto& d : w_.drivers) {
    double* v = field(d);
    const std::size_t k = d.velocity.size();
    for (const std::size_t r : d.rows) std::fill(v + r * k, v + (r + 1) * k, std::nan(""));
  }
  for (const auto& d : w_.drivers) {
    if (t_end < d.start || t_end > d.end) continue;
    double* v = field(d);
    const std::size_t k = d.velocity.size();
    for (const std::size_t r : d.rows)
      for (std::size_t i = 0; i < k; ++i)
        if (!std::isnan(d.velocity[i])) v[r * k + i] = d.velocity[i];
  }
}

void Scheduler::check_finite(long step) const {
  for (const auto& set : w_.state.sets()) {
    const Field* owner = set.name() == sets::bodies ? nullptr : set.find(body_fields::body);
    for (const auto& f : set.fields()) {
      if (f.spec().output != FieldOutput::frame) continue;
      const double* p = f.data(Depth::begin);
      const std::size_t n = f.rows() * f.components();
      for (std::size_t i = 0; i < n; ++i) {
        if (std::isfinite(p[i])) continue;
        const std::size_t row = i / f.components();
        const std::size_t body = owner ? static_cast<std::size_t>(owner->data()[row]) : row;
        std::string where = "of body '" + w_.state.names()[body] + "'";
        if (set.name() == sets::contacts) where = "of contact " + std::to_string(row);
        else if (owner) where += " (" + set.name() + " row " + std::to_string(row) + ")";
        throw RunError("non-finite value in field '" + f.name() + "' " + where + " after step " + std::to_string(step));
      }
    }
  }
}

RunSummary Scheduler::run(const RunOptions& opt) {
  RunSummary sum;
  sum.first_step = opt.first_step;
  const long last = opt.steps ? opt.first_step + *opt.steps : w_.total_steps;
  StepContext ctx{w_.state};
  ctx.h = w_.h;
  ctx.theta = w_.theta;
  ctx.gravity = w_.gravity;
  ctx.external_forces = !w_.forces.empty();
  std::string stop;

  auto write = [&](long step) {
    if (!opt.sink) return;
    refresh_derived_fields();
    check_finite(step);
    const auto t0 = StageTimer::clock::now();
    const SolverInfo solver = w_.contacts ? SolverInfo{w_.contacts->last_iterations(), w_.contacts->last_error()} : SolverInfo{};
    const auto extra = w_.analyses ? w_.analyses->at_frame(w_, step) : std::vector<io::FrameGroup>{};
    opt.sink->write_frame(step, static_cast<double>(step) * w_.h, w_.state, solver, extra);
    sum.timer.add(Stage::output, StageTimer::clock::now() - t0);
  };
  const std::function<void()> refresh = [this] { refresh_derived_fields(); };
  auto run_hooks = [&](Stage s, When when) {
    auto& list = hooks_[static_cast<int>(s)][static_cast<int>(when)];
    if (list.empty()) return;
    const auto t0 = StageTimer::clock::now();
    Context hc(ctx, s, when, stop, refresh);
    for (const Owned<Hook>* h : list) {
      try {
        (*h)->run(hc);
      } catch (...) {
        rethrow_kernel_owned(h->label(), "at step " + std::to_string(ctx.step + 1) + " (" +
                                             (when == When::before ? "before" : "after") + " stage " + std::string(stage_name(s)) + ")");
      }
    }
    sum.timer.add_hooks(StageTimer::clock::now() - t0);
  };

  std::optional<Progress> progress;
  if (opt.progress) progress.emplace(*opt.progress, opt.progress_terminal, opt.first_step, last);
  if (progress && opt.progress_terminal) set_active_progress(&*progress);  // warnings erase the bar first
  struct Reset {
    ~Reset() { set_active_progress(nullptr); }
  } reset;
  // Derived fields are not restart fields: the first frame (or a restart's) has them too.
  derived_stale_ = true;
  derived_depth_ = Depth::begin;
  if (opt.write_first_frame) write(opt.first_step);

  long step = opt.first_step;
  while (step < last) {
    bool written = false;
    ctx.step = step;
    ctx.time = static_cast<double>(step) * w_.h;  // never accumulated: restarts stay bit-identical
    for (int i = 0; i < stage_count; ++i) {
      const Stage s = static_cast<Stage>(i);
      run_hooks(s, When::before);
      if (s == Stage::output) {
        const long done = step + 1;
        if (w_.analyses) {  // some need every step (energy dissipated between frames)
          const auto t0 = StageTimer::clock::now();
          w_.analyses->after_step(w_, done);
          sum.timer.add(Stage::output, StageTimer::clock::now() - t0);
        }
        const bool due = done % w_.output.every == 0 || done == last || !stop.empty();
        if (due) {
          write(done);
          written = true;
        }
      } else if (stages_[i]) {
        const auto t0 = StageTimer::clock::now();
        try {
          stages_[i](ctx);
        } catch (...) {
          rethrow_kernel_owned(stage_owner(s), "at step " + std::to_string(step + 1));
        }
        sum.timer.add(s, StageTimer::clock::now() - t0);
      }
      run_hooks(s, When::after);
    }
    ++step;
    if (progress) progress->update(step, static_cast<double>(step) * w_.h);
    const int signal = opt.interrupt ? opt.interrupt->load() : 0;
    if (stop.empty() && signal == 0) continue;
    // A stop asked after the output stage, or an interrupt, still gets its frame.
    if (!written) write(step);
    if (stop.empty()) sum.interrupted_by = signal;
    break;
  }
  if (progress) progress->finish(step, static_cast<double>(step) * w_.h);
  if (!w_.hooks.empty()) refresh_derived_fields();
  for (auto& h : w_.hooks) plugin_call(h.label(), "at the end of the run", [&] { h->finish(w_.state); });
  if (opt.sink) opt.sink->close();
  if (w_.contacts) sum.timer.set_solve_assembly(w_.contacts->assembly_seconds());
  if (w_.contacts && w_.contacts->shadows) sum.timer.set_solve_shadows(w_.contacts->shadows->stage_seconds());
  sum.last_step = step;
  sum.stopped_by_hook = !stop.empty();
  sum.stop_reason = stop;
  return sum;
}

}  // namespace moreau::kernel
