// Gmsh .msh reader, formats 2.2 and 4.1, ASCII and binary. Reference: the Gmsh manual,
// section "MSH file format" (4.1) and its "Legacy formats" appendix (2.2).
#include "gmsh_read.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>
#include <unordered_map>

#include "element_geometry.hpp"
#include "mesh_check.hpp"

namespace moreau::fem {
namespace {

// ---- Gmsh element types (those the reader can skip or name; only some become elements) --

struct GmshType {
  int number;
  const char* name;
  int dim;
  int nodes;
};

constexpr GmshType gmsh_types[] = {
    {1, "2-node line", 1, 2},          {2, "3-node triangle", 2, 3},        {3, "4-node quadrangle", 2, 4},
    {4, "4-node tetrahedron", 3, 4},   {5, "8-node hexahedron", 3, 8},      {6, "6-node prism", 3, 6},
    {7, "5-node pyramid", 3, 5},       {8, "3-node line", 1, 3},            {9, "6-node triangle", 2, 6},
    {10, "9-node quadrangle", 2, 9},   {11, "10-node tetrahedron", 3, 10},  {12, "27-node hexahedron", 3, 27},
    {13, "18-node prism", 3, 18},      {14, "14-node pyramid", 3, 14},      {15, "1-node point", 0, 1},
    {16, "8-node quadrangle", 2, 8},   {17, "20-node hexahedron", 3, 20},   {18, "15-node prism", 3, 15},
    {19, "13-node pyramid", 3, 13},    {20, "9-node triangle", 2, 9},       {21, "10-node triangle", 2, 10},
    {22, "12-node triangle", 2, 12},   {23, "15-node triangle", 2, 15},     {24, "15-node triangle", 2, 15},
    {25, "21-node triangle", 2, 21},   {26, "4-node line", 1, 4},           {27, "5-node line", 1, 5},
    {28, "6-node line", 1, 6},         {29, "20-node tetrahedron", 3, 20},  {30, "35-node tetrahedron", 3, 35},
    {31, "56-node tetrahedron", 3, 56}, {92, "64-node hexahedron", 3, 64},  {93, "125-node hexahedron", 3, 125},
};

const GmshType* find_gmsh_type(long number) {
  for (const GmshType& t : gmsh_types)
    if (t.number == number) return &t;
  return nullptr;
}

std::string supported_types(int dim) {
  std::string s;
  for (int t = 0; t < element_type_count; ++t) {
    const ElementInfo& info = element_info(static_cast<ElementType>(t));
    if (info.dim != dim) continue;
    if (!s.empty()) s += ", ";
    s += std::to_string(info.gmsh_type) + " (" + find_gmsh_type(info.gmsh_type)->name + ")";
  }
  return s;
}

// ---- Input: tokens with line numbers (ASCII) and raw values (binary) -----------------

class Input {
 public:
  Input(std::string_view text, std::string file) : s_(text), file_(std::move(file)) {}

  bool binary = false;
  bool swap = false;       // binary file of the other endianness
  int size_t_bytes = 8;    // data-size of $MeshFormat

  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }

  // `what` describes the expected value for a message: a string, or a function making one
  // (so a large file does not build a message per number it reads).
  template <class What>
  static std::string text(const What& what) {
    if constexpr (std::is_invocable_v<What>) return what();
    else return std::string(what);
  }

  template <class What>
  std::string_view token(const What& what) {
    skip_space();
    if (pos_ >= s_.size()) fail("expected " + text(what) + ", but the file ends");
    token_pos_ = pos_;
    token_line_ = line_;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    return s_.substr(start, pos_ - start);
  }

  template <class What>
  long long integer(const What& what) {
    const std::string_view t = token(what);
    long long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail_found("expected " + text(what) + " (an integer)", t);
    return v;
  }

