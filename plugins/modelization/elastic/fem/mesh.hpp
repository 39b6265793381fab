#pragma once
// A finite-element mesh: reference node coordinates, elements of mixed types, and named
// sets (Gmsh physical groups, or the sets a generator names). Nodes and elements are
// numbered from 0 in the arrays; the numbers a user knows (Gmsh tags, or 1-based for a
// generated mesh) are kept for messages.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "element.hpp"
#include "error.hpp"

namespace moreau::fem {

/// Cells of possibly mixed types in compressed rows: cell i has type[i] and the nodes
/// nodes[offset[i] .. offset[i+1]).
struct Cells {
  std::vector<ElementType> type;
  std::vector<int> offset{0};
  std::vector<int> nodes;

  int size() const { return static_cast<int>(type.size()); }
  std::span<const int> operator[](int i) const {
    return {nodes.data() + offset[i], static_cast<std::size_t>(offset[i + 1] - offset[i])};
  }
  std::span<int> at(int i) { return {nodes.data() + offset[i], static_cast<std::size_t>(offset[i + 1] - offset[i])}; }
  void add(ElementType t, std::span<const int> cell_nodes);
  void reserve(int cells, int total_nodes);
};

/// Element faces (edges in 2D, faces in 3D), each owned by one element: nodes in the
/// outward order of element.hpp, so the owning element lies on the inner side.
struct Facets {
  Cells cells;
  std::vector<int> element;  ///< owning element
  std::vector<int> face;     ///< local face number in the owning element's table

  int size() const { return cells.size(); }
};

struct Mesh {
  int dim = 0;                  ///< 2 or 3
  Eigen::MatrixXd x;            ///< [dim, nodes] reference coordinates (m)
  Cells elements;               ///< T3/Q4 in 2D, T4/H8 in 3D
  std::map<std::string, std::vector<int>> node_sets;     ///< sorted node numbers
  std::map<std::string, std::vector<int>> element_sets;  ///< sorted element numbers
  std::map<std::string, Facets> boundary_sets;           ///< faces on named boundaries

  // Provenance, for messages only.
  std::string source;                        ///< file path, or the generator's name
  bool from_file = false;                    ///< source is a file
  std::vector<std::int64_t> node_number;     ///< user's number of each node; empty: index + 1
  std::vector<std::int64_t> element_number;  ///< user's number of each element; empty: index + 1
  std::vector<long> element_line;            ///< line of each element in the file; empty/0: unknown
  std::vector<std::string> notes;            ///< what a reader did that a user may want to know

  int node_count() const { return static_cast<int>(x.cols()); }
  int element_count() const { return elements.size(); }
  int dof_count() const { return dim * node_count(); }

  std::int64_t element_label(int e) const;  ///< the user's number of element e
  std::int64_t node_label(int n) const;     ///< the user's number of node n
  /// "element 17 (beam.msh:245)" or "element 17 of the rectangle mesh".
  std::string describe_element(int e) const;

  /// The named set; an unknown name throws MeshError listing the valid names.
  const std::vector<int>& node_set(const std::string& name) const;
  const std::vector<int>& element_set(const std::string& name) const;
  const Facets& boundary_set(const std::string& name) const;
};

/// Every face that belongs to exactly one element, ordered by (element, local face),
/// oriented outward. Faces are matched by their corner nodes.
Facets boundary_facets(const Mesh& mesh);

/// Sorted distinct nodes of some facets.
std::vector<int> facet_nodes(const Facets& facets);

/// Outward unit normal of facet i (from its first corners; exact for straight edges and
/// flat faces) and its measure (length in 2D, area in 3D).
Eigen::Vector3d facet_normal(const Mesh& mesh, const Facets& facets, int i, double* measure = nullptr);

/// Matches faces given by their nodes (e.g. boundary elements of a Gmsh physical group)
/// to element faces, giving them the owning element and the outward order. A face with no
/// matching element face throws the MeshError that `fault(f)` makes.
Facets match_facets(const Mesh& mesh, const Cells& faces, const std::function<MeshError(int)>& fault);

/// Signed measure of element e (area in 2D, volume in 3D), by the element's rule.
double element_measure(const Mesh& mesh, int e);

}  // namespace moreau::fem
