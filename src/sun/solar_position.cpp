#include "penumbra/sun/solar_position.h"

#include <erfa.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace penumbra::sun {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180;

// The wavelength for ERFA's observed-place functions, micrometres: visible light. It
// only matters to eraRefco's refraction constants, which are zero here (no pressure).
constexpr double kVisibleWavelengthUm = 0.55;

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(std::string("solar_position: ") + message);
}

}  // namespace

double refraction_deg(double elevation_deg, const Atmosphere& atmosphere) {
  if (elevation_deg < kRefractionLimitDeg) return 0;
  // Meeus eq. (16.4), arcminutes at 1010 hPa and 10 degrees C; SPA eq. (42) scales it.
  const double argument_deg = elevation_deg + 10.3 / (elevation_deg + 5.11);
  const double standard_arcmin = 1.02 / std::tan(argument_deg * kRadiansPerDegree);
  const double scale = atmosphere.pressure_hpa / 1010 * (283 / (273 + atmosphere.temperature_c));
  return scale * standard_arcmin / 60;
}

namespace {

void check_inputs(const Site& site, const std::optional<Atmosphere>& atmosphere,
                  double ut1_minus_utc_s) {
  require(std::isfinite(site.latitude_deg) && std::abs(site.latitude_deg) <= 90,
          "latitude must lie in -90..90 degrees");
  require(std::isfinite(site.longitude_deg) && std::abs(site.longitude_deg) <= 180,
          "longitude must lie in -180..180 degrees");
  require(std::isfinite(site.elevation_m), "elevation must be finite");
  require(std::isfinite(ut1_minus_utc_s), "UT1 - UTC must be finite");
  if (atmosphere) {
    require(std::isfinite(atmosphere->pressure_hpa) && atmosphere->pressure_hpa > 0,
            "pressure must be positive");
    require(std::isfinite(atmosphere->temperature_c) && atmosphere->temperature_c > -273.15,
            "temperature must lie above absolute zero");
  }
}

// UTC as ERFA's two-part quasi Julian Date (whole day + 0.5, fraction); eraDtf2d knows
// the leap-second days. A status of +1 ("dubious year": before 1960 or past ERFA's
// leap-second table) is accepted: ERFA then takes TAI - UTC as 0 or as the last known
// value, which only shifts TT, and the Sun moves 0.04 arcseconds per second of TT
// (docs/sun.md, "Time scales").
void utc_julian_date(UtcInstant time, double& utc1, double& utc2) {
  const CivilDateTime utc = civil_date_time(time, 0);
  if (eraDtf2d("UTC", utc.date.year, utc.date.month, utc.date.day, utc.hour, utc.minute,
               utc.second + utc.microsecond * 1e-6, &utc1, &utc2) < 0)
    throw std::invalid_argument("solar_position: ERFA refused the date");
}

// returns where the Sun's centre is seen, given the star-independent parameters of the
// site and instant (from eraApco or eraApco13, with zero refraction constants).
SolarPosition observed_sun(eraASTROM& astrom, const std::optional<Atmosphere>& atmosphere) {
  // The Sun's natural direction from the observer, BCRS axes: minus the observer's
  // heliocentric unit vector, so parallax is included. The ICRS-to-CIRS chain of
  // eraAtciq does not fit the Sun itself: its light deflection by the Sun assumes a
  // source beyond the Sun and its parallax a star's. Neglected: light time (the Sun
  // moves about 7 km about the barycentre in 499 s, under 0.00001 degrees).
  double toward_sun[3];
  for (int i = 0; i < 3; ++i) toward_sun[i] = -astrom.eh[i];

  // Aberration by the observer's barycentric velocity (annual plus diurnal: eraApco
  // puts both in astrom.v and sets astrom.diurab to 0), then the rotation to the
  // Celestial Intermediate Reference System.
  double proper[3], cirs[3];
  eraAb(toward_sun, astrom.v, astrom.em, astrom.bm1, proper);
  eraRxp(astrom.bpn, proper, cirs);
  double right_ascension = 0, declination = 0;
  eraC2s(cirs, &right_ascension, &declination);

  // CIRS to the horizon: Earth rotation angle and longitude to the hour angle, then the
  // latitude; refraction constants are zero, so the result is airless.
  double azimuth = 0, zenith = 0, hour_angle = 0, observed_declination = 0,
         observed_right_ascension = 0;
  eraAtioq(right_ascension, declination, &astrom, &azimuth, &zenith, &hour_angle,
           &observed_declination, &observed_right_ascension);

  SolarPosition position;
  position.azimuth_deg = azimuth / kRadiansPerDegree;
  position.elevation_deg = 90 - zenith / kRadiansPerDegree;
  if (atmosphere) position.elevation_deg += refraction_deg(position.elevation_deg, *atmosphere);
  return position;
}

}  // namespace

