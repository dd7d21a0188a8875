#include "bezier_objects.h"

#include <cmath>
#include <sstream>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "planar_faces.h"

namespace penumbra::detail {

std::vector<BezierPatch> read_bezier_file(const std::filesystem::path& path) {
  std::istringstream in(read_input_file(path, "patch file", file_limits::patches));
  std::size_t line_number = 0;
  std::string line;
  // returns the next line with content, split into numbers; fails at the end of the file.
  const auto numbers = [&](std::size_t expected, const char* what) {
    while (std::getline(in, line)) {
      ++line_number;
      std::istringstream fields(line);
      std::vector<double> values;
      std::string field;
      while (fields >> field) {
        std::size_t used = 0;
        double value = 0;
        try {
          value = std::stod(field, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != field.size() || !std::isfinite(value))
          throw InputError(path.string(), "line " + std::to_string(line_number),
                           "\"" + field + "\" is not a finite number (expected " + what + ")");
        values.push_back(value);
      }
      if (values.empty()) continue;
      if (values.size() != expected)
        throw InputError(path.string(), "line " + std::to_string(line_number),
                         "expected " + std::string(what) + ", found " +
                             std::to_string(values.size()) + " numbers");
      return values;
    }
    throw InputError(path.string(), "line " + std::to_string(line_number + 1),
                     "the file ends where " + std::string(what) + " should follow");
  };
  const double count = numbers(1, "the number of patches")[0];
  if (count < 1 || count != std::floor(count) || count > 1e6)
    throw InputError(path.string(), "line " + std::to_string(line_number),
                     "the number of patches must be a positive integer");
  // Read patch by patch: a count the file does not back allocates nothing large.
  std::vector<BezierPatch> patches;
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
    const std::vector<double> degrees = numbers(2, "the degrees \"3 3\"");
    if (degrees[0] != 3 || degrees[1] != 3)
      throw InputError(path.string(), "line " + std::to_string(line_number),
                       "only bicubic patches (degrees 3 3) are read");
    BezierPatch patch;
    for (Vec3d& point : patch.points) {
      const std::vector<double> xyz = numbers(3, "a control point x y z");
      point = {xyz[0], xyz[1], xyz[2]};
    }
    patches.push_back(patch);
  }
  std::string rest;
  if (in >> rest)
    throw InputError(path.string(), "line " + std::to_string(line_number + 1),
                     "unexpected content after the last patch");
  return patches;
}

std::vector<BezierPatch> placed_patches(std::vector<BezierPatch> patches,
                                        const Placement& placement) {
  for (BezierPatch& patch : patches)
    for (Vec3d& p : patch.points) {
      Vec3d q{p[0] * placement.scale, p[1] * placement.scale, p[2] * placement.scale};
      if (placement.y_up) q = {q[0], -q[2], q[1]};
      if (placement.transform) {
        const auto& m = *placement.transform;
        Vec3d r{};
        for (int row = 0; row < 3; ++row)
          r[row] =
              m[4 * row] * q[0] + m[4 * row + 1] * q[1] + m[4 * row + 2] * q[2] + m[4 * row + 3];
        q = r;
      }
      p = q;
    }
  return patches;
}

int grid_segments(const std::vector<BezierPatch>& patches, double tolerance) {
  int n = 1;
  for (const BezierPatch& patch : patches) n = std::max(n, tessellation_segments(patch, tolerance));
  return n;
}

PatchTessellation tessellate(const std::vector<BezierPatch>& patches, double tolerance, double snap,
                             const std::string& name) {
  PatchTessellation result;
  result.segments = grid_segments(patches, tolerance);
  const int n = result.segments;
  // The snap grid's step: the largest power of two not above snap, as for models.
  double step = 0;
  if (snap > 0) {
    int exponent = 0;
    std::frexp(snap, &exponent);
    step = std::ldexp(1.0, exponent - 1);
  }
  const auto snapped = [&](double x) { return step > 0 ? std::round(x / step) * step : x; };
  TriangleSoup soup;
  for (const BezierPatch& patch : patches) {
    const int first = static_cast<int>(soup.points.size());
    for (int k = 0; k <= n; ++k)
      for (int l = 0; l <= n; ++l) {
        const Vec3d p = patch.point(static_cast<double>(k) / n, static_cast<double>(l) / n);
        soup.points.emplace_back(snapped(p[0]), snapped(p[1]), snapped(p[2]));
      }
    const auto index = [&](int k, int l) { return first + k * (n + 1) + l; };
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l) {
        // Wound as S_u x S_v: the patch's own orientation.
        soup.corners.push_back({index(k, l), index(k + 1, l), index(k + 1, l + 1)});
        soup.corners.push_back({index(k, l), index(k + 1, l + 1), index(k, l + 1)});
        soup.materials.push_back(-1);
        soup.materials.push_back(-1);
      }
  }
  result.part.name = name;
  result.part.faces = planar_faces(soup, result.part.repairs);
  result.triangles = soup.corners.size() - result.part.repairs.degenerate_faces_dropped;
  return result;
}

}  // namespace penumbra::detail
