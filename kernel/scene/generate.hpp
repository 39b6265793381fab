#pragma once
// The scene's `generators` (docs/analyses.md#generators), run as a pre-pass on the scene's
// JSON before it is validated: each generator plugin returns body objects that are
// appended to `bodies`, so the builder sees a plain scene. `moreau generate` writes that
// scene out (a run is then reproducible without the generators).
#include <cstddef>
#include <moreau/error.hpp>
#include <string>
#include <vector>

#include "json_file.hpp"

namespace moreau::kernel {

/// Where the generators put their bodies in the expanded scene, so that a fault found
/// later in a generated body names the generator that made it.
class Generated {
 public:
  struct Range {
    std::size_t first = 0, count = 0;  ///< indices into `bodies`
    std::string pointer;               ///< /generators/i
  };
  std::vector<Range> ranges;

  /// Runs `body`, rewriting the messages of input errors in generated bodies.
  template <class F>
  auto locate(F&& body) const {
    try {
      return body();
    } catch (const InputErrors& e) {
      std::vector<InputError> out;
      for (const auto& x : e.errors()) out.push_back(locate(x));
      throw InputErrors(std::move(out));
    } catch (const InputError& e) {
      throw locate(e);
    }
  }
  InputError locate(const InputError& e) const;
};

/// Runs the scene's generators in order and appends their bodies to `bodies`; the
/// expanded scene (file.value) has no `generators` key. Faults: InputErrors / InputError
/// naming the file and the generator's JSON pointer.
Generated expand_generators(JsonFile& file);

}  // namespace moreau::kernel
