// Modelization `chain` (test only, tests/mixed/chain_fields.hpp): a body is a list of point
// masses (`nodes`, their positions) joined by linear springs (consecutive nodes, or the
// pairs in `springs`); `stiffness` per spring, `node_mass` per node, one `velocity` for all.
#include <cmath>
#include <moreau/modelization.hpp>

#include "chain_fields.hpp"

namespace {

using namespace moreau;
namespace C = moreau_test::chain;

class Chain : public Modelization {
 public:
  static Schema schema() { return {}; }
  static constexpr const char* doc = "test: point masses joined by linear springs (several nodes per body)";
  Chain(const Params&, const BuildContext&) {}

  std::string node_set() const override { return C::nodes; }
  std::string element_set() const override { return C::springs; }
  int node_dofs(int dim) const override { return dim; }
  std::vector<FieldSpec> fields(int) const override { return C::fields(); }
  std::string default_integrator() const override { return "chain_theta"; }

  Schema body_schema(int dim) const override {
    Schema s;
    s.array("nodes", "node positions, d numbers each");
    s.vector("velocity", "initial velocity of every node", length::dimension).units("m/s").optional();
    s.number("node_mass", "mass of each node").units("kg").gt(0);
    s.number("stiffness", "spring constant").units("N/m").gt(0);
    s.array("springs", "node pairs joined by a spring (default: consecutive nodes)").optional();
    (void)dim;
    return s;
  }

  BodySize body_size(const Params& p, int) const override {
    const auto& n = p.raw("nodes");
    const std::size_t nodes = n.is_array() ? n.size() : 0;
    const std::size_t springs = p.has("springs") ? p.raw("springs").size() : (nodes > 0 ? nodes - 1 : 0);
    return {nodes, springs};
  }

  std::array<double, 3> init_body(State& st, std::size_t body, const Params& p, const std::optional<MassProperties>&,
                                  const Params*) override {
    const int d = st.dimension();
    const BodyRows r = st.body(body);
    if (r.nodes < 1) throw p.error("nodes", "expected at least one node");
    const auto& list = p.raw("nodes");
    std::vector<double> v = p.has("velocity") ? p.vector("velocity") : std::vector<double>(d, 0.0);
    for (std::size_t i = 0; i < r.nodes; ++i) {
      const auto& x = list[i];
      if (!x.is_array() || static_cast<int>(x.size()) != d)
        throw p.error("nodes", "node " + std::to_string(i) + ": expected " + std::to_string(d) + " numbers");
      for (int k = 0; k < d; ++k) {
        const double xk = x[k].get<double>();
        for (Depth dp : {Depth::begin, Depth::end}) {
          st.field(C::nodes, node_fields::position).row(r.first_node + i, dp)[k] = xk;
          st.field(C::nodes, C::velocity).row(r.first_node + i, dp)[k] = v[k];
        }
        st.field(C::nodes, C::rest_position).row(r.first_node + i)[k] = xk;
      }
      st.field(C::nodes, C::mass).row(r.first_node + i)[0] = p.number("node_mass");
    }
    for (std::size_t e = 0; e < r.elements; ++e) {
      std::size_t a = e, b = e + 1;
      if (p.has("springs")) {
        const auto& s = p.raw("springs")[e];
        a = s.at(0).get<std::size_t>();
        b = s.at(1).get<std::size_t>();
        if (a >= r.nodes || b >= r.nodes || a == b) throw p.error("springs", "spring " + std::to_string(e) + ": bad nodes");
      }
      st.field(C::springs, C::ends).row(r.first_element + e)[0] = static_cast<double>(r.first_node + a);
      st.field(C::springs, C::ends).row(r.first_element + e)[1] = static_cast<double>(r.first_node + b);
      st.field(C::springs, C::stiffness).row(r.first_element + e)[0] = p.number("stiffness");
    }
    return {0, 0, 0};
  }

  Topology topology(const State& st) const override {
    Topology t;
    const Field& e = st.field(C::springs, C::ends);
    t.count = e.rows();
    for (std::size_t i = 0; i < t.count; ++i)
      t.cells.insert(t.cells.end(), {2, 2, static_cast<int>(e.row(i)[0]), static_cast<int>(e.row(i)[1])});  // polyline
    return t;
  }

  void bulk(StepContext&) override {}
  bool has_bulk() const override { return false; }

  void generalised_velocity(const State& st, Velocity which, std::size_t n, double* out) const override {
    const int d = st.dimension();
    const double* v = st.field(C::nodes, which == Velocity::begin ? C::velocity : C::free_velocity).data(Depth::begin);
    for (int k = 0; k < d; ++k) out[k] = v[n * d + k];
  }

  /// A point carried by its nodes: u = Σ_j w_j frame v_j (no rotation).
  void contact_jacobian(const State& st, const PointOnBody& p, double* H) const override {
    const int d = st.dimension();
    for (int j = 0; j < p.count; ++j)
      for (int i = 0; i < d * d; ++i) H[j * d * d + i] = p.weights[j] * p.frame[i];
  }
};

MOREAU_REGISTER(Chain, "chain")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_modelization_chain")
