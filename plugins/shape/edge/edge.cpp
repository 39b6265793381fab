// `edge` (2D): a boundary edge of a mesh as a contact antagonist (facet_shape.hpp).
#include "facet_shape.hpp"

namespace {
using Edge = moreau_facet::Facet<2>;
struct EdgeShape : Edge {
  using Edge::Edge;
  static constexpr const char* doc = "a boundary edge of a mesh as a contact antagonist (2 nodes)";
};
MOREAU_REGISTER(EdgeShape, "edge")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_edge")
