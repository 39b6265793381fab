// Fast bodies against thin walls (docs/contacts.md, "Fast bodies"): detection runs on the
// predicted configuration q⁻ + (1−θ)h v⁻, which a grain at 10³ m/s with h = 1e-3 reaches
// 0.5 m ahead (θ = ½): past a 2 mm wall, or beside the wall it will hit later in the step.
// Swept detection follows such pairs from the start of the step. Whatever the speed, the
// angle, the shapes and θ, a grain must never be found past the wall's mid-plane in front
// of it, and its kinetic energy never rises.
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

struct Shot {
  int dim = 2;
  std::string grain, wall;  // contactor JSON (group set below)
  double wall_angle = 0;    // 2D: the wall body's angle; 3D: its rotation about z
  double phi = 0;           // the wall's mid-plane normal is (cos φ, sin φ); the grain comes from its −n side
  double theta = 0.5, restitution = 0, friction = 0;
  double speed = 1000, incidence = 0, along = 0, across = 0, distance = 0.3;
};

std::string number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

/// The wall's mid-plane goes through the origin with unit normal n = (cos φ, sin φ, 0);
/// the grain starts on the −n side and flies toward the point `along` the wall (and
/// `across` in z), at `incidence` to n.
std::string scene(const Shot& s) {
  const double c = std::cos(s.phi), si = std::sin(s.phi);
  const double dir[2] = {std::cos(s.phi + s.incidence), std::sin(s.phi + s.incidence)};
  const double hit[2] = {-si * s.along, c * s.along};
  const double back = s.distance / std::cos(s.incidence);
  const double x[2] = {hit[0] - back * dir[0], hit[1] - back * dir[1]};
  std::ostringstream o;
  o << R"({"format": "moreau-scene/1", "dimension": )" << s.dim << R"(,
  "time": {"step": 0.001, "duration": 0.02, "theta": )" << s.theta << R"(},
  "laws": {"hard": {"type": "coulomb", "friction": )" << s.friction << R"(, "restitution": )" << s.restitution << R"(}},
  "interactions": [{"groups": ["grain", "wall"], "law": "hard"}],
  "solver": {"type": "nlgs", "tolerance": 1e-10, "max_iterations": 200},
  "output": {"every": 1}, "bodies": [)";
  if (s.dim == 2) {
    o << R"({"name": "wall", "fixed": true, "position": [0, 0], "angle": )" << number(s.wall_angle)
      << R"(, "contactors": [)" << s.wall << R"(]},
    {"name": "grain", "position": [)" << number(x[0]) << ", " << number(x[1]) << R"(], "velocity": [)"
      << number(s.speed * dir[0]) << ", " << number(s.speed * dir[1])
      << R"(], "mass": 0.01, "inertia": 1e-7, "contactors": [)" << s.grain << "]}]}";
  } else {
    o << R"({"name": "wall", "fixed": true, "position": [0, 0, 0], "orientation": [)" << number(std::cos(s.wall_angle / 2))
      << ", 0, 0, " << number(std::sin(s.wall_angle / 2)) << R"(], "contactors": [)" << s.wall << R"(]},
    {"name": "grain", "position": [)" << number(x[0]) << ", " << number(x[1]) << ", " << s.across
      << R"(], "velocity": [)" << number(s.speed * dir[0]) << ", " << number(s.speed * dir[1])
      << R"(, 0], "mass": 0.01, "inertia": [1e-7, 1e-7, 1e-7], "contactors": [)" << s.grain << "]}]}";
  }
  return o.str();
}

/// Runs the shot and checks every frame: the grain is never past the wall's mid-plane
/// while in front of the wall (|along|, |z| below 0.095 of its 0.1 half extent), and its
/// kinetic energy never exceeds the start's (to 1e-9: rounding and solver tolerance).
/// Returns what the run printed on stderr.
std::string fire(const Shot& s, const std::string& name) {
  SceneRun run = run_scene(name, scene(s));
  EXPECT_FALSE(run.frames.empty());
  const int d = s.dim;
  const double n[2] = {std::cos(s.phi), std::sin(s.phi)}, t[2] = {-n[1], n[0]};
  double ke0 = -1;
  for (const auto& f : run.frames) {
    const auto x = run.at(f, "position"), v = run.at(f, "velocity");
    const double* p = x.data() + d;  // body 1: the grain
    const double normal = p[0] * n[0] + p[1] * n[1], along = p[0] * t[0] + p[1] * t[1];
    const double z = d == 3 ? p[2] : 0.0;
    if (std::fabs(along) < 0.095 && std::fabs(z) < 0.095)
      EXPECT_LE(normal, 0.0) << name << ": the grain is past the wall at frame " << f << " (" << normal << " m)";
    double ke = 0;
    for (int k = 0; k < d; ++k) ke += 0.5 * 0.01 * v[d + k] * v[d + k];
    if (ke0 < 0) ke0 = ke;
    EXPECT_LE(ke, ke0 * (1 + 1e-9)) << name << ": kinetic energy rose at frame " << f;
  }
  return run.err;
}

const char* disk = R"({"shape": "disk", "radius": 0.005, "group": "grain"})";
const char* square = R"({"shape": "polygon", "vertices": [[-0.004, -0.004], [0.004, -0.004], [0.004, 0.004], [-0.004, 0.004]], "group": "grain"})";
const char* segment_wall = R"({"shape": "segment", "length": 0.2, "thickness": 0.002, "group": "wall"})";
const char* plate_2d = R"({"shape": "polygon", "vertices": [[-0.001, -0.1], [0.001, -0.1], [0.001, 0.1], [-0.001, 0.1]], "group": "wall"})";
const char* sphere = R"({"shape": "sphere", "radius": 0.005, "group": "grain"})";
const char* cube = R"({"shape": "box", "size": [0.008, 0.008, 0.008], "group": "grain"})";
const char* octahedron = R"({"shape": "convex", "vertices": [[0.005, 0, 0], [-0.005, 0, 0], [0, 0.005, 0], [0, -0.005, 0], [0, 0, 0.005], [0, 0, -0.005]], "group": "grain"})";
const char* box_wall = R"({"shape": "box", "size": [0.002, 0.2, 0.2], "group": "wall"})";
const char* plate_3d = R"({"shape": "convex", "vertices": [[-0.001, -0.1, -0.1], [-0.001, -0.1, 0.1], [-0.001, 0.1, -0.1], [-0.001, 0.1, 0.1], [0.001, -0.1, -0.1], [0.001, -0.1, 0.1], [0.001, 0.1, -0.1], [0.001, 0.1, 0.1]], "group": "wall"})";

}  // namespace

// The issue's case: 10³ m/s, a 2 mm wall, h = 1e-3, head on. From 0.3 m the predicted
// configuration of θ = ½ is 0.2 m past the wall; from 0.706 m it is in front. Where the
// committed (1−θ)h v⁻ alone reaches the wall (0.3 m, θ = ½), the grain leaves faster than
// e = 0 allows, and the run says so once; where it does not, nothing is said.
TEST(FastBodies, GrainAt1000MetresPerSecondStopsAtA2mmWallIn2DAnd3D) {
  for (int dim : {2, 3})
    for (double theta : {0.5, 0.75, 1.0})
      for (double distance : {0.3, 0.706}) {
        Shot s;
        s.dim = dim;
        s.grain = dim == 2 ? disk : sphere;
        s.wall = dim == 2 ? segment_wall : box_wall;
        s.wall_angle = dim == 2 ? std::numbers::pi / 2 : 0;  // the segment lies along its x axis
        s.theta = theta;
        s.distance = distance;
        const std::string err = fire(s, "wall" + std::to_string(dim) + "d_" + std::to_string(static_cast<int>(100 * theta)) +
                                            "_" + std::to_string(static_cast<int>(1000 * distance)));
        const std::string said = "step 1: bodies \"wall\" and \"grain\" met within the step at 1e+03 m/s (swept detection)";
        // The committed travel (1−θ)h·10³ m/s against the gap at the start, 6 mm short of the distance.
        if ((1 - theta) * 1.0 > distance - 0.006) {
          EXPECT_NE(err.find(said), std::string::npos) << err;
          EXPECT_EQ(err.find("met within the step"), err.rfind("met within the step")) << "said once: " << err;
        } else {
          EXPECT_EQ(err.find("met within the step"), std::string::npos) << "theta " << theta << " distance " << distance << ": " << err;
        }
      }
}

// Seeded shots at any speed from 1 to 10⁴ m/s (the largest: 10 m, two thousand wall
// thicknesses, a step), any incidence up to 40°, anywhere along the wall up to its ends
// (where the predicted configuration is beside the wall: a polygon's face clips against
// nothing there), walls turned any way, polygons, boxes and convex shapes, θ ∈ {½, ¾, 1},
// with and without friction and restitution (e = 1 only without friction: Newton's
// restitution with friction can gain energy at eccentric impacts, docs/contacts.md).
// Before swept detection one of these 36 went through (and 25 of 400 of a longer run).
TEST(FastBodies, ShotsAtAnySpeedAngleAndShapeNeverGoThrough) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 36; ++i) {
    Shot s;
    s.dim = i % 2 ? 3 : 2;
    s.phi = 2 * std::numbers::pi * u(rng);
    s.theta = std::array<double, 3>{0.5, 0.75, 1.0}[i % 3];
    s.speed = std::pow(10.0, 4 * u(rng));
    s.incidence = (u(rng) - 0.5) * 1.4;
    s.along = (u(rng) - 0.5) * 0.2;
    s.across = (u(rng) - 0.5) * 0.18;
    s.distance = 0.0065 + 2e-3 * s.speed * u(rng);  // within two steps of the wall
    s.friction = (i / 6) % 2 ? 0.3 : 0.0;
    s.restitution = s.friction > 0 ? 0.5 * ((i / 3) % 2) : 0.5 * ((i / 2) % 3);  // e = 1 only without friction
    const int shape = (i / 2) % 6;
    if (s.dim == 2) {
      s.grain = shape % 2 ? square : disk;
      s.wall = shape < 3 ? segment_wall : plate_2d;
      s.wall_angle = s.phi + (shape < 3 ? std::numbers::pi / 2 : 0.0);  // the segment lies along its x axis
    } else {
      s.grain = shape % 3 == 0 ? sphere : shape % 3 == 1 ? cube : octahedron;
      s.wall = shape < 3 ? box_wall : plate_3d;
      s.wall_angle = s.phi;
    }
    fire(s, "shot" + std::to_string(i));
  }
}

