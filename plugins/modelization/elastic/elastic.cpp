// `elastic`: small-strain isotropic linear elasticity on finite-element meshes
// (docs/deformable.md), beside rigid bodies in one run. A body is a mesh — a Gmsh file or
// a generated rectangle, disk or box — whose nodes are rows of `elastic.nodes` (k = d
// unknowns: the velocity) and whose elements are rows of `elastic.elements`; its material
// (E, ν, density) comes from the scene's `materials`. Used as a library by its integrator
// (the seed's ModelHandler): linear_bulk gives M (consistent or lumped), C = αM + βK
// (Rayleigh) and K, the gravity load and the fixed unknowns; `linear_theta` builds eq. 6
// from them. For the contact side a point on a body moves with the nodes that support it:
// u = Σ_j w_j frame v_j. For the frames written it derives the stresses (element centres,
// and averaged at the nodes). The mesh's named sets become the body's groups
// (State::set_groups): contactors sit on boundary groups, drivers and forces on node groups.
#include <algorithm>
#include <map>
#include <memory>
#include <moreau/linear_bulk.hpp>
#include <moreau/modelization.hpp>

#include "elastic_fields.hpp"
#include "fem/elasticity.hpp"
#include "mesh_input.hpp"

namespace {

using namespace moreau;
namespace E = moreau::elastic;
namespace N = moreau::node_fields;

/// XDMF Mixed topology numbers of the element types (Triangle, Quadrilateral, Tetrahedron, Hexahedron).
int xdmf_type(fem::ElementType t) {
  switch (t) {
    case fem::ElementType::T3: return 4;
    case fem::ElementType::Q4: return 5;
    case fem::ElementType::T4: return 6;
    case fem::ElementType::H8: return 9;
    default: return 0;
  }
}

class Elastic : public Modelization {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "small-strain linear elasticity on finite-element meshes (T3, Q4, T4, H8)";
  Elastic(const Params&, const BuildContext& c) : scene_dir_(c.scene_dir) {}

  std::string node_set() const override { return E::nodes; }
  std::string element_set() const override { return E::elements; }
  int node_dofs(int dim) const override { return dim; }
  std::vector<FieldSpec> fields(int) const override { return E::fields(); }
  std::string default_integrator() const override { return "linear_theta"; }

  Schema body_schema(int dim) const override {
    Schema s;
    s.object("mesh", "{\"file\": PATH} (Gmsh 2.2 or 4.1, relative to the scene) or {\"generate\": \"rectangle\" | \"disk\" | "
                     "\"box\", origin/extent or centre/radius, size, element}");
    s.string("material", "material name: density, young, poisson");
    if (dim == 2)
      s.string("hypothesis", "2D reduction").one_of({"plane_strain", "plane_stress"}).fallback("plane_strain");
    s.string("mass", "mass matrix: consistent, or lumped (diagonal, HRZ)").one_of({"consistent", "lumped"}).fallback("consistent");
    s.number("rayleigh_alpha", "Rayleigh damping C = alpha M + beta K: mass-proportional part").units("1/s").min(0).fallback(0.0);
    s.number("rayleigh_beta", "Rayleigh damping: stiffness-proportional part").units("s").min(0).fallback(0.0);
    s.vector("offset", "moves the whole mesh by this vector", length::dimension).units("m").optional();
    s.vector("velocity", "initial velocity of every node", length::dimension).units("m/s").optional();
    s.array("fixed", "node groups whose nodes never move (all components)").fallback(nlohmann::json::array());
    return s;
  }

  BodySize body_size(const Params& p, int dim) const override {
    const fem::Mesh& m = mesh_of(p, dim);
    return {static_cast<std::size_t>(m.node_count()), static_cast<std::size_t>(m.element_count())};
  }

