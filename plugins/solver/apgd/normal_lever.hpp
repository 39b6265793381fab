#pragma once
// How much of W's normal entries comes through the bodies' rotation, measured on the body
// factor: what decides whether APGD's `normal_tangent` scaling (apgd_core.hpp, Scaling)
// pays in a time step. A contact whose normal passes through the centre of each body it
// touches (disks, spheres) has no rotational part in its normal row of H: its normal entry
// is the bodies' translational 1/m, its tangential ones 1/m + r²/I (a sphere: 3.5/m), W's
// own block of it is diagonal, and scaling the normal by its own entry steps it longer than
// one scalar per contact allows. A contact off a block's centre (boxes, bricks, polygons,
// clusters) turns its body: its normal is coupled through that rotation to its tangents
// and to the block's other contacts, and the per-direction diagonal then steps worse
// (measured: docs/solvers.md "auto", APGD's scaling in time steps).
#include <moreau/contact_problem.hpp>

namespace moreau::apgd {

/// The mean over contacts of the share of the normal diagonal entry W_nn (compliance
/// included) that comes through the bodies' rotation: per contact Σ_s h_R M⁻¹_RR h_Rᵀ / W_nn,
/// h_R the rotational part (the last k − dim entries) of side s's normal row of H, M⁻¹_RR
/// its body's rotational block. In [0, 1]: 0 for disks and spheres, 0.7 for a 2 × 1 brick
/// on its corners. Costs about a tenth of a product by W. 0 without a factor or contacts.
double normal_lever(int dim, const BodyFactor& f);

/// Below this mean share `auto` scales APGD's steps per direction in a time step (the
/// example scenes: disks and spheres 0, box_tower_3d 0.83, masonry_arch_2d 0.63, brick_wall_2d and
/// mortar_wall_2d 0.5, clusters_3d 0.3 to 0.4).
constexpr double round_contacts_max_lever = 0.1;

/// Whether the contacts are those of round bodies (normal_lever below the bound).
inline bool round_contacts(int dim, const BodyFactor& f) { return normal_lever(dim, f) < round_contacts_max_lever; }

}  // namespace moreau::apgd
