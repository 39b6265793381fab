// Field pointers resolved once (moreau/field_cache.hpp): resolved anew when a field is
// declared later, for another State (also one built where a destroyed one was), for a copy
// of a set; a missing required field throws naming it, and leaves the cache as it was.
#include <gtest/gtest.h>

#include <memory>
#include <moreau/field_cache.hpp>
#include <new>
#include <stdexcept>

using namespace moreau;

namespace {

FieldSpec spec(const char* name) {
  return field_spec("m.nodes", name, 2, 3, 2, "m", FieldOutput::none, false, "a field");
}

/// A State with the set m.nodes (fields `a`, `b`) and two rows.
void fill(State& st) {
  st.add_model({"m", "m.nodes", "", 3});
  st.declare(spec("a"));
  st.declare(spec("b"));
  st.add_bodies({{"x", 0, 1, 0}, {"y", 0, 1, 0}});
}

/// A plugin's cache: `a` required, `c` optional; counts its resolutions.
int resolutions = 0;
struct Refs {
  FieldCacheKey cache_key;
  Field *a = nullptr, *c = nullptr;
  static Refs of(State& st) {
    ++resolutions;
    EntitySet& s = st.set("m.nodes");
    Refs r;
    r.a = &s.field("a");
    r.c = s.find("c");
    r.cache_key.take(st, s);
    return r;
  }
};
/// The same keyed by the set (as a solver's save_state(EntitySet&) would).
struct SetRefs {
  FieldCacheKey cache_key;
  const Field* a = nullptr;
  static SetRefs of(const EntitySet& s) {
    ++resolutions;
    SetRefs r;
    r.a = &s.field("a");
    r.cache_key.take(s);
    return r;
  }
};

}  // namespace

TEST(FieldCache, ResolvedOnceThenAgainWhenAFieldIsDeclaredLater) {
  State st(3);
  fill(st);
  Refs cache;
  resolutions = 0;
  const Refs& r = resolved(cache, st);
  EXPECT_EQ(r.a, &st.field("m.nodes", "a"));
  EXPECT_EQ(r.c, nullptr);
  resolved(cache, st);
  resolved(cache, st);
  EXPECT_EQ(resolutions, 1);  // no lookup while nothing changed
  st.declare(spec("c"));      // the optional field appears: the cache must see it
  EXPECT_EQ(resolved(cache, st).c, &st.field("m.nodes", "c"));
  EXPECT_EQ(resolutions, 2);
  st.add_set("other").declare(field_spec("other", "z", 1, 1, 1, "1", FieldOutput::none, false, "z"));
  resolved(cache, st);  // another set's fields do not invalidate it
  EXPECT_EQ(resolutions, 2);
}

TEST(FieldCache, AnotherStateIsResolvedForItself) {
  State s1(3), s2(3);
  fill(s1);
  fill(s2);  // same sets, same field count
  Refs cache;
  resolved(cache, s1);
  EXPECT_EQ(resolved(cache, s2).a, &s2.field("m.nodes", "a"));
  EXPECT_EQ(resolved(cache, s1).a, &s1.field("m.nodes", "a"));
  // A const user keeps its cache and resolves another State apart.
  Refs other;
  const Refs& r = resolved(static_cast<const Refs&>(cache), s2, other);
  EXPECT_EQ(&r, &other);
  EXPECT_EQ(r.a, &s2.field("m.nodes", "a"));
  EXPECT_EQ(resolved(static_cast<const Refs&>(cache), s1, other).a, &s1.field("m.nodes", "a"));
}

TEST(FieldCache, AStateBuiltWhereADestroyedOneWasIsAnotherState) {
  // Keyed by the State's (or the set's) address and the field count, the cache would hand
  // out the destroyed State's fields here: same address, same sets, same count.
  alignas(State) unsigned char storage[sizeof(State)];
  auto* first = new (storage) State(3);
  fill(*first);
  Refs cache;
  resolved(cache, *first);
  first->~State();
  auto* second = new (storage) State(3);
  fill(*second);
  ASSERT_EQ(static_cast<void*>(first), static_cast<void*>(second));
  EXPECT_FALSE(cache.cache_key.current(*second));
  EXPECT_EQ(resolved(cache, *second).a, &second->field("m.nodes", "a"));
  second->~State();
}

TEST(FieldCache, KeyedByTheSet) {
  State st(2);
  fill(st);
  EntitySet& nodes = st.set("m.nodes");
  SetRefs cache;
  resolutions = 0;
  resolved(cache, nodes);
  resolved(cache, static_cast<const EntitySet&>(nodes));
  EXPECT_EQ(resolutions, 1);
  EntitySet copy = nodes;  // other Field objects: another set
  EXPECT_FALSE(cache.cache_key.current(copy));
  EXPECT_EQ(resolved(cache, copy).a, &copy.field("a"));
  copy = nodes;  // assigned: its Fields are new ones again
  EXPECT_FALSE(cache.cache_key.current(copy));
  EXPECT_FALSE(cache.cache_key.current(st));  // a key taken from a set alone names no place in a State
}

TEST(FieldCache, AMissingRequiredFieldThrowsNamingItAndLeavesTheCache) {
  State good(3), bad(3);
  fill(good);
  bad.add_model({"m", "m.nodes", "", 3});
  bad.declare(spec("b"));  // no `a`
  Refs cache;
  resolved(cache, good);
  try {
    resolved(cache, bad);
    FAIL() << "no throw";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("no field 'a' in the set 'm.nodes'"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(cache.cache_key.current(good));  // as it was
  EXPECT_FALSE(cache.cache_key.current(bad));
  EXPECT_EQ(resolved(cache, good).a, &good.field("m.nodes", "a"));
}