  std::array<double, 3> init_body(State& st, std::size_t body, const Params& p, const std::optional<MassProperties>&,
                                  const Params* material) override {
    const int d = st.dimension();
    const BodyRows rows = st.body(body);
    Body B;
    B.body = body;
    B.first_node = rows.first_node;
    B.first_element = rows.first_element;
    B.mesh = meshes_.at(p.pointer());
    const fem::Mesh& mesh = *B.mesh;
    // Material: the scene's, checked by the library (its message, at the material's key).
    if (!material || !material->has("young") || !material->has("poisson"))
      throw p.error("material", "an elastic body needs a material with \"density\", \"young\" and \"poisson\"");
    B.material.young = material->number("young");
    B.material.poisson = material->number("poisson");
    B.material.density = material->number("density");
    B.material.hypothesis = d == 3 ? fem::Hypothesis::solid
                            : p.string("hypothesis") == "plane_stress" ? fem::Hypothesis::plane_stress
                                                                       : fem::Hypothesis::plane_strain;
    try {
      fem::validate(B.material, d);
    } catch (const fem::MaterialError& e) {
      throw material->error(e.parameter(), e.what());
    }
    B.lumped = p.string("mass") == "lumped";
    B.alpha = p.number("rayleigh_alpha");
    B.beta = p.number("rayleigh_beta");

    // Nodes: the mesh's, at rest, all moving with the initial velocity.
    const std::vector<double> v0 = p.has("velocity") ? p.vector("velocity") : std::vector<double>(d, 0.0);
    Field& x = st.field(E::nodes, N::position);
    Field& X = st.field(E::nodes, N::reference_position);
    Field& v = st.field(E::nodes, N::velocity);
    for (int n = 0; n < mesh.node_count(); ++n) {
      const std::size_t r = rows.first_node + static_cast<std::size_t>(n);
      for (int k = 0; k < d; ++k) {
        X.row(r)[k] = mesh.x(k, n);
        for (Depth dp : {Depth::begin, Depth::end}) {
          x.row(r, dp)[k] = mesh.x(k, n);
          v.row(r, dp)[k] = v0[k];
        }
      }
    }
    // The node's share of the mass: M's column sums (its diagonal when lumped), so that
    // Σ mass v is the body's momentum.
    {
      const fem::SparseMatrix M = fem::mass_matrix(mesh, B.material.density, B.lumped ? fem::MassKind::lumped
                                                                                         : fem::MassKind::consistent);
      Field& mass = st.field(E::nodes, E::mass);
      for (int col = 0; col < M.outerSize(); col += d) {
        double sum = 0;
        for (fem::SparseMatrix::InnerIterator it(M, col); it; ++it) sum += it.value();
        mass.row(rows.first_node + static_cast<std::size_t>(col / d))[0] = sum;
      }
    }
    Field& type = st.field(E::elements, E::type);
    for (int e = 0; e < mesh.element_count(); ++e)
      type.row(rows.first_element + static_cast<std::size_t>(e))[0] = fem::element_info(mesh.elements.type[e]).gmsh_type;

    // The mesh's named sets become the body's groups, over rows of the node set.
    BodyGroups g;
    for (const auto& [name, list] : mesh.node_sets) {
      auto& out = g.nodes[name];
      for (int n : list) out.push_back(rows.first_node + static_cast<std::size_t>(n));
    }
    for (const auto& [name, facets] : mesh.boundary_sets) {
      FacetGroup& out = g.facets[name];
      for (int f = 0; f < facets.size(); ++f) {
        for (int n : facets.cells[f]) out.nodes.push_back(rows.first_node + static_cast<std::size_t>(n));
        out.offset.push_back(out.nodes.size());
      }
    }
    st.set_groups(body, g);

    // Fixed node groups: every component of their nodes.
    const auto& fixed = p.raw("fixed");
    Field& fixed_field = st.field(E::nodes, E::fixed);
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      const std::string ptr = p.pointer("fixed") + "/" + std::to_string(i);
      if (!fixed[i].is_string()) throw InputError(ptr, "expected the name of a node group");
      for (const std::size_t r : st.node_group(body, fixed[i].get<std::string>(), ptr)) {
        fixed_field.row(r)[0] = 1;
        for (int k = 0; k < d; ++k) B.fixed.push_back(d * static_cast<int>(r - rows.first_node) + k);
      }
    }
    std::sort(B.fixed.begin(), B.fixed.end());
    B.fixed.erase(std::unique(B.fixed.begin(), B.fixed.end()), B.fixed.end());
    bodies_[body] = std::move(B);
    return {0, 0, 0};
  }

  Topology topology(const State&) const override {
    Topology t;
    for (const auto& [b, B] : bodies_) {
      const fem::Mesh& m = *B.mesh;
      for (int e = 0; e < m.element_count(); ++e) {
        t.cells.push_back(xdmf_type(m.elements.type[e]));
        for (int n : m.elements[e]) t.cells.push_back(static_cast<int>(B.first_node) + n);
        ++t.count;
      }
    }
    return t;
  }

