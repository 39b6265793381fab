#pragma once
// Field pointers resolved by name once, for code that reads the same fields at every step
// or every contact (sdk/README.md, "Resolving fields once"). A lookup by name is a search
// of a map of strings; in hot loops they cost a fifth of a one-body step's CPU time.
//
// A Field keeps its address for its set's life (EntitySet holds its fields in a deque and
// never removes one), so a Field* resolved once stays valid; its buffers do not (depths
// swap, rows change), so ask data() at each use. What may change is which set and which
// fields: another State (even at the same address as a destroyed one), or a field declared
// since, which an optional lookup (find()) missed. FieldCacheKey tells both apart:
//   - the set by its identity (EntitySet::identity()), never by its address;
//   - the number of fields of that set.
// Pointers to required fields (field(), throws when missing) of other sets of the same
// State stay valid too: the set of the key lives as long as its State.
#include <cstddef>
#include <memory>
#include <moreau/state.hpp>
#include <stdexcept>

namespace moreau {

class FieldCacheKey {
 public:
  /// Whether fields resolved from a set when the key was taken are still `set`'s: the same
  /// set (alive), with as many fields.
  bool current(const EntitySet& set) const { return set.identity() == set_ && set.fields().size() == count_; }
  /// The same for a key taken with take(state, set), without looking the set up by name.
  bool current(const State& st) const {
    const auto& sets = st.sets();
    return position_ < sets.size() && current(sets[position_]);
  }

  /// Takes the key of `set`: call it after resolving the fields (a throw leaves no key).
  void take(const EntitySet& set) {
    set_ = set.identity();
    count_ = set.fields().size();
    position_ = static_cast<std::size_t>(-1);
  }
  /// Takes the key of `set`, one of `st`'s sets, for current(st).
  void take(const State& st, const EntitySet& set) {
    take(set);
    const auto& sets = st.sets();
    for (position_ = 0; position_ < sets.size(); ++position_)
      if (&sets[position_] == &set) return;
    throw std::logic_error("FieldCacheKey: the set '" + set.name() + "' is not one of the state's");
  }

 private:
  std::shared_ptr<const void> set_;  // held: no other set can take its identity while the key lives
  std::size_t count_ = 0;
  std::size_t position_ = static_cast<std::size_t>(-1);  // in State::sets()
};

/// The usual use. `cache` is a struct of the Field pointers some code reads, with a
/// FieldCacheKey `cache_key` and a static `of(on)` that resolves them by name (a missing
/// required field throws, naming it, as EntitySet::field does) and takes the key last;
/// `on` is a State or an EntitySet, as the key is taken. Resolved anew when not current.
template <class Cache, class On>
const Cache& resolved(Cache& cache, On& on) {
  if (!cache.cache_key.current(on)) cache = Cache::of(on);
  return cache;
}

/// In a const member function, with a cache filled where the object may change (prepare,
/// init_body): the cache when current, else `other` resolved for `on` (the cache stays).
template <class Cache, class On>
const Cache& resolved(const Cache& cache, On& on, Cache& other) {
  if (cache.cache_key.current(on)) return cache;
  other = Cache::of(on);
  return other;
}

}  // namespace moreau