SolarPosition solar_position(const Site& site, UtcInstant time,
                             const std::optional<Atmosphere>& atmosphere, double ut1_minus_utc_s) {
  check_inputs(site, atmosphere, ut1_minus_utc_s);
  double utc1 = 0, utc2 = 0;
  utc_julian_date(time, utc1, utc2);

  // Star-independent parameters for a terrestrial observer (eraApco13): TT via TAI,
  // UT1 = UTC + dUT1, the Earth's heliocentric and barycentric position and velocity
  // (eraEpv00), the IAU 2006/2000A bias-precession-nutation matrix (CIO based), the
  // Earth rotation angle, the observer's geocentric position and velocity on the
  // WGS84 ellipsoid. Polar motion is neglected (xp = yp = 0) and pressure 0 turns
  // ERFA's own refraction off: refraction is added by SPA's model (observed_sun).
  eraASTROM astrom;
  double equation_of_origins = 0;
  if (eraApco13(utc1, utc2, ut1_minus_utc_s, site.longitude_deg * kRadiansPerDegree,
                site.latitude_deg * kRadiansPerDegree, site.elevation_m, 0, 0, 0, 0, 0,
                kVisibleWavelengthUm, &astrom, &equation_of_origins) < 0)
    throw std::invalid_argument("solar_position: ERFA refused the date");
  return observed_sun(astrom, atmosphere);
}

SolarPositionSolver::SolarPositionSolver(const Site& site,
                                         const std::optional<Atmosphere>& atmosphere,
                                         double ut1_minus_utc_s)
    : site_(site), atmosphere_(atmosphere), ut1_minus_utc_s_(ut1_minus_utc_s) {
  check_inputs(site, atmosphere, ut1_minus_utc_s);
}

int SolarPositionSolver::slot_of(double day) const {
  for (int slot = 0; slot < 2; ++slot)
    if (filled_[slot] && nodes_[slot].day == day) return slot;
  return -1;
}

void SolarPositionSolver::fill(int slot, double day) {
  // The models eraApco13 evaluates at the instant itself, here at 0h TT (TDB taken as
  // TT, as eraApco13 does: they differ by under 2 ms).
  DayNode& node = nodes_[slot];
  node.day = day;
  const double midnight = day + 0.5;
  if (eraEpv00(midnight, 0, node.heliocentric, node.barycentric) < 0)
    throw std::invalid_argument("solar_position: ERFA refused the date");
  double bias_precession_nutation[3][3];
  eraPnm06a(midnight, 0, bias_precession_nutation);
  eraBpn2xy(bias_precession_nutation, &node.cip_x, &node.cip_y);
  node.cio_s = eraS06(midnight, 0, node.cip_x, node.cip_y);
  filled_[slot] = true;
}

