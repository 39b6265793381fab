#pragma once
// The shapes a viewer draws (output `display: "shapes"`, docs/output.md): every
// contactor's display mesh (Shape::display_mesh) placed in its body frame and joined into
// one unstructured mesh. The connectivity and the body-frame vertices never change, so
// they are written once (`/display`); a frame adds only the vertices' world positions, in
// float32 (`/frames/N/display/points`, 4 d bytes per vertex): that is what grows with the
// run, and float32 keeps 1e-7 relative, far below what a screen shows.
#include <cstddef>
#include <moreau/shape.hpp>
#include <vector>

namespace moreau::io {

/// Cell type ids of an XDMF Mixed topology (the same in XDMF 2 and 3). Polyvertex and
/// polygon cells carry their vertex count after the type; triangles and quads do not.
inline constexpr int xdmf_polyvertex = 1, xdmf_polygon = 3, xdmf_triangle = 4, xdmf_quadrilateral = 5;

struct DisplayMeshes {
  int dimension = 3;
  std::vector<double> points;       ///< vertices in the frame of their node, 3 values each (2D: z = 0), m
  std::vector<int> point_body;      ///< body of each vertex
  std::vector<int> point_node;      ///< node of each vertex: index into the frame's node poses (NodePoses)
  std::vector<int> cells;           ///< XDMF Mixed connectivity: each cell's type, [vertex count,] vertices
  std::vector<int> cell_body;       ///< body of each cell
  std::vector<int> cell_contactor;  ///< contactor of each cell (index into /contactors)
  std::size_t vertices() const { return point_body.size(); }
  std::size_t cell_count() const { return cell_body.size(); }
};

/// Appends a contactor's mesh (in its own frame) moved into its node's frame (rigid: the
/// body frame) by its placement: p = offset + R_c v, with `rotation` a 2D angle in [0] or a
/// 3D unit quaternion w x y z. `node` indexes the node poses of world_points. An empty mesh
/// becomes one vertex at the contactor's origin, so every contactor shows. Throws
/// std::invalid_argument on an index out of the mesh's vertices.
void add_contactor(DisplayMeshes& m, const DisplayMesh& mesh, int body, int node, int contactor, const double offset[3],
                   const double rotation[4]);

/// World positions of the vertices, x_n + R_n p, from the node poses: positions [nn, d] and
/// rotations (2D: angles [nn]; 3D: unit quaternions [nn, 4]): d floats per vertex.
void world_points(const DisplayMeshes& m, std::size_t nodes, const double* position, const double* rotation,
                  std::vector<float>& out);

}  // namespace moreau::io
