#pragma once
// "Did you mean …?" for every unknown name a user types: scene keys, plugin names of any
// kind (shape, law, solver, broadphase, force, hook, …), materials, laws, groups, bodies,
// choices. Case does not count when comparing ("Disk" → "disk", "NLGS" → "nlgs").
#include <string>
#include <vector>

namespace moreau::kernel {

/// The candidate closest to `name`: one equal to it but for case first, else the one at
/// the smallest edit distance, ignoring case, within max(2, |name|/3); "" if none is close.
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

/// `; did you mean "x"?` (with `quote` around x) for the nearest candidate, or "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates, char quote = '"');

}  // namespace moreau::kernel
