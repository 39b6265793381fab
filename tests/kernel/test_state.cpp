// The State store: contiguous fields, addressed by name and body, depths swapped not copied.
#include <gtest/gtest.h>

#include <moreau/state.hpp>

using namespace moreau;

namespace {
FieldSpec spec(const std::string& name, int c2, int c3, int depths) {
  FieldSpec f;
  f.name = name;
  f.components_2d = c2;
  f.components_3d = c3;
  f.depths = depths;
  return f;
}
}  // namespace

TEST(State, FieldsAreContiguousPerFieldAndAddressableByBody) {
  State s(3);
  s.declare(std::vector<FieldSpec>{spec("position", 2, 3, 2), spec("angle", 1, 0, 2), spec("mass", 1, 1, 1)});
  EXPECT_FALSE(s.has("angle"));  // a 2D-only field does not exist in 3D
  s.add_bodies({"a", "b", "c"});
  Field& pos = s.field("position");
  EXPECT_EQ(pos.components(), 3);
  pos.row(1)[2] = 7.0;
  EXPECT_EQ(pos.data()[1 * 3 + 2], 7.0);
  EXPECT_EQ(&pos.row(2)[0], pos.data() + 6);
  EXPECT_EQ(s.find_body("c"), 2);
  EXPECT_EQ(s.find_body("z"), -1);
}

TEST(State, SwapExchangesBuffersWithoutCopy) {
  State s(2);
  s.declare(spec("velocity", 2, 3, 2));
  s.add_bodies({"a"});
  Field& v = s.field("velocity");
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
  Field& m = s.declare(spec("mass", 1, 1, 1));
  s.add_bodies({"a"});
  m.row(0)[0] = 2.5;
  s.declare(spec("inertia", 1, 6, 1));  // a later declaration does not move earlier fields
  s.add_bodies({"b"});
  EXPECT_EQ(&m, &s.field("mass"));
  EXPECT_EQ(m.row(0)[0], 2.5);
  EXPECT_EQ(m.row(1)[0], 0.0);
  EXPECT_EQ(s.field("inertia").bodies(), 2u);
}

TEST(State, RedeclaringWithAnotherShapeIsAnError) {
  State s(3);
  s.declare(spec("force", 2, 3, 1));
  EXPECT_NO_THROW(s.declare(spec("force", 2, 3, 1)));
  EXPECT_THROW(s.declare(spec("force", 2, 4, 1)), std::logic_error);
  EXPECT_THROW(s.field("nothing"), std::logic_error);
}
