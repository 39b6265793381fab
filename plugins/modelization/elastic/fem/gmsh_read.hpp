#pragma once
// Gmsh mesh files (.msh), formats 2.2 and 4.1, ASCII or binary (moreau's own reader: see
// docs/deformable.md for why not libgmsh).
//
// The mesh dimension is the highest dimension of the file's elements; those must be T3/Q4
// (2D, in a plane z = constant) or T4/H8 (3D). Physical groups become named sets (a group
// with no name is named by its number):
//   - of the mesh dimension: element set and node set;
//   - one dimension below: boundary set (its edges/faces matched to element faces, which
//     gives them their outward order) and node set;
//   - lower (points, and curves of a 3D mesh): node set.
// Like the generators, the reader adds the element set "all" and the boundary set and node
// set "boundary" (the whole boundary) unless the file defines groups of those names.
// Only nodes of mesh-dimension elements are kept, in file order. In 2D, the elements of a
// geometric surface that are all clockwise (a surface meshed with normal −z) are turned
// counter-clockwise (a note says so); elements still inverted after that are errors.
// Sections other than $MeshFormat, $PhysicalNames, $Entities, $Nodes and $Elements are
// skipped, each named in Mesh::notes. The mesh is checked (check_mesh) before it is returned.
//
// Errors throw MeshError with the file and line (ASCII) or byte offset (binary) and what
// was expected there; an unsupported element type is named with the supported ones.
#include <string>
#include <string_view>

#include "mesh.hpp"

namespace moreau::fem {

Mesh read_gmsh(const std::string& path);

/// The same on a file's content already in memory; `name` stands for the file in messages.
Mesh parse_gmsh(std::string_view content, const std::string& name);

}  // namespace moreau::fem
