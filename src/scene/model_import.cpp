#include "penumbra/scene/model_import.h"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "planar_faces.h"

namespace penumbra {

RepairReport& RepairReport::operator+=(const RepairReport& other) {
  snapped_coordinates_changed += other.snapped_coordinates_changed;
  duplicate_vertices_merged += other.duplicate_vertices_merged;
  degenerate_faces_dropped += other.degenerate_faces_dropped;
  non_surface_primitives_ignored += other.non_surface_primitives_ignored;
  components_reoriented += other.components_reoriented;
  closed_components += other.closed_components;
  open_components += other.open_components;
  non_manifold_edges += other.non_manifold_edges;
  overlapping_faces += other.overlapping_faces;
  return *this;
}

namespace {

// === Exact affine maps

// An affine map of space as the rows of [A | t], exact.
using Affine = std::array<Rational, 12>;

Affine identity_map() {
  Affine m;
  for (auto& x : m) x = 0;
  m[0] = m[5] = m[10] = 1;
  return m;
}

bool is_identity(const Affine& m) {
  return m == identity_map();
}

// returns a after b (a b x).
Affine compose(const Affine& a, const Affine& b) {
  Affine m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      m[4 * i + j] = a[4 * i] * b[j] + a[4 * i + 1] * b[4 + j] + a[4 * i + 2] * b[8 + j];
      if (j == 3) m[4 * i + j] += a[4 * i + 3];
    }
  return m;
}

Rational determinant(const Affine& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}

std::array<Rational, 3> map_point(const Affine& m, const std::array<Rational, 3>& p) {
  std::array<Rational, 3> q;
  for (int i = 0; i < 3; ++i)
    q[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
  return q;
}

// returns the exact map of a row-major 4 x 4 matrix of finite numbers whose last row is
// (0, 0, 0, 1); nothing otherwise.
template <class Number>
std::optional<Affine> affine_map(const Number* rows) {
  for (int k = 0; k < 16; ++k)
    if (!std::isfinite(static_cast<double>(rows[k]))) return std::nullopt;
  if (rows[12] != 0 || rows[13] != 0 || rows[14] != 0 || rows[15] != 1) return std::nullopt;
  Affine m;
  for (int k = 0; k < 12; ++k) m[k] = Rational(static_cast<double>(rows[k]));
  return m;
}

// === Placement

// The file's coordinates (after its node transforms) to world coordinates: scale, snap,
// up-axis turn, transform (docs/scene-format.md, "Placement").
class Placer {
 public:
  Placer(const Placement& placement, const std::string& file)
      : scale_{placement.scale, Rational(placement.scale)},
        snap_{grid_step(placement.snap), Rational(grid_step(placement.snap))},
        y_up_(placement.y_up) {
    const auto fail = [&](const std::string& message) {
      throw InputError(file, "placement", message);
    };
    if (!std::isfinite(placement.scale) || placement.scale <= 0)
      fail("the scale must be finite and positive");
    if (!std::isfinite(placement.snap) || placement.snap < 0)
      fail("the snap grid must be finite and not negative");
    if (placement.transform) {
      transform_ = affine_map(placement.transform->data());
      if (!transform_) fail("the transform must be finite with last row (0, 0, 0, 1)");
      const Rational det = determinant(*transform_);
      if (CGAL::is_zero(det)) fail("the transform is singular");
      mirrors_ = CGAL::is_negative(det);
    }
  }

  // true when the placement reverses orientation (so windings must be reversed).
  bool mirrors() const { return mirrors_; }

  // returns the world point of a point of the file, counting the coordinates snapped.
  RationalPoint3 place(std::array<Rational, 3> p, std::size_t& snapped) const {
    if (scale_.value != 1)
      for (auto& x : p) x *= scale_.exact;
    if (snap_.value > 0)
      for (auto& x : p) {
        Rational rounded = to_grid(x);
        if (rounded != x) {
          ++snapped;
          x = std::move(rounded);
        }
      }
    if (y_up_) {  // (x, y, z) -> (x, -z, y)
      std::swap(p[1], p[2]);
      p[1] = -p[1];
    }
    if (transform_) p = map_point(*transform_, p);
    return RationalPoint3(p[0], p[1], p[2]);
  }

 private:
  struct Number {
    double value;
    Rational exact;
  };

  // returns the largest power of two not above snap (0 for 0): the grid step.
  static double grid_step(double snap) {
    if (!(snap > 0) || !std::isfinite(snap)) return snap;
    int exponent = 0;
    std::frexp(snap, &exponent);  // snap = f 2^exponent, 1/2 <= f < 1
    return std::ldexp(1.0, exponent - 1);
  }

  // returns the multiple of the snap grid nearest x, ties away from zero. A double x is
  // rounded in doubles (the step is a power of two, so x / step and k step are exact).
  // Otherwise the double estimate of x / step is within 1/32 of the true quotient below
  // 2^46, so one exact correction step finds the nearest multiple.
  Rational to_grid(const Rational& x) const {
    double value = 0;
    if (exact_double(x, value)) {
      const double k = std::round(value / snap_.value);
      if (!(std::abs(k) < 0x1p46))
        throw std::range_error("a coordinate is too large for the snap grid");
      return Rational(k * snap_.value);
    }
    const double estimate = CGAL::to_double(x) / snap_.value;
    if (!(std::abs(estimate) < 0x1p46))
      throw std::range_error("a coordinate is too large for the snap grid");
    const double k0 = std::round(estimate);
    Rational k(k0);
    const Rational twice = Rational(2) * (x - k * snap_.exact);
    if (twice > snap_.exact || (twice == snap_.exact && k0 >= 0))
      k += 1;
    else if (twice < -snap_.exact || (twice == -snap_.exact && k0 <= 0))
      k -= 1;
    return k * snap_.exact;
  }

  Number scale_;
  Number snap_;
  bool y_up_;
  std::optional<Affine> transform_;
  bool mirrors_ = false;
};

// hashes a point of the file by its coordinates' values (0 and -0 alike).
struct FloatTripleHash {
  std::size_t operator()(const std::array<ai_real, 3>& p) const {
    const std::hash<ai_real> hash;
    return (hash(p[0]) * 1000003u ^ hash(p[1])) * 1000003u ^ hash(p[2]);
  }
};

// === Names

// returns the name unless it is empty or one Assimp makes up ("<STL_BINARY>", "<OFFRoot>").
std::string usable_name(const aiString& name) {
  std::string text(name.C_Str());
  if (text.empty() || (text.front() == '<' && text.back() == '>')) return {};
  return text;
}

struct PartSource {
  const aiNode* node;
  Affine world;  // the file's node transforms, root to this node
  std::string name;
  std::string parent_name;
};

void collect_parts(const aiScene& scene, const aiNode& node, const Affine& parent,
                   const std::string& parent_name, const std::string& file,
                   std::vector<PartSource>& parts) {
  const std::string name = usable_name(node.mName);
  const auto local = affine_map(&node.mTransformation.a1);
  if (!local)
    throw InputError(file, "node " + (name.empty() ? std::string("(unnamed)") : name),
                     "the node transform is not finite or not affine");
  const Affine world = compose(parent, *local);
  if (node.mNumMeshes > 0) {
    std::string base = name;
    if (base.empty() && node.mNumMeshes == 1)
      base = usable_name(scene.mMeshes[node.mMeshes[0]]->mName);
    if (base.empty()) base = "part";
    parts.push_back({&node, world, base, parent_name});
  }
  for (unsigned k = 0; k < node.mNumChildren; ++k)
    collect_parts(scene, *node.mChildren[k], world, name.empty() ? parent_name : name, file, parts);
}

// gives an OBJ file's parts their whole names: Assimp's OBJ reader ends an object's name at
// its first space ("o Left Wing" becomes "Left"), and merges objects whose names share that
// first word into one part. The file's `o` lines are read here: a part named by the first
// word of exactly one whole name takes it; a part several whole names begin with keeps the
// word (its objects were merged).
void whole_obj_names(const std::filesystem::path& path, std::vector<PartSource>& parts) {
  std::map<std::string, std::set<std::string>> whole_names;  // first word -> whole names
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] != 'o') continue;  // most lines: v, f
    std::istringstream fields(line);
    std::string keyword, first, name;
    if (!(fields >> keyword) || keyword != "o" || !(fields >> first)) continue;
    std::getline(fields, name);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    whole_names[first].insert(first + name);
  }
  for (auto& part : parts) {
    const auto found = whole_names.find(part.name);
    if (found != whole_names.end() && found->second.size() == 1) part.name = *found->second.begin();
  }
}

