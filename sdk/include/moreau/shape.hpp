#pragma once
// A shape (contactor geometry), registered by name. One object per contactor, in its own
// frame; the kernel places it in the body frame (contactor keys `offset`, `angle` /
// `orientation`) and hands detectors and bounds() the composed pose, so "body frame" and
// "body origin" below mean the shape's frame and origin. Detectors read a shape's parameters through
// `shape_name()` and `geometry()` (documented per shape below), so a third party's
// detector can pair with any shape without sharing its C++ class.
//
//   disk     2D  geometry = {radius}
//   segment  2D  geometry = {length, thickness}  (rounded: a capsule along the body x axis)
//   sphere   3D  geometry = {radius}
//   plane    3D  geometry = {nx, ny, nz}           (half-space below the plane through the
//                                                  body origin, outward unit normal, body frame)
//   polygon  2D  geometry = {n, x0, y0, …}          (convex, counter-clockwise, body frame)
//   box      3D  geometry = {lx, ly, lz}            (full edge lengths along the body axes)
//   convex   3D  geometry = {nv, x0, y0, z0, …, nf, k, i0…i(k−1), …}  (corners, then the hull's
//                                                  faces as corner indices, counter-clockwise
//                                                  seen from outside)
//   point    2D, 3D  geometry = {0}                (a node of a mesh, LMGC90's candidate CLxxx /
//                                                  CSxxx: a round shape of radius 0, so a detector
//                                                  written for disks or spheres takes it as is)
//   edge     2D  geometry = {}    support = facet  (a boundary edge of a mesh, LMGC90's ALpxx: its
//                                                  2 nodes come in Pose::nodes)
//   face     3D  geometry = {}    support = facet  (a boundary triangle or quadrangle of a mesh,
//                                                  LMGC90's ASpxx: its 3 or 4 nodes in Pose::nodes)
#include <moreau/modelization.hpp>
#include <moreau/plugin.hpp>
#include <vector>

namespace moreau {

/// What a viewer draws for a shape, in the shape's own frame; the mechanics never read it.
/// 2D shapes give their outline as one polygon (z = 0); 3D shapes give their surface as
/// polygons (triangles or flat faces), counter-clockwise seen from outside.
struct DisplayMesh {
  std::vector<double> points;  ///< x y z per vertex, m, shape frame
  std::vector<int> sizes;      ///< vertex count of each polygon (≥ 3)
  std::vector<int> indices;    ///< the polygons' vertex indices (into points), concatenated
  bool empty() const { return sizes.empty(); }
};

/// A body pose: position (d values) and rotation (2D: angle; 3D: unit quaternion w x y z).
/// A facet shape (Support::facet) is placed by its nodes instead: `nodes` holds their
/// world positions (3 values each, z = 0 in 2D) in the facet's outward order
/// (FacetGroup), `position` the first of them and `rotation` the identity.
struct Pose {
  const double* position;
  const double* rotation;
  const double* nodes = nullptr;
  int node_count = 0;
};

/// What supports a contactor (docs/architecture.md): one node, whose pose (composed with
/// the contactor's placement) places the shape — rigid bodies, candidate points of a mesh —
/// or the nodes of one boundary facet of a mesh, which are the shape (antagonist edges and
/// faces). A facet contactor's contact points carry their interpolation weights on those
/// nodes (ContactPoint::weights).
enum class Support { node, facet };

class MOREAU_API Shape : public Plugin {
 public:
  static constexpr Kind kind = Kind::shape;
  virtual const char* shape_name() const = 0;
  virtual const std::vector<double>& geometry() const = 0;
  /// Unit-density mass properties in the body frame; `has_mass()` false for unbounded
  /// shapes and for the shapes of a mesh (point, edge, face: the body's mass is its
  /// material's).
  virtual bool has_mass() const { return true; }
  /// Node (the default) or facet (see Support).
  virtual Support support() const { return Support::node; }
  virtual MassProperties mass_properties() const = 0;
  /// World axis-aligned bounding box for a pose (3 values each; 2D leaves z at 0).
  /// Unbounded shapes return infinite extents.
  virtual void bounds(int dim, const Pose& pose, double lo[3], double hi[3]) const = 0;
  /// The mesh drawn for this shape (output `display: "shapes"`). `extent` (m) is how far
  /// the scene reaches from the shape's origin at the start: an unbounded shape draws a
  /// patch that large. Empty (the default): the viewer shows a point at the shape's origin,
  /// unless the shape has no mass either (a mesh's point, edge or face: the mesh is drawn).
  virtual DisplayMesh display_mesh(double extent) const {
    (void)extent;
    return {};
  }
  /// Half the shape's smallest width (m): how far another body must move into it to reach
  /// its middle (a disk or sphere: its radius; a segment: half its thickness; a half-space:
  /// infinite). The kernel compares a step's motion with it to find the pairs that need
  /// swept detection (docs/contacts.md, "Fast bodies"); a value too large lets a fast body
  /// through a thin shape, one too small only costs detection time. The default: half the
  /// smallest side of the bounding box at the identity pose, exact for shapes aligned with
  /// their axes (override it for others, e.g. polygons).
  virtual double half_width(int dim) const {
    const double zero[4] = {0, 0, 0, 0}, identity[4] = {1, 0, 0, 0};
    double lo[3], hi[3];
    bounds(dim, Pose{zero, dim == 2 ? zero : identity}, lo, hi);
    double w = hi[0] - lo[0];
    for (int k = 1; k < dim; ++k) w = hi[k] - lo[k] < w ? hi[k] - lo[k] : w;
    return w / 2;
  }
};

}  // namespace moreau
