#pragma once
// A solver linked into a test program, by name, with `params` over its schema's defaults
// (validated as a scene's `solver` block would be). Shared by the solver tests
// (solver_cases.hpp) and moreau_bench_portfolio.
#include <memory>
#include <moreau/solver.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/scene/validate.hpp"
#include "sim.hpp"

namespace solver_cases {

inline std::unique_ptr<moreau::Solver> registered_solver(const std::string& name, const nlohmann::json& params,
                                                         const std::string& what) {
  for (auto& r : moreau::detail::local_registrations())
    if (r.kind == moreau::Kind::solver && r.name == name) {
      std::vector<moreau::InputError> errors;
      moreau::kernel::Validation v{3, errors};
      nlohmann::json filled = moreau::kernel::validate_object(params, r.schema, "/solver", v);
      if (!errors.empty()) throw errors.front();
      return moreau_test::create<moreau::Solver>(name, filled, moreau::BuildContext{});
    }
  throw std::logic_error("no solver " + what + " linked into the program");
}

}  // namespace solver_cases
