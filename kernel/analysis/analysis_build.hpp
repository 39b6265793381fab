#pragma once
// Building the scene's `analyses` (docs/analyses.md): the kernel keys of an entry
// (`type`, `name`, `region`, `every`) are checked here; the plugin's own keys by its
// schema, like any plugin's.
#include <memory>
#include <moreau/error.hpp>
#include <moreau/params.hpp>
#include <moreau/plugin.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis_runner.hpp"

namespace moreau::kernel {

class Registry;
struct World;

/// One validated entry of `analyses`: the plugin, its parameters, and the entry as written.
struct AnalysisEntry {
  std::string type;
  Params params;
  std::string pointer;
  nlohmann::json entry;
};

/// The keys of an entry that are the kernel's, not the plugin's.
std::vector<std::string> analysis_kernel_keys();

/// Checks the kernel keys of every entry (unique names, `every`, the region's form),
/// appending faults to `errors`.
void check_analysis_entries(const std::vector<AnalysisEntry>& entries, int dim, std::vector<InputError>& errors);

/// Creates the analyses (after the bodies and contacts are built), checks each region
/// against the scene's extent and lets each plugin check its names (InputError).
std::unique_ptr<AnalysisRunner> build_analyses(const World& world, Registry& registry, const BuildContext& ctx,
                                               const std::vector<AnalysisEntry>& entries);

}  // namespace moreau::kernel
