#pragma once
// Everything a run needs, built from a validated scene: the State, the plugin objects
// (each keeping its library loaded), and the run settings.
#include <limits>
#include <memory>
#include <moreau/force.hpp>
#include <moreau/hook.hpp>
#include <moreau/integrator.hpp>
#include <moreau/modelization.hpp>
#include <moreau/state.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../analysis/analysis_runner.hpp"
#include "../contact/contact_stages.hpp"
#include "../io/display.hpp"
#include "../io/output_writer.hpp"
#include "../plugin/owned.hpp"
#include "../plugin/registry.hpp"

namespace moreau::kernel {

/// An imposed-velocity driver (scene key `drivers`): chosen components of a body's
/// velocity imposed from `start` to `end`. NaN components are left free.
struct Driver {
  int body = -1;
  /// Scene: d linear then 1 (2D) / 3 (3D) angular components, world frame. Built: the k
  /// unknowns of the body's modelization (rigid: the same; a mesh node: d).
  std::vector<double> velocity;
  std::string node_group;          ///< scene key `nodes`: a node group of the body ("": its one node)
  std::vector<std::size_t> rows;   ///< built: the driven rows of its modelization's node set
  double start = 0;
  double end = std::numeric_limits<double>::infinity();
  std::string pointer;  ///< its place in the scene, for messages
};

struct OutputSettings {
  std::string file;  ///< output HDF5 path ("" = no output)
  long every = 1;    ///< a frame every `every` steps, plus the first and the last
  bool shapes = true;  ///< `display: "shapes"`: contactors drawn as their shapes (else points only)
};

/// A modelization of the scene paired with its integrator (the seed's ModelHandler): the
/// scheduler runs both for the bodies that name this model.
struct Model {
  std::string name;  ///< the modelization plugin, as bodies name it (`model`)
  Owned<Modelization> modelization;
  Owned<Integrator> integrator;
};

struct World {
  std::string scene_file;
  std::string scene_text;   ///< verbatim, stored in the output
  nlohmann::json scene;     ///< validated, defaults filled in
  int dimension = 3;
  double h = 0;
  double theta = 0.5;
  long total_steps = 0;
  std::vector<double> gravity;
  OutputSettings output;

  std::unique_ptr<Registry> registry;  // before the plugin objects: outlives them
  State state;
  std::vector<Model> models;  ///< in the order bodies first name them; index = State::models() index
  std::vector<Owned<Force>> forces;
  std::vector<Owned<Hook>> hooks;
  std::vector<Driver> drivers;
  std::unique_ptr<ContactStages> contacts;  ///< null when the scene has no interactions
  std::vector<io::ContactorInfo> contactor_info;  ///< every contactor and its placement, for the output header
  std::shared_ptr<const io::DisplayMeshes> display;  ///< the shapes drawn in the viewer; null: points only
  std::vector<io::SetTopology> topologies;  ///< the modelizations' element topologies, for the output
  std::unique_ptr<AnalysisRunner> analyses;  ///< the scene's `analyses`; null when it has none

  explicit World(int dim = 3) : state(dim) {}
};

}  // namespace moreau::kernel