  template <class What>
  long long count(const What& what) {
    const long long v = integer(what);
    if (v < 0 || v > 2'000'000'000) fail("expected " + text(what) + " (a count ≥ 0), found " + std::to_string(v));
    return v;
  }

  template <class What>
  double real(const What& what) {
    const std::string_view t = token(what);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail_found("expected " + text(what) + " (a number)", t);
    return v;
  }

  /// A double-quoted string (physical names may hold spaces).
  std::string quoted(const std::string& what) {
    skip_space();
    token_pos_ = pos_;
    token_line_ = line_;
    if (pos_ >= s_.size() || s_[pos_] != '"') fail_found("expected " + what + " in double quotes", peek());
    const std::size_t close = s_.find('"', pos_ + 1);
    const std::size_t eol = s_.find('\n', pos_ + 1);
    if (close == std::string_view::npos || close > eol) fail("expected the closing quote of " + what);
    std::string v(s_.substr(pos_ + 1, close - pos_ - 1));
    pos_ = close + 1;
    return v;
  }

  void keyword(std::string_view word) {
    const std::string_view t = token(std::string(word));
    if (t != word) fail_found("expected " + std::string(word), t);
  }

  /// Binary data starts after the newline that ends the current line.
  void start_binary() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\r' || s_[pos_] == '\t')) ++pos_;
    if (pos_ >= s_.size() || s_[pos_] != '\n') fail("expected the end of the line before binary data");
    ++pos_;
  }

