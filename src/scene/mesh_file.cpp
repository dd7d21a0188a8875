#include "penumbra/scene/mesh_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include "penumbra/base/input_error.h"
#include "penumbra/geometry/geometry_error.h"

namespace penumbra {
namespace {

class LineReader {
 public:
  explicit LineReader(const std::filesystem::path& path) : path_(path), in_(path) {
    if (!in_) throw InputError(path.string(), "", "cannot open the mesh file");
  }

  // reads the next line that is not blank or a comment; false at the end.
  bool next(std::istringstream& fields) {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.erase(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      fields.clear();
      fields.str(line);
      return true;
    }
    return false;
  }

  int line() const { return number_; }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(path_.string(), "line " + std::to_string(number_), message);
  }

  double number(std::istringstream& fields, const char* what) {
    std::string token;
    if (!(fields >> token)) fail(std::string("missing ") + what);
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0')
      fail(std::string("expected a number for ") + what + ", found \"" + token + "\"");
    if (!std::isfinite(x)) fail(std::string("the ") + what + " is not finite");
    return x;
  }

  long integer(std::istringstream& fields, const char* what) {
    std::string token;
    if (!(fields >> token)) fail(std::string("missing ") + what);
    char* end = nullptr;
    const long x = std::strtol(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0')
      fail(std::string("expected an integer for ") + what + ", found \"" + token + "\"");
    return x;
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  int number_ = 0;
};

Point3 read_point(LineReader& reader, std::istringstream& fields) {
  const double x = reader.number(fields, "x coordinate");
  const double y = reader.number(fields, "y coordinate");
  const double z = reader.number(fields, "z coordinate");
  return Point3(x, y, z);
}

void check_face(LineReader& reader, const std::vector<int>& face, std::size_t vertex_count) {
  if (face.size() < 3) reader.fail("a face needs at least 3 vertices");
  for (int index : face)
    if (index < 0 || static_cast<std::size_t>(index) >= vertex_count)
      reader.fail("vertex index " + std::to_string(index + 1) + " is out of range");
}

MeshFile read_obj(const std::filesystem::path& path) {
  MeshFile mesh{path, {}, {}, {}};
  LineReader reader(path);
  std::istringstream fields;
  while (reader.next(fields)) {
    std::string tag;
    fields >> tag;
    if (tag == "v") {
      mesh.vertices.push_back(read_point(reader, fields));
    } else if (tag == "f") {
      // Each corner is v, v/vt, v//vn or v/vt/vn; negative indices count back.
      std::vector<int> face;
      std::string corner;
      while (fields >> corner) {
        char* end = nullptr;
        const long index = std::strtol(corner.c_str(), &end, 10);
        if (end == corner.c_str() || (*end != '\0' && *end != '/') || index == 0)
          reader.fail("bad face corner \"" + corner + "\"");
        face.push_back(static_cast<int>(
            index > 0 ? index - 1 : static_cast<long>(mesh.vertices.size()) + index));
      }
      check_face(reader, face, mesh.vertices.size());
      mesh.faces.push_back(face);
      mesh.face_lines.push_back(reader.line());
    }
    // Texture coordinates, normals, groups and materials do not shape the solid.
  }
  return mesh;
}

MeshFile read_off(const std::filesystem::path& path) {
  MeshFile mesh{path, {}, {}, {}};
  LineReader reader(path);
  std::istringstream fields;
  if (!reader.next(fields)) reader.fail("empty file: expected the OFF header");
  std::string header;
  fields >> header;
  if (header != "OFF") reader.fail("expected the OFF header, found \"" + header + "\"");
  // The counts may follow the header on its line or come on the next one.
  fields >> std::ws;
  if (fields.eof() && !reader.next(fields)) reader.fail("missing the vertex, face and edge counts");
  const long vertex_count = reader.integer(fields, "vertex count");
  const long face_count = reader.integer(fields, "face count");
  if (vertex_count < 0 || face_count < 0) reader.fail("counts must not be negative");
  for (long i = 0; i < vertex_count; ++i) {
    if (!reader.next(fields)) reader.fail("the file ends before vertex " + std::to_string(i));
    mesh.vertices.push_back(read_point(reader, fields));
  }
  for (long i = 0; i < face_count; ++i) {
    if (!reader.next(fields)) reader.fail("the file ends before face " + std::to_string(i));
    const long n = reader.integer(fields, "face size");
    if (n < 3) reader.fail("a face needs at least 3 vertices");
    std::vector<int> face;
    for (long k = 0; k < n; ++k)
      face.push_back(static_cast<int>(reader.integer(fields, "vertex index")));
    check_face(reader, face, mesh.vertices.size());
    mesh.faces.push_back(face);
    mesh.face_lines.push_back(reader.line());
  }
  return mesh;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

MeshFile read_mesh(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return read_obj(path);
  if (extension == ".off") return read_off(path);
  throw InputError(path.string(), "",
                   "unknown mesh format \"" + extension + "\" (expected .obj or .off)");
}

std::vector<ConvexPolyhedron> convex_parts(const MeshFile& mesh) {
  // Components: faces that share a vertex, joined with union-find.
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& face : mesh.faces)
    for (int index : face) parent[find_root(parent, index)] = find_root(parent, face.front());

  struct Component {
    std::vector<Point3> points;
    std::vector<std::size_t> faces;
  };
  std::vector<Component> components(mesh.vertices.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    Component& component = components[find_root(parent, mesh.faces[f].front())];
    component.faces.push_back(f);
    for (int index : mesh.faces[f])
      if (!used[index]) {
        used[index] = true;
        component.points.push_back(mesh.vertices[index]);
      }
  }

  std::vector<ConvexPolyhedron> parts;
  for (Component& component : components) {
    if (component.faces.empty()) continue;
    const auto fail = [&](std::size_t face, const std::string& message) {
      throw InputError(mesh.path.string(), "line " + std::to_string(mesh.face_lines[face]),
                       message);
    };
    ConvexPolyhedron solid;
    try {
      solid = ConvexPolyhedron::hull(component.points);
    } catch (const GeometryError& e) {
      fail(component.faces.front(), std::string("the component of this face is flat: ") + e.what());
    }
    // Exact convexity: each mesh face must lie in the plane of a face of the hull.
    for (std::size_t f : component.faces) {
      const auto& corners = mesh.faces[f];
      const bool on_hull =
          std::any_of(solid.faces().begin(), solid.faces().end(), [&](const Face& face) {
            return std::all_of(corners.begin(), corners.end(),
                               [&](int index) { return face.plane.has_on(mesh.vertices[index]); });
          });
      if (!on_hull)
        fail(f,
             "the mesh component of this face is not convex (the face is not on its convex hull)");
    }
    parts.push_back(std::move(solid));
  }
  // Canonical order: lexicographic over the parts' sorted vertex lists.
  std::sort(parts.begin(), parts.end(), [](const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
    return std::lexicographical_compare(
        a.vertices().begin(), a.vertices().end(), b.vertices().begin(), b.vertices().end(),
        [](const Point3& p, const Point3& q) { return CGAL::compare_xyz(p, q) == CGAL::SMALLER; });
  });
  return parts;
}

}  // namespace penumbra
