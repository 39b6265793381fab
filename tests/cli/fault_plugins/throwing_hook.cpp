// A hook that throws, at a chosen step, one of: a moreau RunError, a moreau InputError, a
// std::runtime_error, an exception class of its own (its what() is code of this library)
// or an int.
#include <moreau/error.hpp>
#include <moreau/hook.hpp>
#include <stdexcept>

namespace {

struct OwnError : std::exception {
  const char* what() const noexcept override { return "own error class of the plugin"; }
};

class Throwing : public moreau::Hook {
 public:
  static moreau::Schema schema() {
    moreau::Schema s;
    s.string("throw", "what to throw").one_of({"run_error", "input_error", "std", "own", "int"});
    s.integer("at_step", "step at which to throw").min(0).fallback(3);
    return s;
  }
  static constexpr const char* doc = "test hook that throws";
  Throwing(const moreau::Params& p, const moreau::BuildContext&) : what_(p.string("throw")), at_(p.integer("at_step")) {}
  std::vector<std::pair<moreau::Stage, moreau::When>> points() const override {
    return {{moreau::Stage::end_step, moreau::When::after}};
  }
  void run(moreau::HookContext& ctx) override {
    if (ctx.step() != at_) return;
    if (what_ == "run_error") throw moreau::RunError("throwing hook: the run cannot go on");
    if (what_ == "input_error") throw moreau::InputError("/hooks/0", "throwing hook: bad parameter");
    if (what_ == "std") throw std::runtime_error("throwing hook: std::runtime_error");
    if (what_ == "own") throw OwnError();
    throw 42;
  }

 private:
  std::string what_;
  long at_;
};

}  // namespace

MOREAU_REGISTER(Throwing, "throwing")
MOREAU_PLUGIN_LIBRARY("moreau_hook_throwing")
