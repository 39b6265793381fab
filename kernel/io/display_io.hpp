#pragma once
// The display meshes in the output file (docs/output.md): the constant part in the header
// group /display, the world vertex positions in each frame's display/points.
#include <moreau/state.hpp>

#include "display.hpp"
#include "h5.hpp"

namespace moreau::io {

/// `/display`: points (body frame, float64), point_body, cells (XDMF Mixed), cell_body,
/// cell_contactor; attribute `cells` (the cell count, which an XDMF topology needs).
void write_display_header(hid_t root, const DisplayMeshes& m);

/// `display/points` [nv, d] float32 under a frame group, from the state's node poses
/// (Depth::begin: the step's final values at stage `output`).
void write_display_frame(hid_t frame, const DisplayMeshes& m, const State& state);

}  // namespace moreau::io
