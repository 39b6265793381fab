#include "scene_schema.hpp"

namespace moreau::kernel::scene_schema {

Schema top() {
  Schema s;
  s.string("format", "scene format and version").one_of({kFormat});
  s.integer("dimension", "2 or 3").min(2).max(3);
  s.object("time", "time stepping: step, duration, theta, integrator");
  s.vector("gravity", "gravity acceleration", length::dimension).units("m/s2").fallback(nullptr);
  s.array("plugin_paths", "extra folders searched first for plugin libraries").fallback(nlohmann::json::array());
  s.object("materials", "named materials: {name: {density, young, poisson}}").fallback(nlohmann::json::object());
  s.object("laws", "named contact laws: {name: {type, ...}}").fallback(nlohmann::json::object());
  s.array("bodies", "the bodies");
  s.object("models", "per modelization the bodies name: {name: {integrator, ...its parameters}}").optional();
  s.array("generators", "generator plugins making bodies before the scene is read: [{type, ...}] (docs/analyses.md)")
      .fallback(nlohmann::json::array());
  s.array("analyses", "analysis plugins run at output frames: [{type, name, region, every, ...}] (docs/analyses.md)")
      .fallback(nlohmann::json::array());
  s.array("drivers", "imposed velocities: [{body, velocity, angular_velocity, start, end}]").fallback(nlohmann::json::array());
  s.array("forces", "external-force plugins: [{type, ...}]").fallback(nlohmann::json::array());
  s.array("interactions", "which contactor groups interact, and by which law: [{groups, law}]").fallback(nlohmann::json::array());
  s.object("detection", "contact detection: broadphase, alert").fallback(nlohmann::json::object());
  s.object("solver", "contact solver: {type, ...}").fallback(nlohmann::json::object());
  s.object("output", "output file and frequency").fallback(nlohmann::json::object());
  s.array("hooks", "hook plugins run at stage boundaries: [{type, ...}]").fallback(nlohmann::json::array());
  s.object("export_problems", "write the local contact problems of chosen steps as FCLib files").optional();
  return s;
}

Schema export_problems() {
  Schema s;
  // `steps` or `every`, exactly one (checked by the builder, which names the pointer).
  s.array("steps", "steps whose problem is written (step N ends at t = N h; its impulses are in output frame N)").optional();
  s.integer("every", "write the problem of every N-th step").min(1).optional();
  s.string("directory", "folder of the files, relative to the output file's folder").fallback("problems");
  s.integer("min_contacts", "steps with fewer contacts write nothing").min(1).fallback(1);
  s.string("kind", "FCLib form: local (W, q, mu) or global (M, H, f, w, mu: deformable bodies' LHS kept sparse)")
      .one_of({"local", "global"})
      .fallback("local");
  return s;
}

Schema time() {
  Schema s;
  s.number("step", "time step h").units("s").gt(0);
  s.number("duration", "simulated time; the run makes round(duration/step) steps").units("s").min(0);
  s.number("theta", "theta of the theta-scheme").min(0.5).max(1).fallback(0.5);
  s.string("integrator", "integrator plugin of every modelization that names none in `models` (default: each modelization's own, theta for rigid)").optional();
  return s;
}

Schema output() {
  Schema s;
  s.string("file", "output HDF5 file (relative to the working folder; --out overrides)").fallback("out.h5");
  s.integer("every", "write a frame every N steps (plus the first and the last)").min(1).fallback(1);
  s.string("display",
           "what ParaView draws for bodies: \"shapes\" (each contactor's outline or surface; its vertices are "
           "written every frame) or \"points\" (body positions only, for the largest runs)")
      .one_of({"shapes", "points"})
      .fallback("shapes");
  return s;
}

Schema material() {
  Schema s;
  s.number("density", "mass density (2D: per unit thickness)").units("kg/m3").gt(0);
  // Elastic constants: the modelizations that read them check them (elastic: E > 0,
  // -1 < nu < 0.5, docs/deformable.md); others ignore them.
  s.number("young", "Young's modulus E (elastic bodies)").units("Pa").optional();
  s.number("poisson", "Poisson's ratio nu (elastic bodies)").units("1").optional();
  return s;
}

Schema body_kernel_keys() {
  Schema s;
  s.string("name", "unique body name");
  s.string("model", "modelization plugin").fallback("rigid");
  s.array("contactors", "the body's contactors (shapes, in the body frame)").fallback(nlohmann::json::array());
  return s;
}

Schema contactor_kernel_keys(int dim) {
  Schema s;
  s.string("shape", "shape plugin");
  s.string("group", "contactor group, paired in `interactions`").fallback("default");
  s.integer("node", "the body's node that supports the contactor (bodies of several nodes; rigid bodies have one; default 0)").min(0).optional();
  s.string("boundary", "a boundary group of the body (meshes): the contactor is repeated on each of its nodes, or "
                       "on each of its facets for a facet shape (edge, face)").optional();
  // The placement of the shape in the body frame (clusters: several contactors on a body).
  s.vector("offset", "position of the shape's origin in the body frame", length::dimension).units("m")
      .fallback(nlohmann::json(std::vector<double>(static_cast<std::size_t>(dim), 0.0)));
  if (dim == 2) s.number("angle", "rotation of the shape in the body frame").units("rad").fallback(0.0);
  else s.vector("orientation", "rotation of the shape in the body frame, unit quaternion w x y z", length::orientation)
           .fallback({1.0, 0.0, 0.0, 0.0});
  return s;
}

Schema driver() {
  Schema s;
  s.string("body", "name of the driven body");
  s.string("nodes", "a node group of the body (meshes): the velocity is imposed on each of its nodes").optional();
  s.vector("velocity", "imposed velocity components; null leaves one free", length::dimension)
      .units("m/s").allow_null_items().optional();
  s.vector("angular_velocity", "imposed angular velocity components (world frame); null leaves one free",
           length::rotation).units("rad/s").allow_null_items().optional();
  s.number("start", "time the driver starts").units("s").min(0).fallback(0.0);
  s.number("end", "time the driver ends (absent: never)").units("s").min(0).optional();
  return s;
}

Schema interaction() {
  Schema s;
  s.array("groups", "the two contactor groups");
  s.string("law", "name of a law in `laws`");
  return s;
}

Schema detection() {
  Schema s;
  // `broadphase` is a plugin name or {"type": name, ...its parameters}, as `solver`: the
  // builder validates it against the plugin's schema (detection_plugin_keys()).
  s.number("alert", "alert distance: contacts are created below this gap").units("m").min(0).fallback(0.0);
  return s;
}

}  // namespace moreau::kernel::scene_schema
