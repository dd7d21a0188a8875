#pragma once
// Luminous intensity distributions (LID) of point sources: Nishita 1985 section 3.1,
// Dobashi 1995 section 3.1. A distribution is given in its own photometric frame:
// gamma is the angle from the illumination axis (0..pi), c the azimuth about the
// axis measured from the C = 0 reference direction. C grows counter-clockwise as
// seen by an observer behind the lamp looking along the axis (for a downlight: seen
// from above), which is the LM-63 type C and the EULUMDAT convention; so the C = 90
// half-plane lies along c0 x axis. docs/photometry.md has the figure and the world
// mapping (penumbra/photometry/orientation.h).

#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>
#include "penumbra/base/numbers.h"

namespace penumbra::photometry {

// converts degrees to radians. Every conversion in the layer goes through this one
// function, so an angle given in degrees hits a table node exactly.
inline double radians(double degrees) {
  return degrees * (pi / 180.0);
}
// converts radians to degrees.
inline double degrees(double radians) {
  return radians * (180.0 / pi);
}

// The symmetry of a distribution about its axis and its principal planes.
enum class Symmetry {
  isotropic,           // the same in every direction
  axial,               // rotationally symmetric about the axis (one C plane)
  quadrant,            // mirror symmetric to the C0-C180 and the C90-C270 planes
  bilateral_c0_c180,   // mirror symmetric to the C0-C180 plane: I(C) = I(360 - C)
  bilateral_c90_c270,  // mirror symmetric to the C90-C270 plane: I(C) = I(180 - C)
  none,
};

// returns the name used in outputs: "isotropic", "axial", "quadrant", "bilateral-c0-c180",
// "bilateral-c90-c270" or "none".
const char* symmetry_name(Symmetry symmetry);

// A direction in the photometric frame, radians.
struct PhotometricDirection {
  double gamma = 0;  // from the axis, 0..pi
  double c = 0;      // azimuth from C = 0, 0..2 pi
};

class Distribution {
 public:
  virtual ~Distribution() = default;

  // returns the intensity in candela toward polar angle gamma and azimuth c (radians).
  virtual double intensity(double gamma, double c) const = 0;

  // returns the largest intensity over the sphere, in candela.
  virtual double max_intensity() const = 0;

  // returns a direction in which the intensity is largest.
  virtual PhotometricDirection max_direction() const { return {}; }

  // returns the total luminous flux in lumen, the integral of intensity over the sphere.
  // The default integrates numerically; the distributions of this layer override it
  // with the exact integral of their interpolant.
  virtual double flux() const;

  // returns the symmetry the distribution is known to have.
  virtual Symmetry symmetry() const { return Symmetry::none; }
};

// Where a distribution specification came from, so errors can name it.
struct SpecContext {
  std::string file;                // the scene file (or "" for a command-line SPEC)
  std::string json_path;           // e.g. "lights[2].lid"
  std::filesystem::path base_dir;  // relative photometric file names resolve here
};

// builds the distribution a scene's `lid` object describes (docs/photometry.md):
//   {"candela": I}                                     isotropic
//   {"table_deg": [...], "candela": [...]}             rotationally symmetric table
//   {"cos_power": k, "spread_deg": s, "candela": I0}   Dobashi eq. (11)
//   {"cardioid": true, "candela": I0}                  Nishita section 3.1: I0 (1 + cos g) / 2
//   {"ies": FILE} or {"ldt": FILE, "lamp_set": n}      photometric files
// each optionally with "interpolation": "linear" | "cosine" (tables and files) and
// "multiplier": m. Throws InputError naming the file and JSON path (or the
// photometric file and line).
std::shared_ptr<const Distribution> make_distribution(const nlohmann::json& spec,
                                                      const SpecContext& context);

// an isotropic point source of the given intensity.
std::shared_ptr<const Distribution> make_isotropic(double candela);

}  // namespace penumbra::photometry
