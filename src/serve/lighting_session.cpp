// A lighting-design session over basis luminances (include/penumbra/serve/lighting_session.h).

#include "penumbra/serve/lighting_session.h"

#include <filesystem>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <variant>

#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/distribution_fit.h"
#include "penumbra/scene/scene.h"

namespace penumbra::serve {
namespace {

// returns a finite number of json, else throws naming field.
double read_number(const nlohmann::json& value, const std::string& field) {
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    throw std::invalid_argument(field + ": expected a finite number");
  return value.get<double>();
}

double read_non_negative(const nlohmann::json& value, const std::string& field) {
  const double number = read_number(value, field);
  if (number < 0) throw std::invalid_argument(field + ": expected a number >= 0");
  return number;
}

std::array<double, 3> read_triple(const nlohmann::json& value, const std::string& field) {
  if (!value.is_array() || value.size() != 3)
    throw std::invalid_argument(field + ": expected an array of 3 numbers");
  return {read_number(value[0], field + "[0]"), read_number(value[1], field + "[1]"),
          read_number(value[2], field + "[2]")};
}

// applies changes (LightingSession::update's fields) to lamp.
void apply_changes(LampState& lamp, const nlohmann::json& changes) {
  if (!changes.is_object()) throw std::invalid_argument("expected a JSON object");
  for (const auto& [key, value] : changes.items()) {
    const std::string field = lamp.name + "." + key;
    if (key == "name") continue;
    if (key == "colour") {
      lamp.colour = read_triple(value, field);
      for (double channel : lamp.colour)
        if (channel < 0) throw std::invalid_argument(field + ": expected channels >= 0");
    } else if (key == "scale") {
      lamp.scale = read_non_negative(value, field);
    } else if (key == "sigma") {
      if (!value.is_boolean()) throw std::invalid_argument(field + ": expected true or false");
      if (!lamp.editor) throw std::invalid_argument(field + ": only point lamps have sigma");
      lamp.sigma = value.get<bool>();
    } else if (key == "aim") {
      lamp.aim_at(read_triple(value, field));
    } else if (key == "axis") {
      lamp.aim_along(read_triple(value, field));
    } else if (key == "controls") {
      if (!lamp.editor) throw std::invalid_argument(field + ": only point lamps have controls");
      if (!value.is_array() || value.size() != lamp.editor->control_intensities().size())
        throw std::invalid_argument(field + ": expected " +
                                    std::to_string(lamp.editor->control_intensities().size()) +
                                    " intensities (candela)");
      std::vector<double> intensities;
      for (std::size_t k = 0; k < value.size(); ++k)
        intensities.push_back(read_non_negative(value[k], field + "[" + std::to_string(k) + "]"));
      // Eq. (19): the weights of the new control points, from scratch.
      lamp.editor.emplace(lamp.editor->degree(), std::move(intensities));
    } else if (key != "controls_deg" && key != "c0") {
      throw std::invalid_argument(field + ": unknown field");
    }
  }
}

// returns the initial state of the basis's light from the scene's light.
LampState initial_state(const basis::BasisLight& light, const Light& scene_light,
                        int control_intervals) {
  LampState lamp;
  lamp.name = light.columns.name;
  lamp.kind = light.columns.kind;
  lamp.degree = light.columns.degree;
  if (const auto* point = std::get_if<PointLight>(&scene_light.source);
      point && light.columns.kind == basis::LightKind::point) {
    lamp.position = point->position;
    lamp.axis = point->axis;
    lamp.c0 = point->c0;
    // Section 4.1: the curve the designer edits, sampled at the control angles (an
    // asymmetric lamp's azimuthal average: the editor holds rotationally symmetric curves).
    const photometry::Distribution& distribution = *point->distribution;
    const basis::AxialProfile profile =
        basis::axial_profile(distribution, basis::breakpoints_of(distribution));
    lamp.editor =
        basis::LegendreWeightEditor::sampled(profile, light.columns.degree, control_intervals);
  }
  return lamp;
}

PatchLux patch_lux(const PatchIlluminance& patches, std::uint32_t patch) {
  PatchLux out;
  out.patch = patch;
  out.lux = patches.lux[patch];
  for (int channel = 0; channel < 3; ++channel) {
    out.total[channel] = patches.total(patch, channel);
    out.direct[channel] = patches.direct(patch, channel);
  }
  return out;
}

}  // namespace

double photometric(float red, float green, float blue) {
  return 0.2126 * red + 0.7152 * green + 0.0722 * blue;
}

Eigen::MatrixX3f vertex_reflectance(const basis::PatchMesh& mesh) {
  Eigen::MatrixX3f out =
      Eigen::MatrixX3f::Zero(static_cast<Eigen::Index>(mesh.vertices().size()), 3);
  const auto& weights = mesh.vertex_weights();
  for (std::size_t v = 0; v < weights.size(); ++v)
    if (!weights[v].empty())
      for (int channel = 0; channel < 3; ++channel)
        out(static_cast<Eigen::Index>(v), channel) =
            static_cast<float>(mesh.patches()[weights[v].front().first].reflectance[channel]);
  return out;
}

RelitScene relight_scene(const basis::BasisLuminances& basis, const basis::Lighting& lighting,
                         const Eigen::MatrixX3f& reflectance) {
  const auto start = std::chrono::steady_clock::now();
  // Section 3.5, step 3 (eq. 18): weighted sums of the vertices' basis values, in C++.
  RelitScene out;
  out.vertex_luminance = basis::relight(basis, lighting, true).vertex_luminance;
  const Eigen::Index vertices = out.vertex_luminance.rows();
  out.vertex_lux.resize(vertices);
  constexpr float pi_f = static_cast<float>(pi);
  for (Eigen::Index v = 0; v < vertices; ++v) {
    float e[3];
    for (int c = 0; c < 3; ++c)
      e[c] = reflectance(v, c) > 0 ? pi_f * out.vertex_luminance(v, c) / reflectance(v, c) : 0.0f;
    out.vertex_lux[v] = static_cast<float>(photometric(e[0], e[1], e[2]));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

LightingSession::LightingSession(basis::BasisLuminances basis, const Scene& scene,
                                 int control_intervals)
    : basis_(std::move(basis)), vertex_reflectance_(vertex_reflectance(basis_.mesh)) {
  const std::string file = scene.file.string();
  for (const Object& object : scene.objects) object_names_.push_back(object.name);
  if (scene.lights.size() != basis_.lights.size())
    throw InputError(file, "lights",
                     "the basis has " + std::to_string(basis_.lights.size()) +
                         " lights, the scene " + std::to_string(scene.lights.size()) +
                         ": the basis file was computed for another scene");
  for (std::size_t i = 0; i < basis_.lights.size(); ++i) {
    const basis::BasisLight& light = basis_.lights[i];
    if (scene.lights[i].name != light.columns.name)
      throw InputError(file, scene.lights[i].json_path,
                       "the basis's light " + std::to_string(i) + " is \"" + light.columns.name +
                           "\": the basis file was computed for another scene");
    const bool scene_point = std::holds_alternative<PointLight>(scene.lights[i].source);
    if (scene_point != (light.columns.kind == basis::LightKind::point))
      throw InputError(file, scene.lights[i].json_path,
                       "the basis's light \"" + light.columns.name +
                           "\" is of another kind: the basis file was computed for another scene");
    lamps_.push_back(initial_state(light, scene.lights[i], control_intervals));
  }
}

const LampState& LightingSession::lamp(const std::string& name) const {
  for (const LampState& lamp : lamps_)
    if (lamp.name == name) return lamp;
  throw UnknownLight(name);
}

LampState& LightingSession::find(const std::string& name) {
  return const_cast<LampState&>(static_cast<const LightingSession&>(*this).lamp(name));
}

void LightingSession::move_control_point(const std::string& name, int index, double candela) {
  LampState& lamp = find(name);
  if (!lamp.editor) throw std::invalid_argument(name + " is not a point lamp: it has no curve");
  if (index < 0 || index > lamp.editor->intervals())
    throw std::invalid_argument("index: expected 0.." + std::to_string(lamp.editor->intervals()));
  if (!std::isfinite(candela) || candela < 0)
    throw std::invalid_argument("candela: expected a finite number >= 0");
  // Section 4.1, eq. (21): the weights change by the moved point's share alone.
  lamp.editor->move_control_point(index, candela);
  stale_ = patches_stale_ = true;
}

void LightingSession::update(const std::string& name, const nlohmann::json& changes) {
  LampState& lamp = find(name);
  LampState changed = lamp;
  apply_changes(changed, changes);
  lamp = std::move(changed);
  stale_ = patches_stale_ = true;
}

nlohmann::json LightingSession::lighting_json() const {
  nlohmann::json lights = nlohmann::json::array();
  for (const LampState& lamp : lamps_) {
    nlohmann::json entry = {{"name", lamp.name}, {"colour", lamp.colour}, {"scale", lamp.scale}};
    if (lamp.editor) {
      entry["sigma"] = lamp.sigma;
      entry["axis"] = lamp.axis;
      nlohmann::json angles = nlohmann::json::array();
      for (int k = 0; k <= lamp.editor->intervals(); ++k)
        angles.push_back(lamp.editor->control_angle(k) * 180 / 3.14159265358979323846);
      entry["controls_deg"] = angles;
      entry["controls"] = lamp.editor->control_intensities();
    }
    lights.push_back(entry);
  }
  return {{"penumbra_lighting", 1},
          {"scene", std::filesystem::path(basis_.scene_file).filename().string()},
          {"lights", lights}};
}

void LightingSession::load_lighting_json(const nlohmann::json& lighting) {
  if (!lighting.is_object() || !lighting.contains("penumbra_lighting") ||
      lighting["penumbra_lighting"] != 1)
    throw std::invalid_argument("penumbra_lighting: expected a lighting file of version 1");
  if (!lighting.contains("lights") || !lighting["lights"].is_array())
    throw std::invalid_argument("lights: expected an array");
  std::vector<LampState> lamps = lamps_;
  for (const nlohmann::json& entry : lighting["lights"]) {
    if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string())
      throw std::invalid_argument("lights[]: expected objects with a \"name\"");
    const std::string name = entry["name"].get<std::string>();
    auto lamp = std::find_if(lamps.begin(), lamps.end(),
                             [&](const LampState& candidate) { return candidate.name == name; });
    if (lamp == lamps.end()) throw UnknownLight(name);
    apply_changes(*lamp, entry);
  }
  lamps_ = std::move(lamps);
  stale_ = patches_stale_ = true;
}

basis::Lighting LightingSession::lighting() const {
  basis::Lighting lighting;
  for (const LampState& lamp : lamps_) {
    basis::LightSetting setting;
    setting.coefficients = lamp.coefficients();
    setting.colour = lamp.colour;
    setting.scale = lamp.scale;
    lighting.push_back(std::move(setting));
  }
  return lighting;
}

const RelitScene& LightingSession::relit() {
  if (stale_) {
    relit_ = relight_scene(basis_, lighting(), vertex_reflectance_);
    stale_ = false;
  }
  return relit_;
}

const PatchIlluminance& LightingSession::patch_illuminance() {
  if (patches_stale_) {
    basis::Relit relit = basis::relight(basis_, lighting(), false);
    patches_.total = std::move(relit.total);
    patches_.direct = std::move(relit.direct);
    patches_.lux.resize(patches_.total.rows());
    for (Eigen::Index i = 0; i < patches_.total.rows(); ++i)
      patches_.lux[i] = static_cast<float>(
          photometric(patches_.total(i, 0), patches_.total(i, 1), patches_.total(i, 2)));
    patches_stale_ = false;
  }
  return patches_;
}

std::optional<PatchLux> LightingSession::lux_of_patch(std::int64_t patch) {
  if (patch < 0 || static_cast<std::size_t>(patch) >= basis_.mesh.size()) return {};
  return patch_lux(patch_illuminance(), static_cast<std::uint32_t>(patch));
}

std::optional<PatchLux> LightingSession::lux_at(const Vec3d& point, double tolerance) {
  const std::optional<std::uint32_t> patch = basis_.mesh.nearest_patch(point, tolerance);
  if (!patch) return {};
  return patch_lux(patch_illuminance(), *patch);
}

}  // namespace penumbra::serve
