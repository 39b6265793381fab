#pragma once
// Internal variables laws share by name on the `contacts` set (docs/laws.md), so that a
// viewer colours every bonded contact alike and the kernel counts bonds per law:
//
//   bond     [1]  int8  0 no bond, 1 intact, 2 broken (or, for `wet`, a ruptured bridge)
//   damage   [1]  1     0 sound … 1 fully damaged (cohesive zones)
//
// A law declaring `bond` gets two counts per frame in the `laws` set (one row per scene
// law, in name order): `bonds`, its intact bonds at the end of the step, and `broken`,
// how many turned from intact to broken since the run began (restart keeps it).
#include <moreau/state.hpp>

namespace moreau::law_fields {

inline constexpr const char* bond = "bond";
inline constexpr const char* damage = "damage";

/// Values of `bond`.
inline constexpr double no_bond = 0, intact = 1, broken = 2;

/// The FieldSpec of `bond` (the kernel completes set, depths, persist, restart, output).
inline FieldSpec bond_field() {
  return field_spec(sets::contacts, bond, 1, 1, 2, "1", FieldOutput::frame, true,
                    "bond of the contact: 0 none, 1 intact, 2 broken", FileType::int8);
}

/// The kernel's `laws` set: counts per scene law (rows in the order of the scene's law
/// names), allocated when some law declares `bond`.
inline constexpr const char* set = "laws";
inline constexpr const char* bonds = "bonds";
inline constexpr const char* broken_count = "broken";

}  // namespace moreau::law_fields
