#pragma once
// Generators (plugin kind `generator`): make bodies — regular arrays, random loose
// deposits — from a few parameters, so a scene need not list every grain. A scene lists
// them under `generators`; before the scene is validated, the kernel runs each in turn
// and appends the bodies it returns to `bodies` (a pre-pass on the scene's JSON): the
// generated bodies are ordinary body objects, validated and built like any other, and
// `moreau generate SCENE --out FULL.json` writes them out as a plain scene.
//
// A generator must be deterministic: the same parameters (including its seed, when it
// draws random numbers) and the same scene give the same bodies, bit for bit.
#include <moreau/plugin.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace moreau {

struct GeneratorInput {
  int dimension = 3;
  /// The scene as it stands: its own bodies, then those of the generators before this one
  /// (a generator may keep clear of them). Not yet validated: read it defensively.
  const nlohmann::json& scene;
  std::string pointer;  ///< this generator's JSON pointer (/generators/i), for errors
};

class MOREAU_API Generator : public Plugin {
 public:
  static constexpr Kind kind = Kind::generator;
  /// The bodies to append, as scene body objects ({"name", "position", "contactors", …}).
  /// Faults the schema cannot express (grains that do not fit) throw InputError at a
  /// pointer below `in.pointer`, saying what was expected.
  virtual std::vector<nlohmann::json> generate(const GeneratorInput& in) = 0;
};

}  // namespace moreau
