#pragma once
// A shape (contactor geometry), registered by name. One object per contactor, attached
// at its body's origin, in the body frame. Detectors read a shape's parameters through
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
#include <moreau/modelization.hpp>
#include <moreau/plugin.hpp>
#include <vector>

namespace moreau {

/// A body pose: position (d values) and rotation (2D: angle; 3D: unit quaternion w x y z).
struct Pose {
  const double* position;
  const double* rotation;
};

class MOREAU_API Shape : public Plugin {
 public:
  static constexpr Kind kind = Kind::shape;
  virtual const char* shape_name() const = 0;
  virtual const std::vector<double>& geometry() const = 0;
  /// Unit-density mass properties in the body frame; `has_mass()` false for unbounded shapes.
  virtual bool has_mass() const { return true; }
  virtual MassProperties mass_properties() const = 0;
  /// World axis-aligned bounding box for a pose (3 values each; 2D leaves z at 0).
  /// Unbounded shapes return infinite extents.
  virtual void bounds(int dim, const Pose& pose, double lo[3], double hi[3]) const = 0;
};

}  // namespace moreau
