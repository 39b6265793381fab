#pragma once
// The State store: all the data of a run, as fields on entity sets (docs/architecture.md).
//
// An entity set is a kind of row: the kernel's `bodies` (one row per scene body) and
// `contacts` (one row per contact of the current step), and each modelization's own sets
// (its nodes, its elements: `rigid.nodes` holds one row per rigid body). A field lives on
// one set and is one contiguous array [rows × components] per time depth (structure of
// arrays, as MuJoCo's mjData). A field with two depths holds the values at the beginning
// (⁻) and at the end (⁺) of the step; `swap_depths()` exchanges the two buffers at the end
// of a step (no copy), so the end buffer then holds stale values that the next step
// overwrites.
//
// Which fields exist is declared by tables of FieldSpec (the kernel's, each
// modelization's): the same table drives allocation, the HDF5 output (`output`), restart
// (`restart`), the carrying over of rows rebuilt each step (`persist`) and the docs
// (`moreau plugins`).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <moreau/error.hpp>
#include <span>
#include <string>
#include <vector>

namespace moreau {

enum class Depth { begin = 0, end = 1 };

/// Where a field goes in the output file (docs/output.md).
enum class FieldOutput {
  none,   ///< working data, never written
  frame,  ///< /frames/NNNNNNNN/<set>/<name>, every frame (the end-of-step values)
  once,   ///< /<set>/<name>, once (constant over a run)
};

/// How a field is written to the file; every field is stored as double in memory.
enum class FileType { real, int32, int8 };

/// When the kernel allocates a field: a scene pays only for what it uses.
enum class Needed {
  always,
  contacts,  ///< the scene has interactions
  forces,    ///< the scene has external-force plugins (the field is zeroed at stage external_forces)
  imposed,   ///< the scene has drivers or hooks (imposed velocities; filled with NaN = free)
};

/// The kernel's sets and the modelizations' set names are fixed strings; a modelization's
/// sets are named "<model>.<set>" (e.g. "rigid.nodes"), the kernel's have no dot.
namespace sets {
inline constexpr const char* bodies = "bodies";
inline constexpr const char* contacts = "contacts";
inline constexpr const char* solver = "solver";  ///< one row: a solver's own state (Solver::state_fields)
}  // namespace sets

struct FieldSpec {
  std::string name;
  std::string set;        ///< the entity set whose rows it has
  int components_2d = 1;  ///< values per row in 2D scenes (0: field absent in 2D)
  int components_3d = 1;  ///< values per row in 3D scenes (0: field absent in 3D)
  int depths = 1;         ///< 1, or 2 for fields with ⁻ and ⁺ values
  std::string units;      ///< SI units, "1" for dimensionless
  std::string doc;
  FieldOutput output = FieldOutput::none;
  bool restart = false;   ///< part of the dynamic state a restart must restore
  /// Rows rebuilt each step (contacts): the values at Depth::begin are carried over to the
  /// new row of the same identity (the warm start; laws' internal variables). New rows: 0.
  bool persist = false;
  FileType file = FileType::real;
  Needed needed = Needed::always;

  int components(int dim) const { return dim == 2 ? components_2d : components_3d; }
};

/// A FieldSpec in one line, for field tables (rigid_fields.hpp, contact_fields.hpp, a
/// modelization's own): set a few more members on the result when needed (persist, file…).
inline FieldSpec field_spec(std::string set, std::string name, int components_2d, int components_3d, int depths,
                            std::string units, FieldOutput output, bool restart, std::string doc,
                            FileType file = FileType::real, Needed needed = Needed::always) {
  FieldSpec s;
  s.name = std::move(name);
  s.set = std::move(set);
  s.components_2d = components_2d;
  s.components_3d = components_3d;
  s.depths = depths;
  s.units = std::move(units);
  s.output = output;
  s.restart = restart;
  s.doc = std::move(doc);
  s.file = file;
  s.needed = needed;
  return s;
}

class Field {
 public:
  Field(FieldSpec spec, int components) : spec_(std::move(spec)), comps_(components) {}

  const FieldSpec& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  int components() const { return comps_; }
  std::size_t rows() const { return n_; }

  /// The contiguous array [rows × components] of one depth.
  double* data(Depth d = Depth::end) { return buf_[index(d)].data(); }
  const double* data(Depth d = Depth::end) const { return buf_[index(d)].data(); }
  std::span<double> row(std::size_t r, Depth d = Depth::end) {
    return {data(d) + r * comps_, static_cast<std::size_t>(comps_)};
  }
  std::span<const double> row(std::size_t r, Depth d = Depth::end) const {
    return {data(d) + r * comps_, static_cast<std::size_t>(comps_)};
  }
  /// Rows [first, first + count) of one depth, contiguous.
  std::span<double> rows(std::size_t first, std::size_t count, Depth d = Depth::end) {
    return {data(d) + first * comps_, count * comps_};
  }
  std::span<const double> rows(std::size_t first, std::size_t count, Depth d = Depth::end) const {
    return {data(d) + first * comps_, count * comps_};
  }

