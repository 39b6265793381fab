#pragma once
// The stages of one time step, in order (DESIGN §1, LMGC90's sequence). Every stage is
// a hook point: hooks run before and after it.
#include <array>
#include <string_view>

namespace moreau {

enum class Stage {
  begin_step,
  external_forces,
  bulk,
  free_velocity,
  detection_configuration,
  broad_phase,
  narrow_phase,
  warm_start,
  solve,
  store_reactions,
  update_dofs,
  end_step,
  output,
};
inline constexpr int stage_count = 13;

inline constexpr std::array<std::string_view, stage_count> stage_names = {
    "begin_step",   "external_forces", "bulk",  "free_velocity",   "detection_configuration",
    "broad_phase",  "narrow_phase",    "warm_start", "solve",      "store_reactions",
    "update_dofs",  "end_step",        "output"};

inline std::string_view stage_name(Stage s) { return stage_names[static_cast<int>(s)]; }

enum class When { before, after };

}  // namespace moreau
