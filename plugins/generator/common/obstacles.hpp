#pragma once
// The scene's bodies a generator keeps its grains clear of (parameter `avoid`, a list of
// body names; when absent, every body listed so far or none, as the generator chooses). Their shapes are read from the
// scene's JSON (position, angle / orientation, each contactor's offset and rotation):
// disks, spheres, rounded segments, planes (half-spaces), polygons and boxes exactly;
// convex polyhedra by their bounding sphere (conservative).
#include <moreau/params.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grains.hpp"

namespace moreau::generate {

class Obstacles {
 public:
  /// `key` absent: every body of the scene so far (`all_by_default`) or none.
  static Obstacles parse(const Params& p, const std::string& key, const nlohmann::json& scene, int dim,
                         bool all_by_default);

  /// The gap between ball (x, r) and the nearest obstacle (+inf without obstacles; < 0:
  /// they overlap).
  double gap(const double* x, double r) const;
  /// Moves the round obstacles of radius up to `max_radius` into `grid` (the generator's
  /// own, whose cells fit them): gap() then no longer looks at them one by one.
  void move_small_balls(BallGrid& grid, double max_radius);

 private:
  struct Item {
    enum Kind { ball, capsule, halfspace, polygon, box } kind = ball;
    double c[3] = {0, 0, 0};  // ball: centre; capsule: end a; halfspace: a point; box: centre
    double d[3] = {0, 0, 0};  // capsule: end b; halfspace: outward normal; box: half sizes
    double rot[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // box: world from box frame
    double r = 0;             // ball, capsule radius
    std::vector<double> v;    // polygon: corners, counter-clockwise
  };
  double item_gap(const Item& it, const double* x, double r) const;
  void add_body(const nlohmann::json& body, const std::string& ptr, const std::string& why);

  int dim_ = 2;
  std::vector<Item> items_;  // looked at one by one
};

}  // namespace moreau::generate
