#pragma once
// Luminous intensity distributions (LID) of point sources: Nishita 1985 section 3.1,
// Dobashi 1995 section 3.1. A distribution is given in its own photometric frame:
// gamma is the angle from the illumination axis (0..pi), c the azimuth about the
// axis measured from the C=0 reference direction, counter-clockwise seen looking
// down the axis from the lamp... (see docs/photometry.md for the exact convention).

#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace penumbra::photometry {

class Distribution {
 public:
  virtual ~Distribution() = default;

  // returns the intensity in candela toward polar angle gamma and azimuth c (radians).
  virtual double intensity(double gamma, double c) const = 0;

  // returns the largest intensity over the sphere, in candela.
  virtual double max_intensity() const = 0;
};

// Where a distribution specification came from, so errors can name it.
struct SpecContext {
  std::string file;                 // the scene file (or "" for a command-line SPEC)
  std::string json_path;            // e.g. "lights[2].lid"
  std::filesystem::path base_dir;   // relative photometric file names resolve here
};

// builds the distribution a scene's `lid` object describes: {"table_deg", "candela"},
// {"cos_power", "spread_deg", "candela"}, {"ies": FILE}, {"ldt": FILE}, ...
// Throws InputError naming the file and JSON path (or the photometric file and line).
std::shared_ptr<const Distribution> make_distribution(const nlohmann::json& spec,
                                                      const SpecContext& context);

// an isotropic point source of the given intensity.
std::shared_ptr<const Distribution> make_isotropic(double candela);

}  // namespace penumbra::photometry
