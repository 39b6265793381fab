// Gmsh reader: the four encodings of one mesh agree, physical groups become sets, and every
// kind of bad file is refused with its file, line and what was expected.
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "fem_test_util.hpp"
#include "gmsh_read.hpp"

namespace moreau::fem {
namespace {

std::string data(const std::string& name) { return std::string(MOREAU_FEM_DATA) + "/" + name; }

double total_measure(const Mesh& mesh) {
  double v = 0;
  for (int e = 0; e < mesh.element_count(); ++e) v += element_measure(mesh, e);
  return v;
}

TEST(FemGmsh, FourEncodingsOfOneMeshAgree) {
  const Mesh ref = read_gmsh(data("square_41.msh"));
  EXPECT_EQ(ref.dim, 2);
  EXPECT_GT(ref.element_count(), 50);
  EXPECT_NEAR(total_measure(ref), 2.0, 1e-12);
  for (const char* name : {"square_22.msh", "square_41_bin.msh", "square_22_bin.msh"}) {
    SCOPED_TRACE(name);
    const Mesh m = read_gmsh(data(name));
    EXPECT_TRUE(m.x.isApprox(ref.x, 1e-15));  // ASCII files hold 16 digits, binary ones all bits
    EXPECT_EQ(m.elements.nodes, ref.elements.nodes);
    EXPECT_EQ(m.node_number, ref.node_number);  // (element numbers differ: 2.2 renumbers repeats)
    EXPECT_EQ(m.node_sets, ref.node_sets);
    EXPECT_EQ(m.element_sets, ref.element_sets);
    ASSERT_EQ(m.boundary_sets.size(), ref.boundary_sets.size());
    for (const auto& [set, facets] : ref.boundary_sets) EXPECT_EQ(m.boundary_set(set).cells.nodes, facets.cells.nodes);
  }
}

TEST(FemGmsh, WindowsLineEndings) {
  std::ifstream in(data("square_41.msh"));
  std::string text, line;
  while (std::getline(in, line)) text += line + "\r\n";
  const Mesh crlf = parse_gmsh(text, "crlf.msh"), ref = read_gmsh(data("square_41.msh"));
  EXPECT_EQ(crlf.x, ref.x);
  EXPECT_EQ(crlf.elements.nodes, ref.elements.nodes);
  EXPECT_EQ(crlf.node_sets, ref.node_sets);
}

TEST(FemGmsh, PhysicalGroupsBecomeSets) {
  const Mesh m = read_gmsh(data("square_22.msh"));  // every triangle twice: "body" and "steel"
  EXPECT_EQ(m.element_set("body").size(), static_cast<std::size_t>(m.element_count()));
  EXPECT_EQ(m.element_set("steel"), m.element_set("body"));
  EXPECT_EQ(m.element_set("all").size(), static_cast<std::size_t>(m.element_count()));
  for (int n : m.node_set("left")) EXPECT_EQ(m.x(0, n), 0.0);
  for (int n : m.node_set("top")) EXPECT_EQ(m.x(1, n), 1.0);
  EXPECT_EQ(m.node_set("left").size(), 5u);  // 1 m at size 0.25
  ASSERT_EQ(m.node_set("origin").size(), 1u);
  EXPECT_EQ(m.x.col(m.node_set("origin")[0]), Eigen::Vector2d(0, 0));
  // Boundary sets are oriented outward: the left side's normals are −x.
  const Facets& left = m.boundary_set("left");
  EXPECT_EQ(left.size(), 4);
  for (int f = 0; f < left.size(); ++f) EXPECT_NEAR(facet_normal(m, left, f).x(), -1.0, 1e-14);
  // The whole boundary, added by the reader: 2·(2 + 1) m of edges.
  double length = 0;
  const Facets& boundary = m.boundary_set("boundary");
  for (int f = 0; f < boundary.size(); ++f) {
    double l = 0;
    facet_normal(m, boundary, f, &l);
    length += l;
  }
  EXPECT_NEAR(length, 6.0, 1e-12);
  // An unknown name lists the valid ones.
  try {
    m.node_set("rigth");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("has no node set 'rigth'; valid: 'body', 'bottom', 'boundary', 'left', "
                                         "'origin', 'right', 'steel', 'top'"),
              std::string::npos)
        << e.what();
  }
}

TEST(FemGmsh, QuadranglesAndUnnamedGroups) {
  const Mesh m = read_gmsh(data("square_quad_41.msh"));
  EXPECT_EQ(m.elements.type.front(), ElementType::Q4);
  EXPECT_EQ(m.element_count(), 8 * 4);
  EXPECT_NEAR(total_measure(m), 2.0, 1e-12);
  EXPECT_EQ(m.element_set("5").size(), 32u);  // unnamed groups are named by their number
  EXPECT_EQ(m.boundary_set("7").size(), 4);
}

TEST(FemGmsh, ThreeDimensionalMeshes) {
  const Mesh tets = read_gmsh(data("box_41.msh"));
  EXPECT_EQ(tets.dim, 3);
  EXPECT_EQ(tets.elements.type.front(), ElementType::T4);
  EXPECT_NEAR(total_measure(tets), 2.0, 1e-12);
  for (int f = 0; f < tets.boundary_set("top").size(); ++f)
    EXPECT_NEAR(facet_normal(tets, tets.boundary_set("top"), f).z(), 1.0, 1e-12);
  for (int f = 0; f < tets.boundary_set("bottom").size(); ++f)
    EXPECT_NEAR(facet_normal(tets, tets.boundary_set("bottom"), f).z(), -1.0, 1e-12);
  EXPECT_EQ(tets.element_set("solid").size(), static_cast<std::size_t>(tets.element_count()));
  ASSERT_EQ(tets.node_set("corner").size(), 1u);
  // The same mesh through 2.2 binary.
  const Mesh bin = read_gmsh(data("box_22_bin.msh"));
  EXPECT_TRUE(bin.x.isApprox(tets.x, 1e-15));
  EXPECT_EQ(bin.elements.nodes, tets.elements.nodes);
  EXPECT_EQ(bin.boundary_set("top").cells.nodes, tets.boundary_set("top").cells.nodes);

  const Mesh hexes = read_gmsh(data("cube_hex_22.msh"));
  EXPECT_EQ(hexes.elements.type.front(), ElementType::H8);
  EXPECT_EQ(hexes.element_count(), 27);
  EXPECT_NEAR(total_measure(hexes), 1.0, 1e-12);
  EXPECT_EQ(hexes.boundary_set("xmin").size(), 9);
  for (int f = 0; f < 9; ++f) EXPECT_NEAR(facet_normal(hexes, hexes.boundary_set("xmin"), f).x(), -1.0, 1e-12);
}

TEST(FemGmsh, ClockwiseSurfacesAreTurned) {
  const Mesh m = read_gmsh(data("clockwise_22.msh"));
  for (int e = 0; e < m.element_count(); ++e) EXPECT_GT(element_measure(m, e), 0);
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_NE(m.notes[0].find("clockwise elements of"), std::string::npos);
  for (int f = 0; f < m.boundary_set("left").size(); ++f)
    EXPECT_NEAR(facet_normal(m, m.boundary_set("left"), f).x(), -1.0, 1e-14);
}

// ---- Errors --------------------------------------------------------------------------

std::string error_of(const std::string& content, long* line = nullptr, std::int64_t* element = nullptr) {
  try {
    parse_gmsh(content, "bad.msh");
  } catch (const MeshError& e) {
    if (line) *line = e.line();
    if (element) *element = e.element();
    EXPECT_EQ(e.file(), "bad.msh");
    return e.what();
  }
  return "no error";
}

const std::string head22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
const std::string nodes22 = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";

TEST(FemGmsh, MissingFile) {
  try {
    read_gmsh("/nonexistent/beam.msh");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/beam.msh: cannot open the mesh file (No such file or directory)");
    EXPECT_EQ(e.file(), "/nonexistent/beam.msh");
  }
}

TEST(FemGmsh, MalformedFilesNameTheLineAndWhatWasExpected) {
  long line = 0;
  EXPECT_EQ(error_of(head22 + "$Nodes\n2\n1 0 0 0\n2 1 abc 0\n$EndNodes\n", &line),
            "bad.msh:7: expected the y coordinate of node 2 (a number), found 'abc'");
  EXPECT_EQ(line, 7);
  EXPECT_EQ(error_of(head22 + "$Nodes\n3\n1 0 0 0\n"), "bad.msh:6: expected a node tag, but the file ends");
  EXPECT_EQ(error_of("hello\n"), "bad.msh:1: not a Gmsh mesh file: expected $MeshFormat first, found 'hello'");
  EXPECT_EQ(error_of(""), "bad.msh:1: not a Gmsh mesh file: it is empty");
  EXPECT_EQ(error_of("$MeshFormat\n4 0 8\n$EndMeshFormat\n"),
            "bad.msh:2: Gmsh format version 4 is not supported; save the mesh as version 4.1 or 2.2 (gmsh -format msh41 or msh22)");
  EXPECT_EQ(error_of(head22 + nodes22 + "$Elements\n1\n1 2 2 0 1 1 2\n$EndElements\n"),
            "bad.msh:14: expected node 3 of element 1 (a 3-node triangle) (an integer), found '$EndElements'");
  EXPECT_EQ(error_of(head22 + nodes22 + "$Elements\n1\n1 2 2 0 1 1 2 3\n"),
            "bad.msh:13: expected $EndElements, but the file ends");
  EXPECT_EQ(error_of(head22 + nodes22), "bad.msh:10: expected an $Elements section, but the file ends");
  EXPECT_EQ(error_of(head22 + nodes22 + "$Elements\n1\n1 77 2 0 1 1 2 3\n$EndElements\n"),
            "bad.msh:13: unknown Gmsh element type 77");
  EXPECT_EQ(error_of(head22 + nodes22 + "$Elements\n1\n1 2 2 0 1 1 2 9\n$EndElements\n"),
            "bad.msh:13: element 1 refers to node 9, which $Nodes does not define");
  EXPECT_EQ(error_of(head22 + "$Comments\nno end\n"), "bad.msh:4: expected $EndComments to close $Comments, but the file ends");
}

TEST(FemGmsh, UnsupportedElementTypesAreNamed) {
  std::int64_t element = 0;
  const std::string tri6 = head22 +
                           "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.5 0 0\n5 0.5 0.5 0\n6 0 0.5 0\n$EndNodes\n"
                           "$Elements\n1\n12 9 2 0 1 1 2 3 4 5 6\n$EndElements\n";
  EXPECT_EQ(error_of(tri6, nullptr, &element),
            "bad.msh:15: element 12 is a 6-node triangle (Gmsh type 9), which moreau does not support; supported 2D "
            "types: 2 (3-node triangle), 3 (4-node quadrangle)");
  EXPECT_EQ(element, 12);
  const std::string prism = head22 +
                            "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 0 1 1\n$EndNodes\n"
                            "$Elements\n1\n3 6 2 0 1 1 2 3 4 5 6\n$EndElements\n";
  EXPECT_NE(error_of(prism).find("element 3 is a 6-node prism (Gmsh type 6), which moreau does not support; supported 3D "
                                 "types: 4 (4-node tetrahedron), 5 (8-node hexahedron)"),
            std::string::npos);
}

TEST(FemGmsh, InvertedAndDegenerateElementsNameElementAndLine) {
  const std::string nodes = "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n";
  long line = 0;
  std::int64_t element = 0;
  // Tetrahedron 8 is positive; 9 has its apex below its base: inverted.
  const std::string inverted = head22 + nodes + "$Elements\n2\n8 4 2 0 1 1 2 3 4\n9 4 2 0 1 1 2 3 5\n$EndElements\n";
  EXPECT_EQ(error_of(inverted, &line, &element),
            "bad.msh: 1 inverted or degenerate element\n  element 9 (bad.msh:15) (T4) is inverted: Jacobian "
            "determinant -1 at integration point 1 of 4");
  EXPECT_EQ(line, 15);
  EXPECT_EQ(element, 9);
  const std::string flat = head22 + nodes + "$Elements\n1\n4 4 2 0 1 1 2 3 3\n$EndElements\n";
  EXPECT_NE(error_of(flat).find("element 4 (bad.msh:14) (T4) is degenerate: Jacobian determinant 0"), std::string::npos);
}

TEST(FemGmsh, OtherFaults) {
  // A 2D mesh out of its plane.
  const std::string warped = head22 + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0.5\n$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n";
  EXPECT_EQ(error_of(warped), "bad.msh:8: a 2D mesh must lie in a plane z = constant, but node 3 has z = 0.5 and node 1 z = 0");
  // A boundary element that is no face of the mesh.
  const std::string stray = head22 + nodes22 +
                            "$Elements\n2\n1 3 2 1 1 1 2 3 4\n2 1 2 2 1 1 3\n$EndElements\n";
  EXPECT_EQ(error_of(stray), "bad.msh:14: element 2 of boundary group '2' is not a face of any 2D element");
  // Only lines.
  EXPECT_EQ(error_of(head22 + nodes22 + "$Elements\n1\n1 1 2 0 1 1 2\n$EndElements\n"),
            "bad.msh: no 2D or 3D elements (the mesh has only points or lines)");
  // Truncated binary file.
  std::string binary = "$MeshFormat\n2.2 1 8\n";
  const int one = 1;
  binary.append(reinterpret_cast<const char*>(&one), 4);
  binary += "\n$EndMeshFormat\n$Nodes\n2\n";
  binary.append(reinterpret_cast<const char*>(&one), 4);
  binary.append(8, '\0');
  EXPECT_EQ(error_of(binary), "bad.msh (byte 61): expected a node coordinate (8 bytes), but the file ends");
  // Skipped sections are noted.
  const Mesh m = parse_gmsh(head22 + "$Comments\nhello\n$EndComments\n" + nodes22 +
                                "$Elements\n1\n1 3 2 0 1 1 2 3 4\n$EndElements\n",
                            "ok.msh");
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_EQ(m.notes[0], "skipped section $Comments of ok.msh");
}

}  // namespace
}  // namespace moreau::fem
