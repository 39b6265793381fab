#pragma once
// The kernel's table of the `contacts` set (docs/architecture.md, docs/output.md): one row
// per contact of the current step, rebuilt at stage warm_start. Fields marked `persist`
// carry their values over to the next step's row of the same identity (`key`): the local
// impulse (the solver's warm start), the status (static/dynamic friction) and the laws'
// internal variables, which each law declares on this set (law.hpp, law_fields.hpp). The table drives the output's contacts/ datasets and the restart
// (fields marked `restart`: the keys and what persists), like every other set.
//
// Conventions: the force acts on the first body, its opposite on the second; the normal
// points from the second body toward the first; local vectors are normal first, then
// t (2D) or t, s (3D), the frame built from n alone (kernel/contact/local_frame.hpp).
#include <moreau/state.hpp>
#include <vector>

namespace moreau::contact_fields {

inline constexpr const char* bodies = "bodies";
inline constexpr const char* key = "key";
inline constexpr const char* point = "point";
inline constexpr const char* normal = "normal";
inline constexpr const char* gap = "gap";
inline constexpr const char* impulse = "impulse";
inline constexpr const char* force = "force";
inline constexpr const char* normal_force = "normal_force";
inline constexpr const char* status = "status";
inline constexpr const char* velocity = "velocity";
inline constexpr const char* law = "law";

inline std::vector<FieldSpec> table() {
  using O = FieldOutput;
  auto f = [](const char* name, int c2, int c3, const char* units, O out, const char* doc, FileType type = FileType::real,
              bool restart = false, bool persist = false) {
    FieldSpec s = field_spec(sets::contacts, name, c2, c3, 1, units, out, restart, doc, type, Needed::contacts);
    s.persist = persist;
    return s;
  };
  return {
      f(bodies, 2, 2, "1", O::frame, "its two bodies (indices into /bodies): the force acts on the first", FileType::int32),
      f(key, 3, 3, "1", O::frame, "its identity: first contactor, second contactor, feature (indices into /contactors)",
        FileType::int32, true),
      f(point, 2, 3, "m", O::frame, "contact point, world, at the detection configuration"),
      f(normal, 2, 3, "1", O::frame, "unit normal, world, from the second body toward the first"),
      f(gap, 1, 1, "m", O::frame, "signed gap at the detection configuration (negative: overlap)"),
      f(impulse, 2, 3, "N s", O::frame, "local impulse r over the step, normal first (the next step's warm start)",
        FileType::real, true, true),
      f(force, 2, 3, "N", O::frame, "the force on the first body, world frame (impulse / h)"),
      f(normal_force, 1, 1, "N", O::frame, "normal force, impulse_n / h (negative: a bond in tension)"),
      f(status, 1, 1, "1", O::frame, "0 open, 1 sticking, 2 sliding (the next step's laws read it: static/dynamic friction)",
        FileType::int8, true, true),
      f(velocity, 2, 3, "m/s", O::none, "local relative velocity at the end of the step (u = W r + q), normal first"),
      f(law, 1, 1, "1", O::none, "its contact law (index into the scene's laws, in name order)"),
  };
}

}  // namespace moreau::contact_fields
