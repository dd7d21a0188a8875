#pragma once
// The state of one lighting-design session over a scene's basis luminances (Dobashi 1995
// sections 3.5 and 4): the lamps as edited, and relighting by weighted sums (eq. 18)
// whenever they change. The HTTP server (lighting_server.h) is a thin layer over it; a
// session is not thread-safe, the server serialises access.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/basis/basis_luminances.h"
#include "penumbra/basis/relight.h"
#include "penumbra/serve/lamp_state.h"

namespace penumbra {
struct Scene;
}

namespace penumbra::serve {

// Thrown for a light name the session does not have.
class UnknownLight : public std::out_of_range {
 public:
  explicit UnknownLight(const std::string& name)
      : std::out_of_range("no light named \"" + name + "\""), name_(name) {}
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

// Photometric illuminance of RGB illuminance: the Rec. 709 luminance weights, so that
// white light (equal channels) gives its channel value.
double photometric(float red, float green, float blue);

// The relit view, in the units the page draws (single precision): what every edit
// recomputes, so only the vertex values (section 3.5, step 3).
struct RelitScene {
  Eigen::MatrixX3f vertex_luminance;  // vertices x 3, cd/m^2 (Gouraud values)
  Eigen::VectorXf vertex_lux;         // vertices: photometric illuminance, area-weighted mean
  double seconds = 0;                 // time of the weighted sums
};

// The illuminance of every patch, computed when asked for (lux queries, tests).
struct PatchIlluminance {
  Eigen::VectorXf lux;      // photometric total illuminance
  Eigen::MatrixX3f total;   // x 3: total illuminance per channel
  Eigen::MatrixX3f direct;  // x 3: direct illuminance per channel
};

// The illuminance of one patch.
struct PatchLux {
  std::uint32_t patch = 0;
  double lux = 0;            // photometric total
  Colour total{}, direct{};  // lux per channel
};

class LightingSession {
 public:
  // starts a session with every lamp as the scene gives it: each point lamp's curve
  // sampled at control_intervals + 1 angles (its azimuthal average when asymmetric),
  // sigma factors on. scene supplies the distributions; its lights must be the basis's
  // (same names, same order), else InputError naming the scene file.
  LightingSession(basis::BasisLuminances basis, const Scene& scene,
                  int control_intervals = default_control_intervals);

  const basis::BasisLuminances& basis() const { return basis_; }
  const std::vector<LampState>& lamps() const { return lamps_; }
  // the scene's object names, by the index patches refer to.
  const std::vector<std::string>& object_names() const { return object_names_; }

  // returns the lamp named name. Throws UnknownLight.
  const LampState& lamp(const std::string& name) const;

  // moves control point index of a point lamp to candela (>= 0, finite), eq. (21).
  // Throws UnknownLight, std::invalid_argument.
  void move_control_point(const std::string& name, int index, double candela);

  // applies a partial update: any of "colour" [r, g, b] (>= 0), "scale" (>= 0), "sigma"
  // (bool), "aim" [x, y, z] (a point), "axis" [x, y, z] (a direction), "controls" [candela
  // per control point]. Everything is checked before anything changes. Throws
  // UnknownLight, std::invalid_argument (with the field), nlohmann::json::exception.
  void update(const std::string& name, const nlohmann::json& changes);

  // returns the lighting setup as JSON (docs/serve.md, "Lighting file").
  nlohmann::json lighting_json() const;
  // replaces the setup by a lighting file's. Lights it does not name keep their state; a
  // name the scene lacks is an error. All or nothing. Throws as update.
  void load_lighting_json(const nlohmann::json& lighting);

  // returns the basis lighting of the lamps (relight.h).
  basis::Lighting lighting() const;

  // relights the vertices (eq. 18) if anything changed since the last call.
  const RelitScene& relit();
  // returns the patches' illuminance (eq. 18 over the patch blocks), recomputed if
  // anything changed since the last call.
  const PatchIlluminance& patch_illuminance();

  // returns the illuminance of patch (relighting first when needed), or {} when out of
  // range.
  std::optional<PatchLux> lux_of_patch(std::int64_t patch);
  // returns the illuminance of the patch nearest to point among those whose plane passes
  // within tolerance (m), or {}.
  std::optional<PatchLux> lux_at(const Vec3d& point, double tolerance = 0.02);

 private:
  LampState& find(const std::string& name);

  basis::BasisLuminances basis_;
  std::vector<LampState> lamps_;
  std::vector<std::string> object_names_;
  Eigen::MatrixX3f vertex_reflectance_;
  RelitScene relit_;
  PatchIlluminance patches_;
  bool stale_ = true, patches_stale_ = true;
};

// returns, per vertex, the reflectance per channel of its face (the patches sharing a
// vertex lie on one face, docs/basis.md): what turns vertex luminance into illuminance.
Eigen::MatrixX3f vertex_reflectance(const basis::PatchMesh& mesh);

// relights the vertices for lighting: basis::relight(..., vertices_only = true), and the
// vertex illuminance E = pi L / rho per channel, which equals the area-weighted mean of
// the patches' E because L = rho E / pi with rho one value per face. A black channel
// (rho = 0) gives 0.
RelitScene relight_scene(const basis::BasisLuminances& basis, const basis::Lighting& lighting,
                         const Eigen::MatrixX3f& vertex_reflectance);

}  // namespace penumbra::serve
