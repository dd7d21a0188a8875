#pragma once
// EULUMDAT (.ldt) photometric files (Stockmar 1990): reading, symmetry expansion
// (Isym 0-4), cd/klm to candela, lamp sets, and conversion to LM-63.

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "penumbra/photometry/ies.h"
#include "penumbra/photometry/table_distribution.h"

namespace penumbra::photometry {

// One standard set of lamps (lines 26a-26f).
struct LampSet {
  int count = 1;  // negative: absolute photometry (the flux is the luminaire's own)
  std::string type;
  double flux = 0;  // total luminous flux of the set, lm
  std::string colour;
  std::string colour_rendering;
  double watts = 0;  // including ballast
};

struct EulumdatFile {
  std::string file;  // where it was read from, for messages
  std::string company;
  int type_indicator = 1;  // Ityp: 1 point source, axial; 2 linear; 3 point source, other
  int symmetry = 0;        // Isym 0-4
  int c_count = 0;         // Nc: C planes in 0..360
  double c_step = 0;       // Dc (0 when not equidistant)
  int gamma_count = 0;     // Ng
  double gamma_step = 0;   // Dg
  std::string report, luminaire_name, luminaire_number, file_name, date_user;
  // luminaire and luminous area, mm; width 0 means round
  double length = 0, width = 0, height = 0;
  double area_length = 0, area_width = 0;
  std::array<double, 4> area_height{};  // in the C0, C90, C180, C270 planes
  double downward_flux_fraction = 0;    // %
  double light_output_ratio = 0;        // LORL, %
  double intensity_factor = 1;          // conversion factor for luminous intensities
  double tilt_deg = 0;
  std::vector<LampSet> lamp_sets;
  std::array<double, 10> direct_ratios{};
  std::vector<double> c_deg;      // all Nc C angles
  std::vector<double> gamma_deg;  // Ng gamma angles
  // the stored planes (Mc1..Mc2 of the specification), cd/klm, [plane][gamma]
  std::vector<std::vector<double>> cd_per_klm;

  bool absolute() const { return !lamp_sets.empty() && lamp_sets.front().count < 0; }
  // returns the C angles of the stored planes: Isym 0 all, 1 {0}, 2 C0..C180,
  // 3 C90..C270, 4 C0..C90.
  std::vector<double> stored_c_deg() const;
};

// parses EULUMDAT text read from file. Throws InputError(file, "line N", ...).
EulumdatFile parse_eulumdat(const std::string& text, const std::filesystem::path& file);

// reads and parses the EULUMDAT file at path.
EulumdatFile read_eulumdat(const std::filesystem::path& path);

// returns the candela grid: I = value * intensity_factor * flux(lamp_set) / 1000. The
// values are cd per 1000 lm of the lamp set's flux, in relative and in absolute
// photometry alike (in absolute photometry that flux is the luminaire's). Isym 0 gets
// a closing C = 360 plane, a copy of C = 0. Throws InputError for a lamp set that does
// not exist.
PhotometricGrid candela_grid(const EulumdatFile& ldt, std::size_t lamp_set = 0);

// reads the file at path and builds its distribution, candela times multiplier.
std::shared_ptr<const TableDistribution> load_eulumdat(const std::filesystem::path& path,
                                                       Interpolation interpolation,
                                                       std::size_t lamp_set = 0,
                                                       double multiplier = 1);

// converts to an LM-63-2002 file (type C, absolute photometry, candela values, metres).
IesFile to_ies(const EulumdatFile& ldt, std::size_t lamp_set = 0);

}  // namespace penumbra::photometry
