// The State store: fields on entity sets, contiguous, addressed by set, name and row;
// depths swapped not copied; bodies mapped to their modelization's rows; rows rebuilt with
// persistent fields carried over by identity.
#include <gtest/gtest.h>

#include <moreau/state.hpp>

using namespace moreau;

namespace {
FieldSpec spec(const std::string& set, const std::string& name, int c2, int c3, int depths) {
  FieldSpec f;
  f.name = name;
  f.set = set;
  f.components_2d = c2;
  f.components_3d = c3;
  f.depths = depths;
  return f;
}
/// A rigid-like model (one node per body) and a chain-like one (several nodes and elements).
void two_models(State& s) {
  s.add_model({"rigid", "rigid.nodes", "", 6});
  s.add_model({"chain", "chain.nodes", "chain.springs", 3});
}
}  // namespace

TEST(State, FieldsAreContiguousPerFieldAndAddressableByRow) {
  State s(3);
  s.add_model({"rigid", "rigid.nodes", "", 6});
  s.declare(std::vector<FieldSpec>{spec("rigid.nodes", "position", 2, 3, 2), spec("rigid.nodes", "angle", 1, 0, 2),
                                   spec("rigid.nodes", "mass", 1, 1, 1)});
  EXPECT_FALSE(s.has("rigid.nodes", "angle"));  // a 2D-only field does not exist in 3D
  s.add_bodies({{"a", 0, 1, 0}, {"b", 0, 1, 0}, {"c", 0, 1, 0}});
  Field& pos = s.field("rigid.nodes", "position");
  EXPECT_EQ(pos.components(), 3);
  pos.row(1)[2] = 7.0;
  EXPECT_EQ(pos.data()[1 * 3 + 2], 7.0);
  EXPECT_EQ(&pos.row(2)[0], pos.data() + 6);
  EXPECT_EQ(s.find_body("c"), 2);
  EXPECT_EQ(s.find_body("z"), -1);
  EXPECT_EQ(s.node_values(1, "position").data(), &pos.row(1)[0]);
}

TEST(State, SwapExchangesBuffersWithoutCopy) {
  State s(2);
  s.add_model({"rigid", "rigid.nodes", "", 3});
  s.declare(spec("rigid.nodes", "velocity", 2, 3, 2));
  s.add_bodies({{"a", 0, 1, 0}});
  Field& v = s.field("rigid.nodes", "velocity");
  const double* begin = v.data(Depth::begin);
  const double* end = v.data(Depth::end);
  v.row(0, Depth::end)[0] = 3.0;
  s.swap_depths();
  EXPECT_EQ(v.data(Depth::begin), end);
  EXPECT_EQ(v.data(Depth::end), begin);
  EXPECT_EQ(v.row(0, Depth::begin)[0], 3.0);
}

TEST(State, AddingBodiesKeepsValuesAndFieldReferences) {
  State s(2);
  s.add_model({"rigid", "rigid.nodes", "", 3});
  Field& m = s.declare(spec("rigid.nodes", "mass", 1, 1, 1));
  s.add_bodies({{"a", 0, 1, 0}});
  m.row(0)[0] = 2.5;
  s.declare(spec("rigid.nodes", "inertia", 1, 6, 1));  // a later declaration does not move earlier fields
  s.add_bodies({{"b", 0, 1, 0}});
  EXPECT_EQ(&m, &s.field("rigid.nodes", "mass"));
  EXPECT_EQ(m.row(0)[0], 2.5);
  EXPECT_EQ(m.row(1)[0], 0.0);
  EXPECT_EQ(s.field("rigid.nodes", "inertia").rows(), 2u);
}

TEST(State, RedeclaringWithAnotherShapeIsAnError) {
  State s(3);
  s.declare(spec("rigid.nodes", "force", 2, 3, 1));
  EXPECT_NO_THROW(s.declare(spec("rigid.nodes", "force", 2, 3, 1)));
  EXPECT_THROW(s.declare(spec("rigid.nodes", "force", 2, 4, 1)), std::logic_error);
  EXPECT_THROW(s.field("rigid.nodes", "nothing"), std::logic_error);
  EXPECT_THROW(s.field("nowhere", "force"), std::logic_error);
}