SolarPosition SolarPositionSolver::at(UtcInstant time) {
  double utc1 = 0, utc2 = 0, tai1 = 0, tai2 = 0, tt1 = 0, tt2 = 0, ut11 = 0, ut12 = 0;
  utc_julian_date(time, utc1, utc2);
  if (eraUtctai(utc1, utc2, &tai1, &tai2) < 0 || eraTaitt(tai1, tai2, &tt1, &tt2) < 0 ||
      eraUtcut1(utc1, utc2, ut1_minus_utc_s_, &ut11, &ut12) < 0)
    throw std::invalid_argument("solar_position: ERFA refused the date");

  // tt1 is a whole day + 0.5 (eraDtf2d's split, kept by eraUtctai and eraTaitt), so the
  // day since 0h TT and the fraction of it are exact.
  const double whole_days = std::floor(tt2);
  const double day = tt1 - 0.5 + whole_days;
  const double f = tt2 - whole_days;
  int first = slot_of(day), second = slot_of(day + 1);
  if (first < 0) {
    first = second == 0 ? 1 : 0;
    fill(first, day);
  }
  if (second < 0) {
    second = 1 - first;
    fill(second, day + 1);
  }
  const DayNode& a = nodes_[first];
  const DayNode& b = nodes_[second];

  // Cubic Hermite interpolation over one day from positions and velocities (au, au/day),
  // velocities from its derivative. Its error is at most h^4 / 384 times the fourth
  // derivative: 0.03 km for the Moon's monthly 4700 km swing of the Earth, 3e-10 au for
  // the yearly orbit; both under 1e-8 degrees seen from the Earth.
  const double f2 = f * f, f3 = f2 * f;
  const double h00 = 2 * f3 - 3 * f2 + 1, h10 = f3 - 2 * f2 + f, h01 = -2 * f3 + 3 * f2,
               h11 = f3 - f2;
  const double d00 = 6 * f2 - 6 * f, d10 = 3 * f2 - 4 * f + 1, d01 = -6 * f2 + 6 * f,
               d11 = 3 * f2 - 2 * f;
  double barycentric[2][3], heliocentric[3];
  for (int i = 0; i < 3; ++i) {
    heliocentric[i] = h00 * a.heliocentric[0][i] + h10 * a.heliocentric[1][i] +
                      h01 * b.heliocentric[0][i] + h11 * b.heliocentric[1][i];
    barycentric[0][i] = h00 * a.barycentric[0][i] + h10 * a.barycentric[1][i] +
                        h01 * b.barycentric[0][i] + h11 * b.barycentric[1][i];
    barycentric[1][i] = d00 * a.barycentric[0][i] + d10 * a.barycentric[1][i] +
                        d01 * b.barycentric[0][i] + d11 * b.barycentric[1][i];
  }
  // The pole's coordinates linearly: the fastest sizeable nutation term (13.66 days, 0.09
  // arcseconds in X) bends them by under 0.003 arcseconds within a day.
  const double cip_x = a.cip_x + f * (b.cip_x - a.cip_x);
  const double cip_y = a.cip_y + f * (b.cip_y - a.cip_y);
  const double cio_s = a.cio_s + f * (b.cio_s - a.cio_s);

  eraASTROM astrom;
  eraApco(tt1, tt2, barycentric, heliocentric, cip_x, cip_y, cio_s, eraEra00(ut11, ut12),
          site_.longitude_deg * kRadiansPerDegree, site_.latitude_deg * kRadiansPerDegree,
          site_.elevation_m, 0, 0, eraSp00(tt1, tt2), 0, 0, &astrom);
  return observed_sun(astrom, atmosphere_);
}

Vec3d light_direction(const SolarPosition& position, double north_deg) {
  if (!std::isfinite(north_deg) || !std::isfinite(position.azimuth_deg) ||
      !std::isfinite(position.elevation_deg))
    throw std::invalid_argument("light_direction: angles must be finite");
  // True north is +Y turned counter-clockwise by north_deg: (-sin n, cos n, 0); east,
  // a quarter turn clockwise from it seen from above: (cos n, sin n, 0). The Sun lies
  // along cos e (sin A east + cos A north) + sin e up, which the angle-difference
  // identities turn into the components below; light travels the opposite way.
  const double relative = (position.azimuth_deg - north_deg) * kRadiansPerDegree;
  const double elevation = position.elevation_deg * kRadiansPerDegree;
  return {-std::cos(elevation) * std::sin(relative), -std::cos(elevation) * std::cos(relative),
          -std::sin(elevation)};
}

}  // namespace penumbra::sun
