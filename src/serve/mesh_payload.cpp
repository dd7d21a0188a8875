// The binary bodies of the API (mesh_payload.h).

#include "mesh_payload.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace penumbra::serve {
namespace {

// Appends 4-byte words in the machine's order: every target penumbra builds for is
// little-endian, as the page's typed arrays expect.
class Words {
 public:
  void u32(std::uint32_t value) { append(&value); }
  void f32(double value) {
    const float word = static_cast<float>(value);
    append(&word);
  }
  template <typename Matrix>
  void f32_matrix_rows(const Matrix& matrix) {
    for (Eigen::Index row = 0; row < matrix.rows(); ++row)
      for (Eigen::Index col = 0; col < matrix.cols(); ++col) f32(matrix(row, col));
  }
  std::string take() { return std::move(bytes_); }

 private:
  void append(const void* word) { bytes_.append(static_cast<const char*>(word), 4); }
  std::string bytes_;
};

static_assert(sizeof(float) == 4, "the API's floats are IEEE single precision");

}  // namespace

std::string mesh_payload(const basis::PatchMesh& mesh) {
  std::vector<std::uint32_t> triangle_patch;
  const auto triangles = mesh.triangles(&triangle_patch);
  Words words;
  words.u32(static_cast<std::uint32_t>(mesh.vertices().size()));
  words.u32(static_cast<std::uint32_t>(triangles.size()));
  words.u32(static_cast<std::uint32_t>(mesh.size()));
  words.u32(0);
  for (const Vec3d& vertex : mesh.vertices())
    for (double coordinate : vertex) words.f32(coordinate);
  for (const auto& triangle : triangles)
    for (std::uint32_t index : triangle) words.u32(index);
  for (std::uint32_t patch : triangle_patch) words.u32(patch);
  for (const basis::Patch& patch : mesh.patches()) {
    for (double coordinate : patch.centre) words.f32(coordinate);
    for (double coordinate : patch.normal) words.f32(coordinate);
  }
  for (const basis::Patch& patch : mesh.patches()) words.u32(patch.object);
  return words.take();
}

std::string relit_payload(const RelitScene& relit) {
  // Row-major RGB, then the lux: copied as blocks, this is on every edit's path.
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> rgb = relit.vertex_luminance;
  std::string bytes(static_cast<std::size_t>(rgb.size() + relit.vertex_lux.size()) * 4, '\0');
  std::memcpy(bytes.data(), rgb.data(), static_cast<std::size_t>(rgb.size()) * 4);
  std::memcpy(bytes.data() + rgb.size() * 4, relit.vertex_lux.data(),
              static_cast<std::size_t>(relit.vertex_lux.size()) * 4);
  return bytes;
}

std::string edited_payload(const std::string& json, const RelitScene& relit) {
  Words words;
  words.u32(static_cast<std::uint32_t>(json.size()));
  std::string bytes = words.take() + json;
  bytes.append((4 - bytes.size() % 4) % 4, ' ');
  return bytes + relit_payload(relit);
}

}  // namespace penumbra::serve