// checks a PLY file's header before Assimp reads it: "ply", then only the header's keywords
// (format, comment, obj_info, element, property) up to "end_header". Debian's Assimp 5.2.4
// reads a header with any other line forever (found by fuzzing,
// tests/fuzz/regressions/model/ply-unknown-header-line.bin); a real
// header is a few hundred bytes, so one without end_header in its first megabyte is refused.
void check_ply_header(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t bytes = 0;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    bytes += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string keyword = line.substr(0, line.find(' '));
    if (number == 1 ? line != "ply"
                    : keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
                          keyword != "element" && keyword != "property" && line != "end_header")
      throw InputError(file, "line " + std::to_string(number),
                       number == 1 ? "not a PLY file: the first line must be \"ply\""
                                   : "not a PLY header line (format, comment, obj_info, element, "
                                     "property or end_header expected)");
    if (line == "end_header") return;
    if (bytes > (1u << 20)) break;
  }
  throw InputError(file, "", "a PLY header without end_header in its first megabyte");
}

// makes the part names unique: parts sharing a name whose parents have distinct names
// are qualified by them ("IfcWindow-1/IfcMappedItem"); others sharing a name are numbered
// #0, #1, ... in file order.
void unique_names(std::vector<PartSource>& parts) {
  std::map<std::string, std::vector<PartSource*>> by_name;
  for (auto& part : parts) by_name[part.name].push_back(&part);
  for (auto& [name, group] : by_name) {
    if (group.size() < 2) continue;
    std::map<std::string, int> parents;
    for (const PartSource* part : group) ++parents[part->parent_name];
    if (parents.size() == group.size() && !parents.count(""))
      for (PartSource* part : group) part->name = part->parent_name + "/" + name;
  }
  std::map<std::string, int> count;
  for (const auto& part : parts) ++count[part.name];
  std::map<std::string, int> next;
  for (auto& part : parts)
    if (count[part.name] > 1) {
      const std::string base = part.name;
      part.name = base + "#" + std::to_string(next[base]++);
    }
}

