#pragma once
// A State field written to / read from an HDF5 group as its table says (FieldSpec::file):
// [rows] or [rows, components], doubles, int32 or int8. Used for the header's constant
// fields, every frame's fields and restarts, so one place knows the conversions.
#include <hdf5.h>

#include <moreau/state.hpp>
#include <string>

namespace moreau::io {

/// Writes `depth` of field `f` as dataset `name` of `where`.
void write_field(hid_t where, const std::string& name, const Field& f, Depth depth);
/// Reads dataset `path` (relative to `where`) into both depths of `f`; InputError naming
/// `file` and `path` when it is missing or has another number of values.
void read_field(hid_t where, const std::string& path, Field& f, const std::string& file);

}  // namespace moreau::io
