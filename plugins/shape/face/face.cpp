// `face` (3D): a boundary triangle or quadrangle of a mesh as a contact antagonist
// (plugins/shape/edge/facet_shape.hpp).
#include <facet_shape.hpp>

namespace {
using Face = moreau_facet::Facet<3>;
struct FaceShape : Face {
  using Face::Face;
  static constexpr const char* doc = "a boundary triangle or quadrangle of a mesh as a contact antagonist (3 or 4 nodes)";
};
MOREAU_REGISTER(FaceShape, "face")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_shape_face")