// === Materials

std::vector<ModelMaterial> materials(const aiScene& scene) {
  std::vector<ModelMaterial> result;
  for (unsigned k = 0; k < scene.mNumMaterials; ++k) {
    const aiMaterial& material = *scene.mMaterials[k];
    ModelMaterial entry;
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) entry.name = name.C_Str();
    // Assimp's stand-in material for files without any carries a made-up grey.
    aiColor3D colour;
    if (entry.name != AI_DEFAULT_MATERIAL_NAME && !usable_name(name).empty() &&
        material.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS && std::isfinite(colour.r) &&
        std::isfinite(colour.g) && std::isfinite(colour.b))
      entry.colour = std::array<double, 3>{colour.r, colour.g, colour.b};
    result.push_back(std::move(entry));
  }
  return result;
}

// === Files

std::string lower(std::string text) {
  for (auto& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

const aiScene* read_scene(Assimp::Importer& importer, const std::filesystem::path& path) {
  const std::string file = path.string();
  check_input_file(path, "model file", file_limits::model);
  if (!std::ifstream(path, std::ios::binary))
    throw InputError(file, "", "cannot open the model file: it cannot be read");
  const std::string extension = lower(path.extension().string());
  if (extension.empty() || !importer.IsExtensionSupported(extension))
    throw InputError(file, "",
                     "unsupported model format \"" + extension +
                         "\" (Assimp reads OBJ, STL, PLY, OFF, glTF, GLB, IFC, 3DS, DAE, FBX, "
                         "...; docs/scene-format.md)");
  // No post-processing step that moves vertices: JoinIdenticalVertices merges within a few
  // ulps; equal points are merged exactly after snapping instead (planar_faces.cpp).
  if (extension == ".ply") check_ply_header(path);
  const aiScene* scene =
      importer.ReadFile(file, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode)
    throw InputError(file, "",
                     std::string("Assimp cannot read the model: ") + importer.GetErrorString());
  return scene;
}

// returns the part of one node: its meshes' triangles placed, repaired and merged into
// planar faces (none when the node has only points and lines).
ModelPart import_part(const aiScene& scene, const PartSource& source, const Placer& placer,
                      const std::string& file, double snap) {
  const std::string location = "part " + source.name;
  ModelPart part;
  part.name = source.name;
  TriangleSoup soup;
  const bool identity = is_identity(source.world);
  const bool mirrored = placer.mirrors() != CGAL::is_negative(determinant(source.world));
  std::size_t triangles = 0;
  // The file's points, each placed once: formats that repeat a point per face (STL, OBJ
  // through Assimp) give the same coordinates several times.
  std::unordered_map<std::array<ai_real, 3>, int, FloatTripleHash> placed;
  std::vector<int> soup_index;
  for (unsigned m = 0; m < source.node->mNumMeshes; ++m) {
    const unsigned mesh_index = source.node->mMeshes[m];
    const aiMesh& mesh = *scene.mMeshes[mesh_index];
    soup_index.assign(mesh.mNumVertices, -1);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError(file, location,
                         "mesh " + std::to_string(mesh_index) + ", vertex " + std::to_string(v) +
                             ": a coordinate is not finite");
      const auto [it, inserted] = placed.emplace(std::array<ai_real, 3>{p.x, p.y, p.z},
                                                 static_cast<int>(soup.points.size()));
      soup_index[v] = it->second;
      if (!inserted) {
        ++part.repairs.duplicate_vertices_merged;
        continue;
      }
      std::array<Rational, 3> q = {Rational(static_cast<double>(p.x)),
                                   Rational(static_cast<double>(p.y)),
                                   Rational(static_cast<double>(p.z))};
      if (!identity) q = map_point(source.world, q);
      try {
        soup.points.push_back(placer.place(std::move(q), part.repairs.snapped_coordinates_changed));
      } catch (const std::range_error& e) {
        throw InputError(file, location,
                         "mesh " + std::to_string(mesh_index) + ", vertex " + std::to_string(v) +
                             ": " + e.what());
      }
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++part.repairs.non_surface_primitives_ignored;
        continue;
      }
      std::array<int, 3> corners = {soup_index[face.mIndices[0]], soup_index[face.mIndices[1]],
                                    soup_index[face.mIndices[2]]};
      if (mirrored) std::swap(corners[1], corners[2]);
      soup.corners.push_back(corners);
      soup.materials.push_back(static_cast<int>(mesh.mMaterialIndex));
      ++triangles;
    }
  }
  part.faces = planar_faces(soup, part.repairs);
  if (part.faces.empty() && triangles > 0)
    throw InputError(file, location,
                     "every face has fewer than 3 distinct, non-collinear points after "
                     "snapping to the " +
                         std::to_string(snap) + " m grid");
  return part;
}

}  // namespace

