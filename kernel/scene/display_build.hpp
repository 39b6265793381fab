#pragma once
// Gathers the contactors' display meshes (Shape::display_mesh) at build time, for the
// output's `display: "shapes"` (kernel/io/display.hpp).
#include <memory>
#include <moreau/shape.hpp>
#include <moreau/state.hpp>
#include <vector>

#include "../io/display.hpp"
#include "../io/output_writer.hpp"

namespace moreau::kernel {

/// The meshes of every contactor (`shapes[i]` is contactor `info[i]`), placed in their
/// body frames. Each shape is told how far the scene reaches from its origin at the start
/// (the largest distance to a corner of the box around the bodies and bounded shapes), so
/// that a plane draws a patch under the whole scene. Null when the state has no body poses.
/// A plugin's malformed mesh is a RunError naming the shape.
std::shared_ptr<const io::DisplayMeshes> build_display(const State& state, const std::vector<io::ContactorInfo>& info,
                                                       const std::vector<const Shape*>& shapes);

/// Each contactor's `reach` (`shapes[i]` is contactor `info[i]`): |offset| + the radius
/// of its bounds at the identity pose about its own origin; infinite for a half-space. For
/// the force network (kernel/io/force_network.hpp).
void set_contactor_reach(int dim, std::vector<io::ContactorInfo>& info, const std::vector<const Shape*>& shapes);

}  // namespace moreau::kernel
