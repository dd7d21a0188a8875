#include "penumbra/basis/basis_file.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <numeric>

#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"

namespace penumbra::basis {

namespace {

constexpr char kMagic[8] = {'P', 'N', 'B', 'R', 'P', 'B', 'L', '1'};
constexpr int kVersion = 1;

// One raw array of the file: its table entry and its bytes.
struct Array {
  std::string type;  // "f32", "f64", "u32"
  std::uint64_t rows = 0, cols = 0;
  std::string bytes;
};

std::size_t type_size(const std::string& type) {
  return type == "f64" ? 8 : 4;
}

template <typename Scalar>
Array array_of(const std::string& type, const Scalar* data, std::uint64_t rows,
               std::uint64_t cols) {
  Array array{type, rows, cols, {}};
  array.bytes.assign(reinterpret_cast<const char*>(data), rows * cols * sizeof(Scalar));
  return array;
}

template <typename Matrix>
Array matrix_array(const std::string& type, const Matrix& matrix) {
  using Scalar = typename Matrix::Scalar;
  const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = matrix;
  return array_of(type, rows.data(), static_cast<std::uint64_t>(rows.rows()),
                  static_cast<std::uint64_t>(rows.cols()));
}

nlohmann::json vec(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

// Reading: every failure names the file and the field.
class Reader {
 public:
  explicit Reader(std::filesystem::path path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw InputError(path_.string(), field, message);
  }

  void load() {
    const std::string content = read_input_file(path_, "basis file", file_limits::basis);
    if (content.size() < 16 || std::memcmp(content.data(), kMagic, 8) != 0)
      fail("", "not a penumbra basis file (.pbl): wrong magic");
    std::uint64_t header_length = 0;
    std::memcpy(&header_length, content.data() + 8, 8);
    if (header_length > content.size() - 16)
      fail("header", "header length beyond the end of the file");
    header_ = parse_input_json(content.substr(16, header_length), path_.string() + ": header");
    if (header_.value("version", 0) != kVersion)
      fail("version",
           "unsupported basis file version (this program reads " + std::to_string(kVersion) + ")");
    std::size_t offset = 16 + header_length;
    const nlohmann::json& table = field("arrays");
    if (!table.is_array()) fail("arrays", "must be an array");
    for (std::size_t k = 0; k < table.size(); ++k) {
      const std::string where = "arrays[" + std::to_string(k) + "]";
      Array array;
      std::string name;
      try {
        name = table[k].at("name").get<std::string>();
        array.type = table[k].at("type").get<std::string>();
        array.rows = table[k].at("rows").get<std::uint64_t>();
        array.cols = table[k].at("cols").get<std::uint64_t>();
      } catch (const nlohmann::json::exception&) {
        fail(where, "needs name, type, rows and cols");
      }
      if (array.type != "f32" && array.type != "f64" && array.type != "u32")
        fail(where + ".type", "unknown type \"" + array.type + "\"");
      if (array.cols != 0 &&
          array.rows > (content.size() - offset) / array.cols / type_size(array.type))
        fail(where, "array \"" + name + "\" runs past the end of the file");
      const std::size_t size = array.rows * array.cols * type_size(array.type);
      array.bytes = content.substr(offset, size);
      offset += size;
      arrays_[name] = std::move(array);
    }
    if (offset != content.size()) fail("arrays", "the file is longer than its arrays");
  }

  const nlohmann::json& field(const std::string& name) const {
    if (!header_.contains(name)) fail(name, "missing");
    return header_.at(name);
  }
  template <typename T>
  T get(const nlohmann::json& json, const std::string& where) const {
    try {
      return json.get<T>();
    } catch (const nlohmann::json::exception&) {
      fail(where, "wrong type");
    }
  }

  // returns array name as a matrix of Scalar with the expected shape (cols; rows when >= 0).
  template <typename Scalar>
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> matrix(const std::string& name,
                                                               const std::string& type,
                                                               std::int64_t rows,
                                                               std::int64_t cols) const {
    const auto found = arrays_.find(name);
    if (found == arrays_.end()) fail("arrays", "array \"" + name + "\" is missing");
    const Array& array = found->second;
    if (array.type != type) fail("arrays", "array \"" + name + "\" must be " + type);
    if ((rows >= 0 && array.rows != static_cast<std::uint64_t>(rows)) ||
        (cols >= 0 && array.cols != static_cast<std::uint64_t>(cols)))
      fail("arrays", "array \"" + name + "\" has the wrong shape");
    Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> out(
        static_cast<Eigen::Index>(array.rows), static_cast<Eigen::Index>(array.cols));
    std::memcpy(out.data(), array.bytes.data(), array.bytes.size());
    return out;
  }

  BasisBlock block(const std::string& name, const nlohmann::json& info, std::int64_t rows,
                   std::int64_t cols) const {
    if (info.value("compressed", false)) {
      const Eigen::MatrixXf left = matrix<float>(name + ".left", "f32", rows, -1);
      const Eigen::MatrixXf right = matrix<float>(name + ".right", "f32", cols, left.cols());
      return BasisBlock::low_rank(left, right, info.value("error", 0.0));
    }
    return BasisBlock(matrix<float>(name, "f32", rows, cols));
  }

  const nlohmann::json& header() const { return header_; }

 private:
  std::filesystem::path path_;
  nlohmann::json header_;
  std::map<std::string, Array> arrays_;
};

Vec3d vec_of(const Reader& reader, const nlohmann::json& json, const std::string& where) {
  const auto v = reader.get<std::vector<double>>(json, where);
  if (v.size() != 3) reader.fail(where, "must have 3 numbers");
  return {v[0], v[1], v[2]};
}

}  // namespace

void write_basis(const std::filesystem::path& path, const BasisLuminances& basis) {
  const PatchMesh& mesh = basis.mesh;
  const std::size_t n = mesh.size(), vertex_count = mesh.vertices().size();
  std::vector<std::pair<std::string, Array>> arrays;
  const auto add = [&](const std::string& name, Array array) {
    arrays.emplace_back(name, std::move(array));
  };

  add("vertices", array_of("f64", mesh.vertices().data()->data(), vertex_count, 3));
  // the objects by name, each patch's object as its place there: the file does not depend on
  // the order of the scene's objects (docs/reliability.md)
  std::vector<std::size_t> by_name(basis.object_names.size());
  std::iota(by_name.begin(), by_name.end(), 0);
  std::sort(by_name.begin(), by_name.end(), [&](std::size_t a, std::size_t b) {
    return basis.object_names[a] < basis.object_names[b];
  });
  std::vector<std::uint32_t> place(by_name.size());
  std::vector<std::string> names;
  for (std::size_t k = 0; k < by_name.size(); ++k) {
    place[by_name[k]] = static_cast<std::uint32_t>(k);
    names.push_back(basis.object_names[by_name[k]]);
  }
  std::vector<std::uint32_t> object, face, offsets{0}, indices;
  std::vector<double> centre, normal, area, reflectance;
  for (const Patch& patch : mesh.patches()) {
    object.push_back(patch.object < place.size() ? place[patch.object] : patch.object);
    face.push_back(patch.face);
    centre.insert(centre.end(), patch.centre.begin(), patch.centre.end());
    normal.insert(normal.end(), patch.normal.begin(), patch.normal.end());
    area.push_back(patch.area);
    reflectance.insert(reflectance.end(), patch.reflectance.begin(), patch.reflectance.end());
    indices.insert(indices.end(), patch.vertices.begin(), patch.vertices.end());
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
  }
  add("patch_object", array_of("u32", object.data(), n, 1));
  add("patch_face", array_of("u32", face.data(), n, 1));
  add("patch_centre", array_of("f64", centre.data(), n, 3));
  add("patch_normal", array_of("f64", normal.data(), n, 3));
  add("patch_area", array_of("f64", area.data(), n, 1));
  add("patch_reflectance", array_of("f64", reflectance.data(), n, 3));
  add("patch_vertex_offsets", array_of("u32", offsets.data(), n + 1, 1));
  add("patch_vertex_indices", array_of("u32", indices.data(), indices.size(), 1));

  nlohmann::json lights = nlohmann::json::array();
  for (std::size_t k = 0; k < basis.lights.size(); ++k) {
    const BasisLight& light = basis.lights[k];
    const std::string prefix = "light" + std::to_string(k);
    nlohmann::json blocks = nlohmann::json::object();
    const auto add_block = [&](const std::string& name, const BasisBlock& block) {
      blocks[name] = {
          {"compressed", block.is_compressed()}, {"rank", block.rank()}, {"error", block.error()}};
      if (block.is_compressed()) {
        add(prefix + "." + name + ".left", matrix_array("f32", block.left()));
        add(prefix + "." + name + ".right", matrix_array("f32", block.right()));
      } else {
        add(prefix + "." + name, matrix_array("f32", block.full_values()));
      }
    };
    add_block("direct", light.direct);
    for (int c = 0; c < basis.channels; ++c) {
      add_block("total" + std::to_string(c), light.total[static_cast<std::size_t>(c)]);
      add_block("vertex" + std::to_string(c), light.vertex_luminance[static_cast<std::size_t>(c)]);
    }
    lights.push_back({{"name", light.columns.name},
                      {"kind", kind_name(light.columns.kind)},
                      {"degree", light.columns.degree},
                      {"first_column", light.columns.first_column},
                      {"count", light.columns.count},
                      {"position", vec(light.position)},
                      {"axis", vec(light.axis)},
                      {"c0", vec(light.c0)},
                      {"lid", light.lid},
                      {"lid_base", light.lid_base},
                      {"coefficients",
                       std::vector<double>(light.coefficients.data(),
                                           light.coefficients.data() + light.coefficients.size())},
                      {"blocks", blocks}});
  }
  nlohmann::json header = {
      {"format", "penumbra-basis"},
      {"version", kVersion},
      {"scene", basis.scene_file},
      {"channels", basis.channels},
      {"patch_count", n},
      {"vertex_count", vertex_count},
      {"patch_size", basis.options.patch_size},
      {"degree", basis.options.degree},
      {"form_factors",
       {{"method",
         basis.options.form_factors.method == FormFactorMethod::rays ? "rays" : "analytic"},
        {"rays", basis.options.form_factors.rays},
        {"seed", basis.options.form_factors.seed},
        {"entries", basis.form_factor_entries}}},
      {"radiosity",
       {{"tolerance", basis.options.radiosity.tolerance}, {"iterations", basis.iterations}}},
      {"compression", basis.options.compression},
      {"sigma", basis.options.sigma},
      {"objects", names},
      {"lights", lights}};
  if (basis.camera)
    header["camera"] = {{"eye", vec(basis.camera->eye)}, {"target", vec(basis.camera->target)},
                        {"up", vec(basis.camera->up)},   {"fov_deg", basis.camera->fov_deg},
                        {"width", basis.camera->width},  {"height", basis.camera->height}};
  nlohmann::json table = nlohmann::json::array();
  for (const auto& [name, array] : arrays)
    table.push_back(
        {{"name", name}, {"type", array.type}, {"rows", array.rows}, {"cols", array.cols}});
  header["arrays"] = table;
  const std::string text = header.dump();
  write_atomically(path, [&](std::ostream& out) {
    out.write(kMagic, 8);
    const std::uint64_t length = text.size();
    out.write(reinterpret_cast<const char*>(&length), 8);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    for (const auto& entry : arrays)
      out.write(entry.second.bytes.data(), static_cast<std::streamsize>(entry.second.bytes.size()));
  });
}

namespace {

BasisLuminances read_checked_basis(const std::filesystem::path& path) {
  Reader reader(path);
  reader.load();
  const nlohmann::json& header = reader.header();
  BasisLuminances basis;
  const auto n = reader.get<std::int64_t>(reader.field("patch_count"), "patch_count");
  const auto vertex_count = reader.get<std::int64_t>(reader.field("vertex_count"), "vertex_count");
  basis.channels = reader.get<int>(reader.field("channels"), "channels");
  if (basis.channels != 1 && basis.channels != 3) reader.fail("channels", "must be 1 or 3");
  basis.scene_file = header.value("scene", "");
  basis.options.patch_size = header.value("patch_size", 0.0);
  basis.options.degree = header.value("degree", 0);
  basis.options.compression = header.value("compression", 0.0);
  basis.options.sigma = header.value("sigma", true);
  if (header.contains("objects"))
    basis.object_names = reader.get<std::vector<std::string>>(header["objects"], "objects");
  basis.iterations = header.contains("radiosity") ? header["radiosity"].value("iterations", 0) : 0;

  const Eigen::MatrixXd vertices = reader.matrix<double>("vertices", "f64", vertex_count, 3);
  std::vector<Vec3d> points(static_cast<std::size_t>(vertex_count));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    points[static_cast<std::size_t>(v)] = {vertices(v, 0), vertices(v, 1), vertices(v, 2)};
  using U32 = Eigen::Matrix<std::uint32_t, Eigen::Dynamic, Eigen::Dynamic>;
  const U32 object = reader.matrix<std::uint32_t>("patch_object", "u32", n, 1);
  const U32 face = reader.matrix<std::uint32_t>("patch_face", "u32", n, 1);
  const Eigen::MatrixXd centre = reader.matrix<double>("patch_centre", "f64", n, 3);
  const Eigen::MatrixXd normal = reader.matrix<double>("patch_normal", "f64", n, 3);
  const Eigen::MatrixXd area = reader.matrix<double>("patch_area", "f64", n, 1);
  const Eigen::MatrixXd reflectance = reader.matrix<double>("patch_reflectance", "f64", n, 3);
  const U32 offsets = reader.matrix<std::uint32_t>("patch_vertex_offsets", "u32", n + 1, 1);
  const U32 indices = reader.matrix<std::uint32_t>("patch_vertex_indices", "u32", -1, 1);
  std::vector<Patch> patches(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    Patch& patch = patches[static_cast<std::size_t>(i)];
    patch.object = object(i);
    if (!basis.object_names.empty() && patch.object >= basis.object_names.size())
      reader.fail("patch_object", "object index out of range at patch " + std::to_string(i));
    patch.face = face(i);
    patch.centre = {centre(i, 0), centre(i, 1), centre(i, 2)};
    patch.normal = {normal(i, 0), normal(i, 1), normal(i, 2)};
    patch.area = area(i);
    patch.reflectance = {reflectance(i, 0), reflectance(i, 1), reflectance(i, 2)};
    if (offsets(i) > offsets(i + 1) || offsets(i + 1) > indices.rows())
      reader.fail("patch_vertex_offsets", "offsets out of range at patch " + std::to_string(i));
    for (std::uint32_t k = offsets(i); k < offsets(i + 1); ++k) {
      if (indices(k) >= vertex_count)
        reader.fail("patch_vertex_indices",
                    "vertex index out of range at patch " + std::to_string(i));
      patch.vertices.push_back(indices(k));
    }
    if (patch.vertices.size() < 3)
      reader.fail("patch_vertex_offsets",
                  "patch " + std::to_string(i) + " has fewer than 3 vertices");
  }
  basis.mesh = PatchMesh(std::move(points), std::move(patches));

  const nlohmann::json& lights = reader.field("lights");
  if (!lights.is_array()) reader.fail("lights", "must be an array");
  for (std::size_t k = 0; k < lights.size(); ++k) {
    const std::string where = "lights[" + std::to_string(k) + "]";
    const nlohmann::json& entry = lights[k];
    const auto member = [&](const char* key) -> const nlohmann::json& {
      if (!entry.contains(key)) reader.fail(where + "." + key, "missing");
      return entry.at(key);
    };
    BasisLight light;
    light.columns.name = reader.get<std::string>(member("name"), where + ".name");
    const auto kind = reader.get<std::string>(member("kind"), where + ".kind");
    light.columns.kind = kind == "point"    ? LightKind::point
                         : kind == "linear" ? LightKind::linear
                         : kind == "area"   ? LightKind::area
                                            : LightKind::directional;
    light.columns.degree = reader.get<int>(member("degree"), where + ".degree");
    light.columns.first_column =
        reader.get<Eigen::Index>(member("first_column"), where + ".first_column");
    light.columns.count = reader.get<Eigen::Index>(member("count"), where + ".count");
    if (light.columns.count < 1 || light.columns.count > 100000)
      reader.fail(where + ".count", "out of range");
    light.position = vec_of(reader, member("position"), where + ".position");
    light.axis = vec_of(reader, member("axis"), where + ".axis");
    light.c0 = vec_of(reader, member("c0"), where + ".c0");
    light.lid = entry.value("lid", nlohmann::json());
    light.lid_base = entry.value("lid_base", "");
    const auto coefficients =
        reader.get<std::vector<double>>(member("coefficients"), where + ".coefficients");
    if (static_cast<Eigen::Index>(coefficients.size()) != light.columns.count)
      reader.fail(where + ".coefficients",
                  "needs " + std::to_string(light.columns.count) + " numbers");
    light.coefficients =
        Eigen::Map<const Eigen::VectorXd>(coefficients.data(), light.columns.count);
    const std::string prefix = "light" + std::to_string(k);
    const nlohmann::json& blocks = member("blocks");
    const auto info = [&](const std::string& name) {
      return blocks.contains(name) ? blocks.at(name) : nlohmann::json::object();
    };
    light.direct = reader.block(prefix + ".direct", info("direct"), n, light.columns.count);
    for (int c = 0; c < basis.channels; ++c) {
      const std::string total = "total" + std::to_string(c), vertex = "vertex" + std::to_string(c);
      light.total.push_back(
          reader.block(prefix + "." + total, info(total), n, light.columns.count));
      light.vertex_luminance.push_back(
          reader.block(prefix + "." + vertex, info(vertex), vertex_count, light.columns.count));
    }
    basis.lights.push_back(std::move(light));
  }
  if (header.contains("camera") && header["camera"].is_object()) {
    const nlohmann::json& camera = header["camera"];
    Camera c;
    c.eye = vec_of(reader, camera.value("eye", nlohmann::json()), "camera.eye");
    c.target = vec_of(reader, camera.value("target", nlohmann::json()), "camera.target");
    c.up = vec_of(reader, camera.value("up", nlohmann::json()), "camera.up");
    c.fov_deg = camera.value("fov_deg", 60.0);
    c.width = camera.value("width", 640);
    c.height = camera.value("height", 480);
    if (!(c.fov_deg > 0 && c.fov_deg < 180)) reader.fail("camera.fov_deg", "must lie in (0, 180)");
    if (const std::string problem = image_size_problem(c.width, c.height); !problem.empty())
      reader.fail("camera", problem);
    basis.camera = c;
  }
  return basis;
}

}  // namespace

BasisLuminances read_basis(const std::filesystem::path& path) {
  try {
    return read_checked_basis(path);
  } catch (const nlohmann::json::exception& error) {
    // a header field of the wrong type, read with a default (json::value)
    throw InputError(path.string(), "header",
                     std::string("a field has the wrong type: ") + error.what());
  }
}

}  // namespace penumbra::basis