  /// Resizes to n rows, keeping the values of the rows that stay; new rows get `fill`.
  void resize(std::size_t n, double fill = 0.0) {
    n_ = n;
    for (int k = 0; k < spec_.depths; ++k) buf_[k].resize(n * comps_, fill);
  }
  void swap_depths() {
    if (spec_.depths == 2) std::swap(buf_[0], buf_[1]);
  }

 private:
  friend class EntitySet;
  int index(Depth d) const { return spec_.depths == 2 ? static_cast<int>(d) : 0; }
  FieldSpec spec_;
  int comps_;
  std::size_t n_ = 0;
  std::vector<double> buf_[2];
};

/// Rows of one kind of entity, and the fields on them.
class EntitySet {
 public:
  EntitySet(std::string name, int dim) : name_(std::move(name)), dim_(dim) {}

  const std::string& name() const { return name_; }
  std::size_t rows() const { return rows_; }
  /// What tells this set from every other, alive or destroyed, for as long as someone holds
  /// it (FieldCacheKey, field_cache.hpp): its address does not, since a new State's set may
  /// take a destroyed one's place. A copy, or a set assigned to, has other Fields: a new one.
  const std::shared_ptr<const void>& identity() const { return identity_.token; }

  /// Declares a field of this set. Declaring the same name twice with the same shape is
  /// allowed (two plugins needing one field); different shapes not.
  Field& declare(const FieldSpec& spec) {
    const int comps = spec.components(dim_);
    auto it = index_.find(spec.name);
    if (it != index_.end()) {
      Field& f = fields_[it->second];
      if (f.components() != comps || f.spec().depths != spec.depths)
        throw std::logic_error("field '" + name_ + "/" + spec.name + "' declared twice with different shapes");
      return f;
    }
    if (comps <= 0) throw std::logic_error("field '" + name_ + "/" + spec.name + "' does not exist in this dimension");
    index_[spec.name] = fields_.size();
    fields_.emplace_back(spec, comps);
    fields_.back().spec_.set = name_;
    fields_.back().resize(rows_, spec.needed == Needed::imposed ? nan_fill() : 0.0);
    return fields_.back();
  }

  bool has(const std::string& name) const { return index_.count(name) != 0; }
  Field& field(const std::string& name) { return fields_[lookup(name)]; }
  const Field& field(const std::string& name) const { return fields_[lookup(name)]; }
  /// nullptr when the set has no such field.
  Field* find(const std::string& name) {
    auto it = index_.find(name);
    return it == index_.end() ? nullptr : &fields_[it->second];
  }
  const Field* find(const std::string& name) const {
    auto it = index_.find(name);
    return it == index_.end() ? nullptr : &fields_[it->second];
  }
  std::deque<Field>& fields() { return fields_; }
  const std::deque<Field>& fields() const { return fields_; }

  /// Appends n rows (zero in every field, NaN in imposed ones); returns the first.
  std::size_t add_rows(std::size_t n) {
    const std::size_t first = rows_;
    rows_ += n;
    for (auto& f : fields_) f.resize(rows_, f.spec().needed == Needed::imposed ? nan_fill() : 0.0);
    return first;
  }

  /// The rows anew (rows rebuilt each step: contacts): new row i continues old row
  /// `from[i]` (−1: a new entity). Persistent fields carry their Depth::begin values (both
  /// depths of the new row get them); the other fields are zeroed.
  void rebuild(const std::vector<std::ptrdiff_t>& from) {
    const std::size_t n = from.size();
    for (auto& f : fields_) {
      const int c = f.comps_;
      if (f.spec().persist) {
        std::vector<double> carried(n * c, 0.0);
        const double* old = f.data(Depth::begin);
        for (std::size_t i = 0; i < n; ++i)
          if (from[i] >= 0)
            for (int k = 0; k < c; ++k) carried[i * c + k] = old[static_cast<std::size_t>(from[i]) * c + k];
        f.n_ = n;
        if (f.spec().depths == 2) f.buf_[1] = carried;
        f.buf_[0] = std::move(carried);
      } else {
        f.n_ = n;
        for (int d = 0; d < f.spec().depths; ++d) f.buf_[d].assign(n * c, 0.0);
      }
    }
    rows_ = n;
  }

