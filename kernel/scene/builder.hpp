#pragma once
// Scene → World: validates the whole scene first (every fault reported at once, with its
// JSON pointer), loading only the plugins the scene names, then builds the objects.
#include <memory>
#include <string>

#include "../run/world.hpp"
#include "json_file.hpp"

namespace moreau::kernel {

/// Validates and builds. Throws InputErrors (every fault) or InputError, with the file.
/// `output_path` (default: the scene's output.file) sets where plugins write their files.
/// `shadow_solvers`: the text of MOREAU_SHADOW_SOLVERS, which `moreau run` reads ("": none;
/// docs/solvers.md, "Comparing solvers on one run").
std::unique_ptr<World> build_world(const std::string& scene_path, const std::string& output_path = "",
                                   const std::string& shadow_solvers = "");

/// Validates and builds the scene without running or writing anything (what `moreau check`
/// runs). Same errors as build_world.
void check_scene(const std::string& scene_path);
/// The same from a scene already read (the fuzz target parses its input itself; `moreau
/// generate` checks the scene it expanded). Generators are expanded first.
std::unique_ptr<World> build_world(const JsonFile& scene, const std::string& output_path = "",
                                   const std::string& shadow_solvers = "");
void check_scene(const JsonFile& scene);

}  // namespace moreau::kernel
