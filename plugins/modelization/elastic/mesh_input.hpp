#pragma once
// The `mesh` of an elastic body in a scene (docs/scene.md, "Elastic bodies"): a Gmsh file
// or a generated rectangle, disk or box. Faults become InputErrors at the JSON pointer of
// the offending key, with the library's message (file and line, element number).
#include <moreau/params.hpp>
#include <string>

#include "fem/mesh.hpp"

namespace moreau::elastic {

/// Reads or generates the mesh described by `mesh` (the body's `mesh` object at
/// `pointer`); relative file paths resolve against `scene_dir`. Then moves it by `offset`
/// (d values). The mesh's dimension must be `dim`.
fem::Mesh scene_mesh(const nlohmann::json& mesh, const std::string& pointer, const std::string& scene_dir, int dim,
                     const std::vector<double>& offset);

}  // namespace moreau::elastic
