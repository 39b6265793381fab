#pragma once
// Convex shapes in 2D (polygons, possibly rounded) and 3D (polyhedra), their mass
// properties, and contact generation between them (DESIGN §1 narrow phase):
// separating axes give the gap, and when a face is the closest feature the touching
// faces are clipped against each other so a face contact gets a manifold (2 points in
// 2D, up to 4 in 3D) and stacks stand. In 3D, vertices within the alert distance in
// front of a face of the other body are added as predictive points, so a polyhedron
// pivoting on an edge or a corner is caught before its far side goes through.
//
// Conventions of every detector: the normal points from the second shape toward the
// first; the point is midway between the two surfaces; gap < 0 is overlap.
#include <array>
#include <moreau/detector.hpp>
#include <moreau/modelization.hpp>
#include <string>
#include <vector>

#include "vec.hpp"

namespace moreau::geom {

// ---- 2D -------------------------------------------------------------------------------

/// A convex polygon in the world frame, counter-clockwise, grown by `radius` (a rounded
/// polygon; a segment is a 2-vertex polygon with radius half its thickness).
struct Polygon {
  std::vector<V2> v;
  double radius = 0;
};

/// Validates polygon vertices (x0, y0, x1, y1, …): at least 3, convex, no collinear or
/// repeated vertices. Returns them counter-clockwise; throws std::invalid_argument naming
/// the fault.
std::vector<V2> convex_polygon(const std::vector<std::array<double, 2>>& vertices);
MassProperties polygon_mass(const std::vector<V2>& ccw);
/// Half the smallest width of a convex polygon (its width is smallest across an edge).
double polygon_half_width(const std::vector<V2>& ccw);
/// Shape geometry {n, x0, y0, …} placed at a pose.
Polygon polygon_at(const std::vector<double>& geometry, const Pose& pose);
/// A `segment` shape {length, thickness} placed at a pose.
Polygon segment_at(const std::vector<double>& geometry, const Pose& pose);

void polygon_polygon(const Polygon& a, const Polygon& b, double alert, std::vector<ContactPoint>& out);
void disk_polygon(V2 centre, double radius, const Polygon& b, double alert, std::vector<ContactPoint>& out);

// ---- 3D -------------------------------------------------------------------------------

/// A convex polyhedron: vertices, faces (vertex indices, counter-clockwise seen from
/// outside), outward unit face normals and plane offsets (n·x = d on the face), edges.
struct Polyhedron {
  std::vector<V3> v;
  std::vector<std::vector<int>> faces;
  std::vector<V3> normal;
  std::vector<double> offset;
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 2>> edge_faces;  ///< the two faces meeting at each edge
  V3 centre;  ///< mean of the vertices (inside)
  void finish();  ///< computes normals, offsets, edges, edge_faces and centre from v and faces
};

/// Faces of the convex hull of points (counter-clockwise from outside, coplanar faces
/// merged). Throws std::invalid_argument if the points are fewer than 4, repeated or
/// coplanar, or if some point is not a vertex of the hull (`convex` shapes list only
/// vertices).
std::vector<std::vector<int>> hull_faces(const std::vector<V3>& points);
MassProperties polyhedron_mass(const Polyhedron& body_frame);
/// Half the smallest width across a face (an upper bound of half the smallest width, which
/// an edge pair may set; equal for boxes, plates and prisms).
double polyhedron_half_width(const Polyhedron& p);
/// Shape geometry placed at a pose: `box` {lx, ly, lz}; `convex` {nv, x0, y0, z0, …, nf,
/// k0, i…, k1, i…} (faces as vertex indices, counter-clockwise from outside).
Polyhedron polyhedron_at(const std::string& shape, const std::vector<double>& geometry, const Pose& pose);
std::vector<double> box_geometry_as_convex(const std::vector<double>& box);

void polyhedron_polyhedron(const Polyhedron& a, const Polyhedron& b, double alert, std::vector<ContactPoint>& out);
/// First the polyhedron, second the half-space {x : n·(x − p) ≤ 0}.
void polyhedron_plane(const Polyhedron& a, V3 n, V3 p, double alert, std::vector<ContactPoint>& out);
void sphere_polyhedron(V3 centre, double radius, const Polyhedron& b, double alert, std::vector<ContactPoint>& out);

/// Keeps at most 4 of the points of a manifold: the deepest, and those spanning the
/// largest area around it (so the support polygon is kept).
void reduce_manifold(std::vector<ContactPoint>& points, std::size_t first);

}  // namespace moreau::geom