  void swap_depths() {
    for (auto& f : fields_) f.swap_depths();
  }

 private:
  static double nan_fill() { return __builtin_nan(""); }
  std::size_t lookup(const std::string& name) const {
    auto it = index_.find(name);
    if (it == index_.end()) throw std::logic_error("no field '" + name + "' in the set '" + name_ + "'");
    return it->second;
  }
  struct Identity {
    std::shared_ptr<const void> token = std::make_shared<char>();
    Identity() = default;
    Identity(const Identity&) {}  // a new token
    Identity& operator=(const Identity&) {
      token = std::make_shared<char>();
      return *this;
    }
  };
  std::string name_;
  int dim_;
  std::size_t rows_ = 0;
  Identity identity_;
  std::deque<Field> fields_;  // deque: a Field& stays valid when more fields are declared
  std::map<std::string, std::size_t> index_;
};

/// A modelization of the scene, as the State records it: its name and its sets.
struct ModelInfo {
  std::string name;      ///< the modelization plugin (a body's `model`)
  std::string nodes;     ///< its node set ("<model>.nodes")
  std::string elements;  ///< its element set, "" when it has none
  int node_dofs = 0;     ///< unknowns per node (generalised velocity: rigid 3 in 2D, 6 in 3D)
};

/// Where a body's data is: its modelization (index into State::models()) and its ranges
/// of rows in that modelization's node and element sets.
struct BodyRows {
  int model = -1;
  std::size_t first_node = 0, nodes = 0;
  std::size_t first_element = 0, elements = 0;
};

/// Named groups of a body's rows (docs/architecture.md "Groups"): a mesh's physical groups
/// or a generator's sets, recorded by the modelization when it fills the body, read by the
/// kernel (contactors on a boundary, drivers on nodes) and by plugins (forces on nodes).
/// A facet group lists boundary facets (edges in 2D, triangles or quadrangles in 3D), each
/// as node rows in outward order: counter-clockwise seen from outside in 3D; in 2D the
/// edge's direction turned by −90° is the outward normal.
struct FacetGroup {
  std::vector<std::size_t> offset{0};  ///< facet i has the nodes nodes[offset[i] .. offset[i+1])
  std::vector<std::size_t> nodes;      ///< rows of the modelization's node set
  std::size_t size() const { return offset.size() - 1; }
  std::size_t count(std::size_t i) const { return offset[i + 1] - offset[i]; }
  const std::size_t* facet(std::size_t i) const { return nodes.data() + offset[i]; }
};
struct BodyGroups {
  std::map<std::string, std::vector<std::size_t>> nodes;  ///< node rows, sorted
  std::map<std::string, FacetGroup> facets;
};

/// A body to add: its name, modelization and how many nodes and elements it owns.
struct BodyLayout {
  std::string name;
  int model = 0;
  std::size_t nodes = 1, elements = 0;
};

/// The kernel's table of the `bodies` set (DESIGN §5): one row per scene body.
namespace body_fields {
inline constexpr const char* model = "model";
inline constexpr const char* first_node = "first_node";
inline constexpr const char* nodes = "nodes";
inline constexpr const char* first_element = "first_element";
inline constexpr const char* elements = "elements";
/// In every modelization set: the body each row belongs to (index into `bodies`).
inline constexpr const char* body = "body";
}  // namespace body_fields

class State {
 public:
  explicit State(int dimension = 3) : dim_(dimension) {
    auto f = [](const char* name, const char* doc) {
      return field_spec(sets::bodies, name, 1, 1, 1, "1", FieldOutput::once, false, doc, FileType::int32);
    };
    declare(f(body_fields::model, "its modelization: index into /models/name"));
    declare(f(body_fields::first_node, "first row of its nodes in its modelization's node set"));
    declare(f(body_fields::nodes, "number of its nodes"));
    declare(f(body_fields::first_element, "first row of its elements in its modelization's element set"));
    declare(f(body_fields::elements, "number of its elements"));
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  int dimension() const { return dim_; }

  // ---- Sets and fields ----------------------------------------------------------------
  /// The set of that name, created empty if needed.
  EntitySet& add_set(const std::string& name) {
    if (EntitySet* s = find_set(name)) return *s;
    set_index_[name] = sets_.size();
    sets_.emplace_back(name, dim_);
    return sets_.back();
  }
  bool has_set(const std::string& name) const { return set_index_.count(name) != 0; }
  EntitySet& set(const std::string& name) { return sets_[set_lookup(name)]; }
  const EntitySet& set(const std::string& name) const { return sets_[set_lookup(name)]; }
  EntitySet* find_set(const std::string& name) {
    auto it = set_index_.find(name);
    return it == set_index_.end() ? nullptr : &sets_[it->second];
  }
  const EntitySet* find_set(const std::string& name) const {
    auto it = set_index_.find(name);
    return it == set_index_.end() ? nullptr : &sets_[it->second];
  }
  std::deque<EntitySet>& sets() { return sets_; }
  const std::deque<EntitySet>& sets() const { return sets_; }

  /// Declares a field on its set (`spec.set`, created if needed).
  Field& declare(const FieldSpec& spec) {
    if (spec.set.empty()) throw std::logic_error("field '" + spec.name + "' names no set");
    return add_set(spec.set).declare(spec);
  }
  /// Declares the fields of a table that exist in this dimension.
  void declare(const std::vector<FieldSpec>& table) {
    for (const auto& s : table)
      if (s.components(dim_) > 0) declare(s);
  }
  bool has(const std::string& set, const std::string& name) const {
    const EntitySet* s = find_set(set);
    return s && s->has(name);
  }
  Field& field(const std::string& set, const std::string& name) { return this->set(set).field(name); }
  const Field& field(const std::string& set, const std::string& name) const { return this->set(set).field(name); }

  // ---- Modelizations and bodies -------------------------------------------------------
  /// Records a modelization (creating its sets); returns its index.
  int add_model(const ModelInfo& m) {
    for (std::size_t i = 0; i < models_.size(); ++i)
      if (models_[i].name == m.name) return static_cast<int>(i);
    models_.push_back(m);
    add_set(m.nodes).declare(owner_field(m.nodes));
    if (!m.elements.empty()) add_set(m.elements).declare(owner_field(m.elements));
    return static_cast<int>(models_.size() - 1);
  }
  const std::vector<ModelInfo>& models() const { return models_; }
  int find_model(const std::string& name) const {
    for (std::size_t i = 0; i < models_.size(); ++i)
      if (models_[i].name == name) return static_cast<int>(i);
    return -1;
  }

  std::size_t bodies() const { return names_.size(); }
  const std::vector<std::string>& names() const { return names_; }
  /// Index of a body by name, or -1.
  int find_body(const std::string& name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return static_cast<int>(i);
    return -1;
  }

  /// Adds bodies, their rows in `bodies` and their node and element rows in their
  /// modelizations' sets (zero-filled), all at once; returns the index of the first.
  std::size_t add_bodies(const std::vector<BodyLayout>& bodies) {
    const std::size_t first = names_.size();
    std::vector<std::size_t> nodes(models_.size(), 0), elements(models_.size(), 0);
    for (const auto& b : bodies) {
      if (b.model < 0 || static_cast<std::size_t>(b.model) >= models_.size())
        throw std::logic_error("body '" + b.name + "' of an unknown modelization");
      nodes[b.model] += b.nodes;
      elements[b.model] += b.elements;
    }
    std::vector<std::size_t> next_node(models_.size()), next_element(models_.size());
    for (std::size_t m = 0; m < models_.size(); ++m) {
      next_node[m] = set(models_[m].nodes).add_rows(nodes[m]);
      if (!models_[m].elements.empty()) next_element[m] = set(models_[m].elements).add_rows(elements[m]);
      else if (elements[m] > 0) throw std::logic_error("modelization '" + models_[m].name + "' has no element set");
    }
    EntitySet& bs = set(sets::bodies);
    bs.add_rows(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const auto& b = bodies[i];
      const std::size_t row = first + i;
      names_.push_back(b.name);
      bs.field(body_fields::model).data()[row] = b.model;
      bs.field(body_fields::first_node).data()[row] = static_cast<double>(next_node[b.model]);
      bs.field(body_fields::nodes).data()[row] = static_cast<double>(b.nodes);
      bs.field(body_fields::first_element).data()[row] = static_cast<double>(next_element[b.model]);
      bs.field(body_fields::elements).data()[row] = static_cast<double>(b.elements);
      double* owner = set(models_[b.model].nodes).field(body_fields::body).data();
      for (std::size_t k = 0; k < b.nodes; ++k) owner[next_node[b.model] + k] = static_cast<double>(row);
      if (b.elements > 0) {
        double* eo = set(models_[b.model].elements).field(body_fields::body).data();
        for (std::size_t k = 0; k < b.elements; ++k) eo[next_element[b.model] + k] = static_cast<double>(row);
      }
      next_node[b.model] += b.nodes;
      next_element[b.model] += b.elements;
    }
    return first;
  }

  /// Where body `b`'s data is.
  BodyRows body(std::size_t b) const {
    const EntitySet& bs = set(sets::bodies);
    BodyRows r;
    r.model = static_cast<int>(bs.field(body_fields::model).data()[b]);
    r.first_node = static_cast<std::size_t>(bs.field(body_fields::first_node).data()[b]);
    r.nodes = static_cast<std::size_t>(bs.field(body_fields::nodes).data()[b]);
    r.first_element = static_cast<std::size_t>(bs.field(body_fields::first_element).data()[b]);
    r.elements = static_cast<std::size_t>(bs.field(body_fields::elements).data()[b]);
    return r;
  }
  const ModelInfo& model_of(std::size_t b) const { return models_[static_cast<std::size_t>(body(b).model)]; }

  /// The values of a node field for all of body `b`'s nodes ([nodes × components],
  /// contiguous: a body's nodes are consecutive rows). A rigid body has one node, so this
  /// is its row. Throws std::logic_error when the body's modelization has no such field.
  std::span<double> node_values(std::size_t b, const std::string& name, Depth d = Depth::end) {
    const BodyRows r = body(b);
    return field(models_[r.model].nodes, name).rows(r.first_node, r.nodes, d);
  }
  std::span<const double> node_values(std::size_t b, const std::string& name, Depth d = Depth::end) const {
    const BodyRows r = body(b);
    return field(models_[r.model].nodes, name).rows(r.first_node, r.nodes, d);
  }
  /// Whether body `b`'s modelization has the node field `name`.
  bool has_node_field(std::size_t b, const std::string& name) const { return has(model_of(b).nodes, name); }

  // ---- Named groups of a body's rows ---------------------------------------------------
  /// Records body `b`'s groups (its modelization, when it fills the body).
  void set_groups(std::size_t b, BodyGroups g) { groups_[b] = std::move(g); }
  /// Body `b`'s groups, or null when its modelization records none (rigid bodies).
  const BodyGroups* groups(std::size_t b) const {
    auto it = groups_.find(b);
    return it == groups_.end() ? nullptr : &it->second;
  }
  /// The node rows of body `b`'s group `name`. Throws InputError at `pointer`, naming the
  /// body's groups, when it has no such group.
  const std::vector<std::size_t>& node_group(std::size_t b, const std::string& name, const std::string& pointer) const {
    const BodyGroups* g = groups(b);
    if (g) {
      auto it = g->nodes.find(name);
      if (it != g->nodes.end()) return it->second;
    }
    throw InputError(pointer, group_fault(b, name, "node", g ? names_of(g->nodes) : std::string()));
  }
  /// The facets of body `b`'s group `name` (same faults as node_group).
  const FacetGroup& facet_group(std::size_t b, const std::string& name, const std::string& pointer) const {
    const BodyGroups* g = groups(b);
    if (g) {
      auto it = g->facets.find(name);
      if (it != g->facets.end()) return it->second;
    }
    throw InputError(pointer, group_fault(b, name, "boundary", g ? names_of(g->facets) : std::string()));
  }

  /// End of step: ⁺ values become the ⁻ values of the next step (buffers swapped).
  void swap_depths() {
    for (auto& s : sets_) s.swap_depths();
  }

 private:
  static FieldSpec owner_field(const std::string& set) {
    return field_spec(set, body_fields::body, 1, 1, 1, "1", FieldOutput::once, false,
                      "the body of each row (index into /bodies)", FileType::int32);
  }
  template <class Map>
  static std::string names_of(const Map& m) {
    std::string s;
    for (const auto& [k, v] : m) s += (s.empty() ? "\"" : ", \"") + k + "\"";
    return s;
  }
  std::string group_fault(std::size_t b, const std::string& name, const char* kind, const std::string& valid) const {
    const std::string body = "body \"" + names_[b] + "\"";
    if (valid.empty())
      return body + " (a \"" + model_of(b).name + "\" body) has no " + kind + " groups, so no " + kind + " group \"" + name + "\"";
    return body + " has no " + kind + " group \"" + name + "\"; its " + kind + " groups: " + valid;
  }
  std::size_t set_lookup(const std::string& name) const {
    auto it = set_index_.find(name);
    if (it == set_index_.end()) throw std::logic_error("no set '" + name + "' in the state");
    return it->second;
  }
  int dim_;
  std::vector<std::string> names_;
  std::vector<ModelInfo> models_;
  std::deque<EntitySet> sets_;  // deque: references stay valid when sets are added
  std::map<std::string, std::size_t> set_index_;
  std::map<std::size_t, BodyGroups> groups_;
};

}  // namespace moreau