  void bulk(StepContext&) override {}
  bool has_bulk() const override { return false; }

  bool linear_bulk(const State& st, std::size_t body, LinearBulk& out) const override {
    const Body& B = bodies_.at(body);
    const fem::Mesh& m = *B.mesh;
    const int d = st.dimension();
    out.K = fem::stiffness_matrix(m, B.material);
    out.M = fem::mass_matrix(m, B.material.density, B.lumped ? fem::MassKind::lumped : fem::MassKind::consistent);
    if (B.alpha != 0 || B.beta != 0) out.C = fem::rayleigh_damping(out.M, out.K, B.alpha, B.beta);
    else out.C.resize(0, 0);
    out.load.resize(0);
    // Gravity acts through the consistent load ∫ρ N g whatever the mass matrix.
    out.gravity.resize(m.dof_count(), d);
    for (int c = 0; c < d; ++c) out.gravity.col(c) = fem::gravity_load(m, B.material.density, Eigen::VectorXd::Unit(d, c));
    out.fixed = B.fixed;
    return true;
  }

  bool has_derived_fields() const override { return true; }
  void derived_fields(State& st, Depth depth) override {
    const int d = st.dimension();
    const double* u = st.field(E::nodes, N::displacement).data(depth);
    double* se = st.field(E::elements, E::stress).data();
    double* ve = st.field(E::elements, E::von_mises).data();
    double* sn = st.field(E::nodes, E::stress).data();
    double* vn = st.field(E::nodes, E::von_mises).data();
    for (const auto& [b, B] : bodies_) {
      const fem::Mesh& m = *B.mesh;
      const Eigen::Map<const Eigen::VectorXd> ub(u + d * B.first_node, m.dof_count());
      const fem::StressField s = fem::element_stress(m, B.material, ub);
      const fem::StressField sn_b = fem::nodal_stress(m, s);
      const Eigen::VectorXd vm_e = fem::von_mises(s), vm_n = fem::von_mises(sn_b);
      Eigen::Map<Eigen::MatrixXd>(se + 6 * B.first_element, 6, m.element_count()) = s;
      Eigen::Map<Eigen::VectorXd>(ve + B.first_element, m.element_count()) = vm_e;
      Eigen::Map<Eigen::MatrixXd>(sn + 6 * B.first_node, 6, m.node_count()) = sn_b;
      Eigen::Map<Eigen::VectorXd>(vn + B.first_node, m.node_count()) = vm_n;
    }
  }

  void generalised_velocity(const State& st, Velocity which, std::size_t n, double* out) const override {
    const int d = st.dimension();
    const double* v = st.field(E::nodes, which == Velocity::begin ? N::velocity : N::free_velocity).data(Depth::begin);
    for (int k = 0; k < d; ++k) out[k] = v[n * d + k];
  }

  /// A point carried by its nodes: u = Σ_j w_j frame v_j.
  void contact_jacobian(const State& st, const PointOnBody& p, double* H) const override {
    const int d = st.dimension();
    for (int j = 0; j < p.count; ++j)
      for (int i = 0; i < d * d; ++i) H[j * d * d + i] = p.weights[j] * p.frame[i];
  }

 private:
  struct Body {
    std::size_t body = 0, first_node = 0, first_element = 0;
    std::shared_ptr<const fem::Mesh> mesh;
    fem::Material material;
    bool lumped = false;
    double alpha = 0, beta = 0;
    std::vector<int> fixed;  ///< unknowns within the body
  };

  /// The body's mesh, read or generated once (body_size comes first, init_body reuses it).
  const fem::Mesh& mesh_of(const Params& p, int dim) const {
    auto it = meshes_.find(p.pointer());
    if (it != meshes_.end()) return *it->second;
    const std::vector<double> offset = p.has("offset") ? p.vector("offset") : std::vector<double>(dim, 0.0);
    auto m = std::make_shared<const fem::Mesh>(E::scene_mesh(p.raw("mesh"), p.pointer("mesh"), scene_dir_, dim, offset));
    return *meshes_.emplace(p.pointer(), std::move(m)).first->second;
  }

  std::string scene_dir_;
  mutable std::map<std::string, std::shared_ptr<const fem::Mesh>> meshes_;  ///< by the body's JSON pointer
  std::map<std::size_t, Body> bodies_;                                     ///< by body index
};

MOREAU_REGISTER(Elastic, "elastic")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_modelization_elastic")