  template <class T, class What>
  T raw(const What& what) {
    token_pos_ = pos_;
    if (s_.size() - pos_ < sizeof(T))
      fail("expected " + text(what) + " (" + std::to_string(sizeof(T)) + " bytes), but the file ends");
    T v;
    std::memcpy(&v, s_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if (swap) v = byteswap(v);
    return v;
  }
  template <class What>
  long long raw_int(const What& what) { return raw<std::int32_t>(what); }
  template <class What>
  long long raw_size(const What& what) {
    const long long v = size_t_bytes == 8 ? static_cast<long long>(raw<std::uint64_t>(what)) : raw<std::uint32_t>(what);
    if (v < 0 || v > 2'000'000'000LL * 64) fail("expected " + text(what) + ", found the implausible value " + std::to_string(v));
    return v;
  }
  template <class What>
  long long raw_count(const What& what) {
    const long long v = raw_size(what);
    if (v > 2'000'000'000) fail("expected " + text(what) + " (a count), found " + std::to_string(v));
    return v;
  }
  template <class What>
  double raw_real(const What& what) { return raw<double>(what); }

  // Values that are text in an ASCII file and raw in a binary one (4.1 sections).
  template <class What>
  long long any_count(const What& what) { return binary ? raw_count(what) : count(what); }  // size_t
  template <class What>
  long long any_size(const What& what) { return binary ? raw_size(what) : count(what); }  // size_t tag
  template <class What>
  long long any_int(const What& what) { return binary ? raw_int(what) : integer(what); }  // int
  template <class What>
  double any_real(const What& what) { return binary ? raw_real(what) : real(what); }

  /// Skips to the line "$End<name>" (an unknown section).
  void skip_section(const std::string& name) {
    const std::string end = "\n$End" + name;
    const std::size_t at = s_.find(end, pos_ == 0 ? 0 : pos_ - 1);
    if (at == std::string_view::npos) fail("expected $End" + name + " to close $" + name + ", but the file ends");
    for (std::size_t i = pos_; i < at + 1; ++i) line_ += s_[i] == '\n';
    pos_ = at + end.size();
  }

  long line() const { return binary ? 0 : token_line_; }
  std::string where() const {
    if (binary) return file_ + " (byte " + std::to_string(token_pos_) + ")";
    return file_ + ":" + std::to_string(token_line_);
  }
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& message) const { throw MeshError(where() + ": " + message, file_, line()); }
  [[noreturn]] void fail_found(const std::string& expected, std::string_view found) const {
    std::string f(found.substr(0, 40));
    if (binary)
      for (char& c : f)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    fail(expected + ", found '" + f + "'");
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
  void skip_space() {
    while (pos_ < s_.size() && is_space(s_[pos_])) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view peek() const {
    std::size_t e = pos_;
    while (e < s_.size() && !is_space(s_[e])) ++e;
    return s_.substr(pos_, e - pos_);
  }
  template <class T>
  static T byteswap(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    std::reverse(b, b + sizeof(T));
    std::memcpy(&v, b, sizeof(T));
    return v;
  }

  std::string_view s_;
  std::string file_;
  std::size_t pos_ = 0, token_pos_ = 0;
  long line_ = 1, token_line_ = 1;
};

// ---- What the file holds, before it becomes a Mesh ------------------------------------

struct RawElement {
  const GmshType* type;
  std::int64_t tag;
  int entity;          // elementary entity (geometric surface, volume…)
  long line;           // 0 in a binary file
  std::size_t first;   // its node tags: RawMesh::element_nodes[first, first + type->nodes)
};

struct RawMesh {
  double version = 0;
  std::map<std::pair<int, int>, std::string> physical_names;        // (dim, tag) → name
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;  // (dim, entity) → physical tags (4.1)
  std::vector<std::int64_t> node_tags;
  std::vector<double> coords;  // 3 per node
  std::vector<long> node_line;
  std::vector<RawElement> elements;
  std::vector<std::int64_t> element_nodes;
  std::vector<std::pair<std::size_t, int>> membership;  // (element, physical tag), 2.2
  bool have_nodes = false, have_elements = false;
  std::vector<std::string> notes;
};

void read_format(Input& in, RawMesh& raw) {
  const std::string_view version = in.token("the format version");
  if (version == "4.1") raw.version = 4.1;
  else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") raw.version = 2.2;
  else in.fail("Gmsh format version " + std::string(version) + " is not supported; save the mesh as version 4.1 or 2.2 (gmsh -format msh41 or msh22)");
  const long long file_type = in.integer("the file type (0 ASCII, 1 binary)");
  if (file_type != 0 && file_type != 1) in.fail("expected the file type 0 (ASCII) or 1 (binary), found " + std::to_string(file_type));
  const long long data_size = in.integer("the data size");
  if (file_type == 1) {
    if (data_size != 4 && data_size != 8) in.fail("expected the data size 4 or 8, found " + std::to_string(data_size));
    in.size_t_bytes = static_cast<int>(data_size);
    in.start_binary();
    in.binary = true;
    const std::int32_t one = in.raw<std::int32_t>("the endianness mark (the integer 1)");
    if (one != 1) {
      in.swap = true;
      const std::uint32_t u = static_cast<std::uint32_t>(one);
      const std::uint32_t swapped = (u >> 24) | ((u >> 8) & 0xff00u) | ((u << 8) & 0xff0000u) | (u << 24);
      if (swapped != 1) in.fail("expected the endianness mark (the integer 1) after the binary format line");
    }
  }
  in.keyword("$EndMeshFormat");
}

void read_physical_names(Input& in, RawMesh& raw) {
  const long long n = in.count("the number of physical names");
  for (long long i = 0; i < n; ++i) {
    const int dim = static_cast<int>(in.integer("the dimension of a physical group"));
    if (dim < 0 || dim > 3) in.fail("expected a physical group dimension 0 to 3, found " + std::to_string(dim));
    const int tag = static_cast<int>(in.integer("the tag of a physical group"));
    raw.physical_names[{dim, tag}] = in.quoted("the name of a physical group");
  }
  in.keyword("$EndPhysicalNames");
}

void read_entities(Input& in, RawMesh& raw) {
  long long counts[4];
  if (in.binary) in.start_binary();
  static const char* what[4] = {"the number of points", "the number of curves", "the number of surfaces", "the number of volumes"};
  for (int d = 0; d < 4; ++d) counts[d] = in.any_count(what[d]);
  for (int d = 0; d < 4; ++d)
    for (long long i = 0; i < counts[d]; ++i) {
      const int tag = static_cast<int>(in.any_int("an entity tag"));
      for (int k = 0; k < (d == 0 ? 3 : 6); ++k) in.any_real("an entity coordinate");
      const long long np = in.any_count("the number of physical tags");
      std::vector<int>& phys = raw.entity_physicals[{d, tag}];
      for (long long p = 0; p < np; ++p) phys.push_back(static_cast<int>(in.any_int("a physical tag")));
      if (d > 0) {
        const long long nb = in.any_count("the number of bounding entities");
        for (long long b = 0; b < nb; ++b) in.any_int("a bounding entity tag");
      }
    }
  in.keyword("$EndEntities");
}

void add_node(RawMesh& raw, std::int64_t tag, double x, double y, double z, long line) {
  raw.node_tags.push_back(tag);
  raw.coords.insert(raw.coords.end(), {x, y, z});
  raw.node_line.push_back(line);
}

void read_nodes_22(Input& in, RawMesh& raw) {
  const long long n = in.count("the number of nodes");
  if (in.binary) in.start_binary();
  raw.node_tags.reserve(n);
  raw.coords.reserve(3 * n);
  for (long long i = 0; i < n; ++i) {
    if (in.binary) {
      const long long tag = in.raw_int("a node tag");
      const double x = in.raw_real("a node coordinate"), y = in.raw_real("a node coordinate"), z = in.raw_real("a node coordinate");
      add_node(raw, tag, x, y, z, 0);
    } else {
      const long long tag = in.integer("a node tag");
      const long line = in.line();
      const double x = in.real([&] { return "the x coordinate of node " + std::to_string(tag); });
      const double y = in.real([&] { return "the y coordinate of node " + std::to_string(tag); });
      const double z = in.real([&] { return "the z coordinate of node " + std::to_string(tag); });
      add_node(raw, tag, x, y, z, line);
    }
  }
  in.keyword("$EndNodes");
}

/// The header of a 4.1 $Nodes or $Elements section: numbers of blocks and of items
/// (the smallest and largest tags that follow are not needed).
std::pair<long long, long long> read_block_header(Input& in, const std::string& item) {
  if (in.binary) in.start_binary();
  const long long blocks = in.any_count("the number of " + item + " blocks");
  const long long n = in.any_count("the number of " + item + "s");
  in.any_size("the smallest " + item + " tag");
  in.any_size("the largest " + item + " tag");
  return {blocks, n};
}

void read_nodes_41(Input& in, RawMesh& raw) {
  const auto [blocks, n] = read_block_header(in, "node");
  raw.node_tags.reserve(n);
  raw.coords.reserve(3 * n);
  std::vector<std::int64_t> tags;
  for (long long b = 0; b < blocks; ++b) {
    const long long dim = in.any_int("the entity dimension of a node block");
    in.any_int("the entity tag of a node block");
    const long long parametric = in.any_int("the parametric flag of a node block (0 or 1)");
    if (parametric != 0 && parametric != 1) in.fail("expected the parametric flag 0 or 1, found " + std::to_string(parametric));
    const long long count = in.any_count("the number of nodes in the block");
    tags.resize(count);
    for (auto& t : tags) t = in.any_size("a node tag");
    const int extra = parametric ? static_cast<int>(dim) : 0;
    for (long long i = 0; i < count; ++i) {
      double c[3];
      long line = 0;
      for (int k = 0; k < 3; ++k) {
        c[k] = in.any_real([&] { return std::string("the ") + "xyz"[k] + " coordinate of node " + std::to_string(tags[i]); });
        if (k == 0) line = in.line();
      }
      for (int k = 0; k < extra; ++k) in.any_real("a parametric coordinate");
      add_node(raw, tags[i], c[0], c[1], c[2], line);
    }
  }
  if (static_cast<long long>(raw.node_tags.size()) != n)
    in.fail("$Nodes announces " + std::to_string(n) + " nodes but its blocks hold " + std::to_string(raw.node_tags.size()));
  in.keyword("$EndNodes");
}

const GmshType* element_type(Input& in, long long number) {
  const GmshType* t = find_gmsh_type(number);
  if (!t) in.fail("unknown Gmsh element type " + std::to_string(number));
  return t;
}

void read_elements_22(Input& in, RawMesh& raw) {
  const long long n = in.count("the number of elements");
  raw.elements.reserve(n);
  if (in.binary) {
    in.start_binary();
    long long done = 0;
    while (done < n) {
      const GmshType* type = element_type(in, in.raw_int("the element type of a block"));
      const long long follow = in.raw_int("the number of elements in the block");
      const long long ntags = in.raw_int("the number of tags");
      if (follow <= 0 || follow > n - done || ntags < 0 || ntags > 100) in.fail("expected an element block header, found an implausible one");
      for (long long i = 0; i < follow; ++i) {
        RawElement e{type, in.raw_int("an element tag"), 0, 0, raw.element_nodes.size()};
        int physical = 0;
        for (long long t = 0; t < ntags; ++t) {
          const int v = in.raw_int("an element tag value");
          if (t == 0) physical = v;
          if (t == 1) e.entity = v;
        }
        for (int k = 0; k < type->nodes; ++k) raw.element_nodes.push_back(in.raw_int("an element node"));
        if (physical != 0) raw.membership.emplace_back(raw.elements.size(), physical);
        raw.elements.push_back(e);
      }
      done += follow;
    }
  } else {
    for (long long i = 0; i < n; ++i) {
      const long long tag = in.integer("an element tag");
      const long line = in.line();
      const GmshType* type = element_type(in, in.integer([&] { return "the type of element " + std::to_string(tag); }));
      const long long ntags = in.count([&] { return "the number of tags of element " + std::to_string(tag); });
      RawElement e{type, tag, 0, line, raw.element_nodes.size()};
      int physical = 0;
      for (long long t = 0; t < ntags; ++t) {
        const int v = static_cast<int>(in.integer([&] { return "a tag of element " + std::to_string(tag); }));
        if (t == 0) physical = v;
        if (t == 1) e.entity = v;
      }
      for (int k = 0; k < type->nodes; ++k)
        raw.element_nodes.push_back(in.integer([&] {
          return "node " + std::to_string(k + 1) + " of element " + std::to_string(tag) + " (a " + type->name + ")";
        }));
      if (physical != 0) raw.membership.emplace_back(raw.elements.size(), physical);
      raw.elements.push_back(e);
    }
  }
  in.keyword("$EndElements");
}

void read_elements_41(Input& in, RawMesh& raw) {
  const auto [blocks, n] = read_block_header(in, "element");
  raw.elements.reserve(n);
  for (long long b = 0; b < blocks; ++b) {
    const long long dim = in.any_int("the entity dimension of an element block");
    const long long entity = in.any_int("the entity tag of an element block");
    const GmshType* type = element_type(in, in.any_int("the element type of an element block"));
    if (type->dim != dim) in.fail("element block of dimension " + std::to_string(dim) + " holds " + type->name + " elements");
    const long long count = in.any_count("the number of elements in the block");
    for (long long i = 0; i < count; ++i) {
      const long long tag = in.any_size("an element tag");
      RawElement e{type, tag, static_cast<int>(entity), in.line(), raw.element_nodes.size()};
      for (int k = 0; k < type->nodes; ++k)
        raw.element_nodes.push_back(in.any_size([&] {
          return "node " + std::to_string(k + 1) + " of element " + std::to_string(tag) + " (a " + type->name + ")";
        }));
      raw.elements.push_back(e);
    }
  }
  if (static_cast<long long>(raw.elements.size()) != n)
    in.fail("$Elements announces " + std::to_string(n) + " elements but its blocks hold " + std::to_string(raw.elements.size()));
  in.keyword("$EndElements");
}

RawMesh read_raw(Input& in) {
  RawMesh raw;
  bool format = false;
  while (!in.at_end()) {
    const std::string_view t = in.token("a section");
    if (!format && t != "$MeshFormat") in.fail_found("not a Gmsh mesh file: expected $MeshFormat first", t);
    if (t.empty() || t[0] != '$') in.fail_found("expected a section such as $Nodes or $Elements", t);
    const std::string name(t.substr(1));
    if (name == "MeshFormat") {
      if (format) in.fail("a second $MeshFormat section");
      read_format(in, raw);
      format = true;
    } else if (name == "PhysicalNames") {
      read_physical_names(in, raw);
    } else if (name == "Entities" && raw.version > 4) {
      read_entities(in, raw);
    } else if (name == "Nodes") {
      if (raw.have_nodes) in.fail("a second $Nodes section");
      raw.version > 4 ? read_nodes_41(in, raw) : read_nodes_22(in, raw);
      raw.have_nodes = true;
    } else if (name == "Elements") {
      if (raw.have_elements) in.fail("a second $Elements section");
      raw.version > 4 ? read_elements_41(in, raw) : read_elements_22(in, raw);
      raw.have_elements = true;
    } else if (name == "PartitionedEntities") {
      in.fail("partitioned meshes are not supported; save the mesh without partitions");
    } else if (name.starts_with("End")) {
      in.fail_found("expected a section, found its end without its start", t);
    } else {
      in.skip_section(name);
      raw.notes.push_back("skipped section $" + name + " of " + in.file());
    }
  }
  if (!format) in.fail("not a Gmsh mesh file: it is empty");
  if (!raw.have_nodes) in.fail("expected a $Nodes section, but the file ends");
  if (!raw.have_elements) in.fail("expected an $Elements section, but the file ends");
  return raw;
}

// ---- From the file's contents to a Mesh -------------------------------------------------

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string where(const std::string& file, long line) { return line > 0 ? file + ":" + std::to_string(line) : file; }

/// In 2D, turns counter-clockwise the elements of each geometric surface whose elements
/// are all clockwise (negative Jacobian at every integration point).
void orient_surfaces(Mesh& mesh, const std::vector<int>& entity) {
  std::map<int, std::pair<int, int>> counts;  // entity → (clockwise, total)
  detail::ElementGeometry g;
  for (int e = 0; e < mesh.element_count(); ++e) {
    g.bind(mesh, e);
    bool all_negative = true;
    for (const QuadraturePoint& q : element_info(g.type).rule) all_negative &= g.evaluate(q.xi.data()) < 0;
    auto& c = counts[entity[e]];
    c.first += all_negative;
    ++c.second;
  }
  int turned = 0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& c = counts[entity[e]];
    if (c.first != c.second) continue;
    reverse_orientation(mesh.elements.type[e], mesh.elements.at(e));
    ++turned;
  }
  if (turned > 0)
    mesh.notes.push_back(std::to_string(turned) + " clockwise elements of " + mesh.source +
                         " turned counter-clockwise (surfaces meshed with normal −z)");
}

Mesh build(const RawMesh& raw, const std::string& file) {
  Mesh mesh;
  mesh.source = file;
  mesh.from_file = true;
  mesh.notes = raw.notes;
  int dim = 0;
  for (const RawElement& e : raw.elements) dim = std::max(dim, e.type->dim);
  if (dim < 2) throw MeshError(file + ": no 2D or 3D elements (the mesh has only points or lines)", file);
  mesh.dim = dim;

  // Nodes: tag → position in $Nodes.
  std::unordered_map<std::int64_t, int> node_index;
  node_index.reserve(raw.node_tags.size());
  for (std::size_t i = 0; i < raw.node_tags.size(); ++i)
    if (!node_index.emplace(raw.node_tags[i], static_cast<int>(i)).second)
      throw MeshError(where(file, raw.node_line[i]) + ": node " + std::to_string(raw.node_tags[i]) + " is defined twice",
                      file, raw.node_line[i]);
  const auto raw_node = [&](const RawElement& e, int k) {
    const std::int64_t tag = raw.element_nodes[e.first + k];
    const auto it = node_index.find(tag);
    if (it == node_index.end())
      throw MeshError(where(file, e.line) + ": element " + std::to_string(e.tag) + " refers to node " + std::to_string(tag) +
                          ", which $Nodes does not define",
                      file, e.line, e.tag);
    return it->second;
  };

  // Elements of the mesh dimension. A 2.2 file repeats an element once per physical group
  // (under a new number): elements with the same nodes are one element, in every group.
  std::vector<int> compact(raw.node_tags.size(), -1);  // $Nodes position → mesh node
  std::vector<int> order;                              // mesh node → $Nodes position
  using NodeKey = std::array<int, 8>;
  struct KeyHash {
    std::size_t operator()(const NodeKey& k) const {
      std::size_t h = 0;
      for (int v : k) h = h * 0x9E3779B97F4A7C15ull + static_cast<std::size_t>(v);
      return h;
    }
  };
  std::unordered_map<NodeKey, int, KeyHash> element_of_nodes;
  std::vector<int> mesh_element(raw.elements.size(), -1);
  std::vector<int> entity;
  std::vector<int> nodes(128);  // the largest Gmsh element has 125 nodes
  for (std::size_t r = 0; r < raw.elements.size(); ++r) {
    const RawElement& e = raw.elements[r];
    if (e.type->dim != dim) continue;
    ElementType type;
    if (!element_type_from_gmsh(e.type->number, type) || element_info(type).dim != dim)
      throw MeshError(where(file, e.line) + ": element " + std::to_string(e.tag) + " is a " + e.type->name +
                          " (Gmsh type " + std::to_string(e.type->number) + "), which moreau does not support; supported " +
                          std::to_string(dim) + "D types: " + supported_types(dim),
                      file, e.line, e.tag);
    const int n = e.type->nodes;
    NodeKey key;
    key.fill(-1);
    for (int k = 0; k < n; ++k) {  // the key: the node positions, sorted (insertion, n ≤ 8)
      nodes[k] = raw_node(e, k);
      int j = k;
      for (; j > 0 && key[j - 1] > nodes[k]; --j) key[j] = key[j - 1];
      key[j] = nodes[k];
    }
    const auto [it, inserted] = element_of_nodes.emplace(key, mesh.elements.size());
    if (!inserted) {
      mesh_element[r] = it->second;
      continue;
    }
    for (int k = 0; k < n; ++k) {
      int& c = compact[nodes[k]];
      if (c < 0) {
        c = static_cast<int>(order.size());
        order.push_back(nodes[k]);
      }
      nodes[k] = c;
    }
    mesh_element[r] = mesh.elements.size();
    mesh.elements.add(type, std::span<const int>(nodes.data(), n));
    mesh.element_number.push_back(e.tag);
    mesh.element_line.push_back(e.line);
    entity.push_back(e.entity);
  }
  // Mesh nodes in $Nodes order, so the numbering follows the file.
  {
    std::vector<int> by_file = order;
    std::sort(by_file.begin(), by_file.end());
    for (std::size_t i = 0; i < by_file.size(); ++i) compact[by_file[i]] = static_cast<int>(i);
    for (int& v : mesh.elements.nodes) v = compact[order[v]];
    order = std::move(by_file);
  }
  mesh.x.resize(dim, static_cast<Eigen::Index>(order.size()));
  mesh.node_number.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (int k = 0; k < dim; ++k) mesh.x(k, static_cast<Eigen::Index>(i)) = raw.coords[3 * order[i] + k];
    mesh.node_number[i] = raw.node_tags[order[i]];
  }
  if (dim == 2 && !order.empty()) {
    const double z0 = raw.coords[3 * order[0] + 2];
    const double extent = (mesh.x.rowwise().maxCoeff() - mesh.x.rowwise().minCoeff()).maxCoeff();
    for (std::size_t i = 0; i < order.size(); ++i)
      if (std::abs(raw.coords[3 * order[i] + 2] - z0) > 1e-9 * extent) {
        const long line = raw.node_line[order[i]];
        throw MeshError(where(file, line) + ": a 2D mesh must lie in a plane z = constant, but node " +
                            std::to_string(raw.node_tags[order[i]]) + " has z = " + number(raw.coords[3 * order[i] + 2]) +
                            " and node " + std::to_string(raw.node_tags[order[0]]) + " z = " + number(z0),
                        file, line);
      }
  }
  if (dim == 2) orient_surfaces(mesh, entity);

  // Physical groups.
  const auto group_name = [&](int gdim, int tag) {
    const auto it = raw.physical_names.find({gdim, tag});
    return it != raw.physical_names.end() ? it->second : std::to_string(tag);
  };
  std::vector<std::pair<std::size_t, int>> membership = raw.membership;
  if (raw.version > 4)
    for (std::size_t r = 0; r < raw.elements.size(); ++r) {
      const auto it = raw.entity_physicals.find({raw.elements[r].type->dim, raw.elements[r].entity});
      if (it == raw.entity_physicals.end()) continue;
      for (int p : it->second) membership.emplace_back(r, p);
    }
  std::map<std::string, Cells> faces;
  std::map<std::string, std::vector<std::size_t>> face_source;  // raw element of each face
  std::set<std::string> groups;
  for (const auto& [r, tag] : membership) {
    const RawElement& e = raw.elements[r];
    const std::string name = group_name(e.type->dim, tag);
    groups.insert(name);
    std::vector<int>& node_set = mesh.node_sets[name];
    if (e.type->dim == dim) {
      mesh.element_sets[name].push_back(mesh_element[r]);
      for (int v : mesh.elements[mesh_element[r]]) node_set.push_back(v);
      continue;
    }
    for (int k = 0; k < e.type->nodes; ++k) {
      const int c = compact[raw_node(e, k)];
      if (c < 0)
        throw MeshError(where(file, e.line) + ": element " + std::to_string(e.tag) + " of physical group '" + name +
                            "' has node " + std::to_string(raw.element_nodes[e.first + k]) + ", which belongs to no " +
                            std::to_string(dim) + "D element",
                        file, e.line, e.tag);
      nodes[k] = c;
      node_set.push_back(c);
    }
    if (e.type->dim != dim - 1) continue;
    ElementType type;
    if (!element_type_from_gmsh(e.type->number, type) || element_info(type).dim != dim - 1)
      throw MeshError(where(file, e.line) + ": element " + std::to_string(e.tag) + " of boundary group '" + name + "' is a " +
                          e.type->name + ", which moreau does not support as a boundary; supported: " + supported_types(dim - 1),
                      file, e.line, e.tag);
    faces[name].add(type, std::span<const int>(nodes.data(), e.type->nodes));
    face_source[name].push_back(r);
  }
  for (auto& [group, cells] : faces) {
    const std::string& name = group;  // clang 14 cannot capture a structured binding
    const auto& source = face_source[name];
    mesh.boundary_sets[name] = match_facets(mesh, cells, [&](int f) {
      const RawElement& e = raw.elements[source[f]];
      return MeshError(where(file, e.line) + ": element " + std::to_string(e.tag) + " of boundary group '" + name +
                           "' is not a face of any " + std::to_string(dim) + "D element",
                       file, e.line, e.tag);
    });
  }
  for (auto& [name, set] : mesh.node_sets) {
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  for (auto& [name, set] : mesh.element_sets) {
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  if (!groups.contains("all")) {
    std::vector<int> all(mesh.element_count());
    for (int e = 0; e < mesh.element_count(); ++e) all[e] = e;
    mesh.element_sets["all"] = std::move(all);
  }
  if (!groups.contains("boundary")) {
    mesh.boundary_sets["boundary"] = boundary_facets(mesh);
    mesh.node_sets["boundary"] = facet_nodes(mesh.boundary_sets["boundary"]);
  }
  return mesh;
}

}  // namespace

Mesh parse_gmsh(std::string_view content, const std::string& name) {
  Input in(content, name);
  const RawMesh raw = read_raw(in);
  Mesh mesh = build(raw, name);
  check_mesh(mesh);
  return mesh;
}

Mesh read_gmsh(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw MeshError(path + ": cannot open the mesh file (" + std::strerror(errno) + ")", path);
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) throw MeshError(path + ": cannot read the mesh file", path);
  return parse_gmsh(content.str(), path);
}

}  // namespace moreau::fem
