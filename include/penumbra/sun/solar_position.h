#pragma once
// The Sun's apparent topocentric azimuth and elevation for a site and a UTC instant
// (issue 19), computed with ERFA, the BSD-licensed edition of the IAU SOFA library:
// Earth ephemeris, IAU 2006/2000A precession-nutation, Earth rotation angle, annual
// and diurnal aberration and parallax; refraction by Saemundsson's formula when the
// air is given. docs/sun.md has the chain of frames, what is neglected (UT1 - UTC by
// default: up to 0.004 degrees) and the accuracy measured against published values
// (JPL Horizons within 0.0013 degrees). Doubles only, no CGAL.

#include <optional>

#include "penumbra/base/vec3d.h"
#include "penumbra/sun/civil_time.h"

namespace penumbra::sun {

// A place on the Earth.
struct Site {
  double latitude_deg = 0;   // geodetic (WGS84), north positive, -90..90
  double longitude_deg = 0;  // east positive, -180..180
  double elevation_m = 0;    // height above the WGS84 ellipsoid (sea level is close enough)
};

// The air at the site, for refraction.
struct Atmosphere {
  double pressure_hpa = 1010;  // local (not sea-level) pressure, > 0
  double temperature_c = 10;   // > -273.15
};

// Where the Sun's centre is seen.
struct SolarPosition {
  double azimuth_deg = 0;    // from true north through east, 0..360
  double elevation_deg = 0;  // above the horizon (negative below it), -90..90
  double zenith_deg() const { return 90 - elevation_deg; }
};

// The Sun's semidiameter and the standard refraction at the horizon, as NREL's spa.c
// uses them (SUN_RADIUS, atmos_refract): below an airless elevation of
// -(0.26667 + 0.5667) degrees no part of the Sun can be refracted into view, and spa.c
// and solar_position apply no refraction.
inline constexpr double kRefractionLimitDeg = -(0.26667 + 0.5667);

// returns the apparent topocentric position of the Sun's centre seen from site at
// time. Without atmosphere the elevation is airless (geometric); with it, refraction
// refraction_deg(elevation, *atmosphere) is added whenever the airless elevation is at
// least kRefractionLimitDeg. ut1_minus_utc_s is UT1 - UTC in seconds (IERS Bulletin A);
// the default 0 costs at most 0.004 degrees, since |UT1 - UTC| < 0.9 s. Throws
// std::invalid_argument for a latitude outside -90..90, a longitude outside -180..180,
// non-finite values, a pressure that is not positive or a temperature at or below
// absolute zero.
SolarPosition solar_position(const Site& site, UtcInstant time,
                             const std::optional<Atmosphere>& atmosphere = std::nullopt,
                             double ut1_minus_utc_s = 0);

// Solar positions for one site at many instants (the steps of `penumbra sun` and of
// sun-hours): solar_position to within 1e-5 degrees, about fifty times faster. The
// Earth's position and velocity and the precession-nutation of the pole change slowly;
// they are computed at 0h TT of each day the instants fall in and interpolated between
// (cubic Hermite and linear; docs/sun.md bounds the error). Not thread-safe: use one
// solver per thread.
class SolarPositionSolver {
 public:
  // throws std::invalid_argument as solar_position does.
  explicit SolarPositionSolver(const Site& site,
                               const std::optional<Atmosphere>& atmosphere = std::nullopt,
                               double ut1_minus_utc_s = 0);

  // returns the position solar_position(site, time, atmosphere, ut1_minus_utc_s) gives.
  SolarPosition at(UtcInstant time);

 private:
  // What is interpolated, at 0h TT of one day (Julian Date day + 0.5).
  struct DayNode {
    double day = 0;                          // JD(TT) - 0.5, a whole number
    double heliocentric[2][3] = {};          // Earth, au and au/day, BCRS axes
    double barycentric[2][3] = {};           // Earth, au and au/day, BCRS axes
    double cip_x = 0, cip_y = 0, cio_s = 0;  // CIP X, Y and CIO locator s, radians
  };
  // returns the slot (0 or 1) holding the node of day, or -1.
  int slot_of(double day) const;
  // computes the node of day into slot.
  void fill(int slot, double day);

  Site site_;
  std::optional<Atmosphere> atmosphere_;
  double ut1_minus_utc_s_;
  DayNode nodes_[2];
  bool filled_[2] = {false, false};
};

// returns the atmospheric refraction in degrees for a body at airless elevation
// elevation_deg: Saemundsson (1986) as given by Meeus, Astronomical Algorithms, 2nd ed.,
// eq. (16.4), R = 1.02' / tan(h + 10.3 / (h + 5.11)), scaled by (P / 1010) (283 / (273 + T))
// as in NREL SPA eq. (42). Zero below kRefractionLimitDeg.
double refraction_deg(double elevation_deg, const Atmosphere& atmosphere);

// returns the unit vector along which sunlight travels in the model frame (the
// direction of a "directional" light: from the Sun into the scene, so z < 0 while the
// Sun is up). north_deg is the angle of true north from the model's +Y axis,
// counter-clockwise seen from above (+Z); 0 means +Y is north and +X east, 90 means
// north is -X. The Sun toward azimuth A and elevation e lies along
// (cos e sin(A - north_deg), cos e cos(A - north_deg), sin e).
Vec3d light_direction(const SolarPosition& position, double north_deg);

}  // namespace penumbra::sun
