// penumbra info SCENE: counts, and each object's faces with their exact planes.

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "penumbra/base/parallel.h"
#include "penumbra/io/rational.h"
#include "penumbra/scene/load_scene.h"
#include "verbs.h"

namespace penumbra::cli {
namespace {

// prints the plane scaled so that its largest normal component has magnitude 1:
// a canonical exact form, then the same in doubles.
void print_plane(std::ostream& out, const Plane3& plane) {
  const std::array<Rational, 4> coefficients = io::canonical_plane(plane);
  out << "plane [";
  for (int i = 0; i < 4; ++i) out << (i ? ", " : "") << io::rational_string(coefficients[i]);
  out << "] ~ [";
  // Rounded from the exact value (+ 0.0 prints an exact zero as 0, never -0).
  for (int i = 0; i < 4; ++i) out << (i ? ", " : "") << CGAL::to_double(coefficients[i]) + 0.0;
  out << "]";
}

int run_info(const std::string& path) {
  const Scene& scene = load_scene_until_exit(path);
  for (const std::string& warning : scene.warnings)
    std::cerr << "penumbra: warning: " << warning << "\n";

  std::size_t faces = 0, vertices = 0;
  for (const Object& object : scene.objects) {
    faces += object.solid.faces().size();
    vertices += object.solid.vertices().size();
  }
  std::cout << "scene " << path << "\n"
            << "objects " << scene.objects.size() << ", faces " << faces << ", vertices "
            << vertices << ", lights " << scene.lights.size() << ", materials "
            << scene.materials.size() - 1 << "\n";
  if (!scene.mesh_faces.empty()) {
    std::size_t pieces = 0;
    for (const Object& object : scene.objects) pieces += !object.part.empty();
    std::cout << "mesh faces " << scene.mesh_faces.size() << " (non-convex parts' faces, one entry "
              << "per receiving side), cut into " << pieces << " convex pieces\n";
  }
  // Each object's lines written on its own thread (rational strings cost), printed in order;
  // a mesh part that is not convex is listed once, by its faces, at its first piece.
  std::vector<std::string> texts(scene.objects.size());
  for_each_index(
      scene.objects.size(), true,
      [&](std::size_t k) {
        const Object& object = scene.objects[k];
        std::ostringstream out;
        if (!object.part.empty()) {
          if (k > 0 && scene.objects[k - 1].part == object.part) return;
          std::size_t first = kNoMeshFace;
          for (std::size_t m : object.mesh_faces) first = std::min(first, m);
          std::size_t last = first;
          while (last < scene.mesh_faces.size() && scene.mesh_faces[last].part == object.part)
            ++last;
          std::size_t count = 0;
          for (std::size_t j = k; j < scene.objects.size() && scene.objects[j].part == object.part;
               ++j)
            ++count;
          out << "\nobject " << object.part << " (mesh, material "
              << scene.materials[object.material].name << "): " << last - first << " faces, "
              << count << " convex pieces\n";
          for (std::size_t m = first; m < last; ++m) {
            const MeshFace& face = scene.mesh_faces[m];
            out << "  face " << face.index << ": " << face.outer.size() << " vertices, "
                << face.holes.size() << " holes, " << face.pieces.size() << " pieces, ";
            print_plane(out, face.plane);
            out << "\n";
          }
          texts[k] = out.str();
          return;
        }
        out << "\nobject " << object.name << " (" << object.kind
            << (object.solid.is_flat() ? ", two-sided" : "") << ", material "
            << scene.materials[object.material].name << "): " << object.solid.faces().size()
            << " faces, " << object.solid.vertices().size() << " vertices\n";
        for (std::size_t f = 0; f < object.solid.faces().size(); ++f) {
          const Face& face = object.solid.faces()[f];
          out << "  face " << f << ": " << face.vertices.size() << " vertices, ";
          print_plane(out, face.plane);
          out << "\n";
        }
        texts[k] = out.str();
      },
      64);
  // in the documents' order (by name), whatever the order of the scene file
  std::vector<std::size_t> order(scene.objects.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scene.objects[a].face_owner() < scene.objects[b].face_owner();
  });
  for (std::size_t k : order) std::cout << texts[k];
  std::cout << "\n";
  for (const Light& light : scene.lights) {
    std::cout << "light " << light.name << " (" << kind_name(light) << ")";
    if (const auto* point = std::get_if<PointLight>(&light.source))
      std::cout << " at [" << point->position[0] << ", " << point->position[1] << ", "
                << point->position[2] << "], max " << point->distribution->max_intensity() << " cd";
    if (const auto* tube = std::get_if<LinearLight>(&light.source))
      std::cout << " from [" << tube->start[0] << ", " << tube->start[1] << ", " << tube->start[2]
                << "] to [" << tube->end[0] << ", " << tube->end[1] << ", " << tube->end[2] << "], "
                << tube->candela_per_metre << " cd/m";
    if (const auto* panel = std::get_if<AreaLight>(&light.source))
      std::cout << ", " << panel->vertices.size() << " vertices, " << panel->area() << " m2, "
                << panel->luminance << " cd/m2" << (panel->two_sided ? ", two-sided" : "");
    if (const auto* sun = std::get_if<DirectionalLight>(&light.source))
      std::cout << " toward [" << sun->direction[0] << ", " << sun->direction[1] << ", "
                << sun->direction[2] << "], " << sun->illuminance << " lx";
    std::cout << "\n";
  }
  if (scene.camera)
    std::cout << "camera " << scene.camera->width << " x " << scene.camera->height << ", fov "
              << scene.camera->fov_deg << " deg\n";
  return 0;
}

}  // namespace

void register_info(CLI::App& app) {
  CLI::App* verb = app.add_subcommand("info", "objects, faces, exact planes and lights of a scene");
  auto path = std::make_shared<std::string>();
  verb->add_option("SCENE", *path, "scene file (JSON)")->required();
  verb->callback([path] { exit_status() = run_info(*path); });
}

}  // namespace penumbra::cli