// A fast grain hits a resting one 0.2 m before the wall: the first must not pass through
// the second (the predicted configuration puts it 0.5 m ahead), and neither through the wall.
TEST(FastBodies, FastGrainHitsARestingGrainBeforeAWall) {
  SceneRun run = run_scene("chain", R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.001, "duration": 0.01},
  "laws": {"hard": {"type": "coulomb"}},
  "bodies": [
    {"name": "wall", "fixed": true, "position": [0, 0], "angle": 1.5707963267948966,
     "contactors": [{"shape": "segment", "length": 0.2, "thickness": 0.002, "group": "wall"}]},
    {"name": "b", "position": [-0.2, 0], "mass": 0.01, "inertia": 1e-7, "contactors": [{"shape": "disk", "radius": 0.005, "group": "grain"}]},
    {"name": "a", "position": [-0.6, 0], "velocity": [1000, 0], "mass": 0.01, "inertia": 1e-7,
     "contactors": [{"shape": "disk", "radius": 0.005, "group": "grain"}]}
  ],
  "interactions": [{"groups": ["grain", "wall"], "law": "hard"}, {"groups": ["grain", "grain"], "law": "hard"}],
  "output": {"every": 1}})");
  for (const auto& f : run.frames) {
    const auto x = run.at(f, "position");
    const double xb = x[2], xa = x[4];
    EXPECT_LE(xa, xb - 0.01 + 1e-9) << "a passed through b at frame " << f;
    EXPECT_LE(xb, -0.006 + 1e-9) << "b passed the wall at frame " << f;
  }
}
