#pragma once
// The State store: all per-body data of a run, one contiguous array per field
// (structure of arrays, as MuJoCo's mjData), addressable by field name and body.
//
// A field with two time depths holds the values at the beginning (⁻) and at the end
// (⁺) of the step; `swap_depths()` exchanges the two buffers at the end of a step (no
// copy), so the end buffer then holds stale values that the next step overwrites.
//
// Which fields exist is declared by tables of FieldSpec (a modelization's table, see
// plugins/modelization/rigid/rigid_fields.hpp): the same table drives allocation,
// the HDF5 output (`output`), restart (`restart`) and the docs (`moreau plugins`).
#include <cstddef>
#include <deque>
#include <map>
#include <moreau/error.hpp>
#include <span>
#include <string>
#include <vector>

namespace moreau {

enum class Depth { begin = 0, end = 1 };

/// Where a field goes in the output file.
enum class FieldOutput {
  none,    ///< working data, never written
  frame,   ///< /frames/NNNNNNNN/<name>, every frame (the end-of-step values)
  bodies,  ///< /bodies/<name>, once (constant over a run)
};

struct FieldSpec {
  std::string name;
  int components_2d = 1;  ///< values per body in 2D scenes (0: field absent in 2D)
  int components_3d = 1;  ///< values per body in 3D scenes (0: field absent in 3D)
  int depths = 1;         ///< 1, or 2 for fields with ⁻ and ⁺ values
  std::string units;      ///< SI units, "1" for dimensionless
  std::string doc;
  FieldOutput output = FieldOutput::none;
  bool restart = false;   ///< part of the dynamic state a restart must restore
  bool as_int8 = false;   ///< written as int8 (flags); stored as double like every field

  int components(int dim) const { return dim == 2 ? components_2d : components_3d; }
};

class Field {
 public:
  Field(FieldSpec spec, int components) : spec_(std::move(spec)), comps_(components) {}

  const FieldSpec& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  int components() const { return comps_; }
  std::size_t bodies() const { return n_; }

  /// The contiguous array [bodies × components] of one depth.
  double* data(Depth d = Depth::end) { return buf_[index(d)].data(); }
  const double* data(Depth d = Depth::end) const { return buf_[index(d)].data(); }
  std::span<double> row(std::size_t body, Depth d = Depth::end) {
    return {data(d) + body * comps_, static_cast<std::size_t>(comps_)};
  }
  std::span<const double> row(std::size_t body, Depth d = Depth::end) const {
    return {data(d) + body * comps_, static_cast<std::size_t>(comps_)};
  }

  void resize(std::size_t n, double fill = 0.0) {
    n_ = n;
    for (int k = 0; k < spec_.depths; ++k) buf_[k].assign(n * comps_, fill);
  }
  void swap_depths() {
    if (spec_.depths == 2) std::swap(buf_[0], buf_[1]);
  }

 private:
  int index(Depth d) const { return spec_.depths == 2 ? static_cast<int>(d) : 0; }
  FieldSpec spec_;
  int comps_;
  std::size_t n_ = 0;
  std::vector<double> buf_[2];
};

class State {
 public:
  explicit State(int dimension = 3) : dim_(dimension) {}

  int dimension() const { return dim_; }
  std::size_t bodies() const { return names_.size(); }

  /// Declares a field (before or after bodies are added). Declaring the same name twice
  /// with the same shape is allowed (two plugins needing one field); different shapes not.
  Field& declare(const FieldSpec& spec) {
    const int comps = spec.components(dim_);
    auto it = index_.find(spec.name);
    if (it != index_.end()) {
      Field& f = fields_[it->second];
      if (f.components() != comps || f.spec().depths != spec.depths)
        throw std::logic_error("field '" + spec.name + "' declared twice with different shapes");
      return f;
    }
    if (comps <= 0) throw std::logic_error("field '" + spec.name + "' does not exist in this dimension");
    index_[spec.name] = fields_.size();
    fields_.emplace_back(spec, comps);
    fields_.back().resize(bodies());
    return fields_.back();
  }
  void declare(const std::vector<FieldSpec>& table) {
    for (const auto& s : table)
      if (s.components(dim_) > 0) declare(s);
  }

  /// Adds n bodies (zero-filled in every field); returns the index of the first.
  std::size_t add_bodies(const std::vector<std::string>& names) {
    const std::size_t first = names_.size();
    for (const auto& n : names) names_.push_back(n);
    for (auto& f : fields_) {
      std::vector<double> keep[2];
      for (int d = 0; d < f.spec().depths; ++d)
        keep[d].assign(f.data(static_cast<Depth>(d)), f.data(static_cast<Depth>(d)) + first * f.components());
      f.resize(names_.size());
      for (int d = 0; d < f.spec().depths; ++d) std::copy(keep[d].begin(), keep[d].end(), f.data(static_cast<Depth>(d)));
    }
    return first;
  }

  bool has(const std::string& name) const { return index_.count(name) != 0; }
  Field& field(const std::string& name) { return fields_[lookup(name)]; }
  const Field& field(const std::string& name) const { return fields_[lookup(name)]; }
  std::deque<Field>& fields() { return fields_; }
  const std::deque<Field>& fields() const { return fields_; }

  const std::vector<std::string>& names() const { return names_; }
  /// Index of a body by name, or -1.
  int find_body(const std::string& name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return static_cast<int>(i);
    return -1;
  }

  /// End of step: ⁺ values become the ⁻ values of the next step (buffers swapped).
  void swap_depths() {
    for (auto& f : fields_) f.swap_depths();
  }

 private:
  std::size_t lookup(const std::string& name) const {
    auto it = index_.find(name);
    if (it == index_.end()) throw std::logic_error("no field '" + name + "' in the state");
    return it->second;
  }
  int dim_;
  std::vector<std::string> names_;
  std::deque<Field> fields_;  // deque: a Field& stays valid when more fields are declared
  std::map<std::string, std::size_t> index_;
};

}  // namespace moreau
