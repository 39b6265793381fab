#pragma once
// Hooks: user code run before and after any stage of a step (the User plugin, user/).
// A hook reads the whole state at any point; it may write it (steer: imposed
// velocities, extra forces) only before the solve stage, so that what the solver and
// the output see stays consistent. It may ask the run to stop after the current step.
#include <moreau/plugin.hpp>
#include <moreau/stage.hpp>
#include <moreau/state.hpp>
#include <string>
#include <utility>
#include <vector>

namespace moreau {

class MOREAU_API HookContext {
 public:
  virtual ~HookContext() = default;
  virtual Stage stage() const = 0;
  virtual When when() const = 0;
  virtual long step() const = 0;       ///< index of the current step
  virtual double time() const = 0;     ///< t⁻ of the current step (s)
  virtual double time_step() const = 0;
  virtual const std::vector<double>& gravity() const = 0;  ///< d components (m/s²)
  virtual const State& state() const = 0;
  /// Writable state; throws RunError from the solve stage on (read-only there).
  virtual State& steer() = 0;
  /// Ends the run cleanly after the current step (its frame is written).
  virtual void request_stop(const std::string& reason) = 0;
};

class MOREAU_API Hook : public Plugin {
 public:
  static constexpr Kind kind = Kind::hook;
  /// Where this hook runs. Stages no hook asks for cost nothing.
  virtual std::vector<std::pair<Stage, When>> points() const = 0;
  virtual void run(HookContext& ctx) = 0;
  /// Once, after the last step (flush files…); the run's final state.
  virtual void finish(const State&) {}
};

}  // namespace moreau