TEST(State, BodiesOfSeveralModelizationsMapToTheirRows) {
  State s(3);
  two_models(s);
  s.declare(spec("rigid.nodes", "position", 2, 3, 2));
  s.declare(spec("chain.nodes", "position", 2, 3, 2));
  s.declare(spec("chain.springs", "tension", 1, 1, 1));
  // Scene order mixes the models; each model's rows follow its bodies' order.
  s.add_bodies({{"r0", 0, 1, 0}, {"c0", 1, 4, 3}, {"r1", 0, 1, 0}, {"c1", 1, 2, 1}});
  EXPECT_EQ(s.set("rigid.nodes").rows(), 2u);
  EXPECT_EQ(s.set("chain.nodes").rows(), 6u);
  EXPECT_EQ(s.set("chain.springs").rows(), 4u);
  const BodyRows r1 = s.body(2), c1 = s.body(3);
  EXPECT_EQ(r1.model, 0);
  EXPECT_EQ(r1.first_node, 1u);
  EXPECT_EQ(c1.model, 1);
  EXPECT_EQ(c1.first_node, 4u);
  EXPECT_EQ(c1.nodes, 2u);
  EXPECT_EQ(c1.first_element, 3u);
  EXPECT_EQ(c1.elements, 1u);
  // The inverse map: each row's body.
  const double* owner = s.field("chain.nodes", body_fields::body).data();
  EXPECT_EQ(owner[3], 1.0);
  EXPECT_EQ(owner[4], 3.0);
  // A body's node values: its nodes' rows, contiguous.
  auto x = s.node_values(3, "position");
  EXPECT_EQ(x.size(), 2u * 3u);
  EXPECT_EQ(x.data(), s.field("chain.nodes", "position").data() + 4 * 3);
  EXPECT_TRUE(s.has_node_field(1, "position"));
  EXPECT_FALSE(s.has_node_field(0, "tension"));
}

TEST(State, RebuiltRowsCarryPersistentFieldsByIdentity) {
  State s(2);
  FieldSpec impulse = spec(sets::contacts, "impulse", 2, 3, 1);
  impulse.persist = true;
  FieldSpec damage = spec(sets::contacts, "damage", 1, 1, 2);  // a law's internal variable, ⁻ and ⁺
  damage.persist = true;
  s.declare(impulse);
  s.declare(damage);
  s.declare(spec(sets::contacts, "gap", 1, 1, 1));
  EntitySet& c = s.set(sets::contacts);
  c.rebuild({-1, -1, -1});
  for (int i = 0; i < 3; ++i) {
    c.field("impulse").row(i)[0] = 10 + i;
    c.field("damage").row(i, Depth::end)[0] = 0.1 * (i + 1);
    c.field("gap").row(i)[0] = -1;
  }
  s.swap_depths();  // end of step: the ⁺ damage becomes ⁻
  // Next step: old contact 2 persists as row 0, old 0 as row 2, row 1 is new.
  c.rebuild({2, -1, 0});
  EXPECT_EQ(c.rows(), 3u);
  EXPECT_EQ(c.field("impulse").row(0)[0], 12.0);
  EXPECT_EQ(c.field("impulse").row(1)[0], 0.0);
  EXPECT_EQ(c.field("impulse").row(2)[0], 10.0);
  EXPECT_DOUBLE_EQ(c.field("damage").row(0, Depth::begin)[0], 0.3);
  EXPECT_DOUBLE_EQ(c.field("damage").row(0, Depth::end)[0], 0.3);
  EXPECT_EQ(c.field("gap").row(0)[0], 0.0);  // not persistent: new each step
  c.rebuild({});
  EXPECT_EQ(c.rows(), 0u);
}