ImportedModel import_model(const std::filesystem::path& path, const Placement& placement,
                           bool parallel) {
  const std::string file = path.string();
  const Placer placer(placement, file);
  Assimp::Importer importer;
  const aiScene& scene = *read_scene(importer, path);

  std::vector<PartSource> sources;
  collect_parts(scene, *scene.mRootNode, identity_map(), "", file, sources);
  if (lower(path.extension().string()) == ".obj") whole_obj_names(path, sources);
  unique_names(sources);
  // the triangles to place, each node's meshes counted as often as nodes use them: refused
  // over the limit before any exact point is made (docs/reliability.md, "Limits").
  std::uint64_t faces = 0;
  for (const PartSource& source : sources)
    for (unsigned m = 0; m < source.node->mNumMeshes; ++m)
      if (source.node->mMeshes[m] < scene.mNumMeshes)
        faces += scene.mMeshes[source.node->mMeshes[m]]->mNumFaces;
  if (faces > max_model_faces)
    throw InputError(file, "",
                     "the model has " + std::to_string(faces) + " faces, over the limit of " +
                         std::to_string(max_model_faces) + " (docs/reliability.md, \"Limits\")");

  ImportedModel model;
  model.materials = materials(scene);
  // Parts are independent: placed and merged across threads, assembled in file order (the
  // first failing part in file order is the error reported).
  std::vector<ModelPart> parts(sources.size());
  std::vector<std::exception_ptr> errors(sources.size());
  for_each_index(sources.size(), parallel, [&](std::size_t k) {
    try {
      parts[k] = import_part(scene, sources[k], placer, file, placement.snap);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (errors[k]) std::rethrow_exception(errors[k]);
    ModelPart& part = parts[k];
    model.repairs += part.repairs;
    if (part.faces.empty()) continue;  // points and lines only
    const int material = part.faces.front().material;
    if (material >= 0 && static_cast<std::size_t>(material) < model.materials.size() &&
        std::all_of(part.faces.begin(), part.faces.end(),
                    [&](const PlanarFace& face) { return face.material == material; }))
      part.colour = model.materials[material].colour;
    model.parts.push_back(std::move(part));
  }
  if (model.parts.empty()) throw InputError(file, "", "the model has no faces");
  return model;
}

}  // namespace penumbra
