#pragma once
// IES LM-63 photometric files (LM-63-1986, -1991, -1995, -2002, -2019): reading,
// the candela grid they describe, and writing them back (penumbra lid convert).

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "penumbra/photometry/table_distribution.h"

namespace penumbra::photometry {

// The TILT section: lamp output factors against the luminaire's tilt.
struct IesTilt {
  std::string mode = "NONE";           // "NONE", "INCLUDE", or the TILT file's name as written
  int lamp_to_luminaire_geometry = 0;  // 1, 2 or 3 (LM-63); 0 when mode is NONE
  std::vector<double> angles_deg;
  std::vector<double> factors;
};

// An LM-63 file as written: every value kept, so that write_ies reproduces it.
struct IesFile {
  std::string file;    // where it was read from, for messages
  std::string format;  // the first line ("IESNA:LM-63-2002", "IESNA91", ...); "" for LM-63-1986
  int year = 1986;     // 1986, 1991, 1995, 2002 or 2019
  std::vector<std::string> label_lines;  // keyword ([KEY] value) and label lines, verbatim
  IesTilt tilt;
  int lamp_count = 1;
  double lumens_per_lamp = -1;  // -1: absolute photometry
  double candela_multiplier = 1;
  int photometric_type = 1;  // 1 = C, 2 = B, 3 = A
  int units_type = 2;        // 1 = feet, 2 = metres
  // luminous opening (LM-63-2002 table 1): negative values describe round, elliptical
  // and spherical shapes, so any sign is valid.
  double width = 0, length = 0, height = 0;
  double ballast_factor = 1;
  double ballast_lamp_factor = 1;  // LM-63-1986 to -1995; "future use" from 2002 on
  double input_watts = 0;
  std::vector<double> vertical_deg;
  std::vector<double> horizontal_deg;
  std::vector<std::vector<double>> candela;  // [horizontal][vertical], as written

  bool absolute() const { return lumens_per_lamp == -1; }
  // returns the value of the first [key] line, or "".
  std::string keyword(const std::string& key) const;
  // returns the factor all candela values are multiplied by: the candela multiplier,
  // the ballast factor and, before LM-63-2002, the ballast-lamp photometric factor.
  double scale() const;
};

// parses LM-63 text read from file (the name is used in messages and to find a TILT
// file). Throws InputError(file, "line N", what is wrong).
IesFile parse_ies(const std::string& text, const std::filesystem::path& file);

// reads and parses the LM-63 file at path.
IesFile read_ies(const std::filesystem::path& path);

// returns the grid of candela values the file describes (values times scale()).
// Types B and A keep their own angles; TableDistribution maps them to C-gamma.
PhotometricGrid candela_grid(const IesFile& ies);

// writes ies as LM-63 text that parse_ies reads back to the same values. A TILT file
// is written inline as TILT=INCLUDE, so the output stands alone.
void write_ies(std::ostream& out, const IesFile& ies);

// reads the file at path and builds its distribution, candela times multiplier.
std::shared_ptr<const TableDistribution> load_ies(const std::filesystem::path& path,
                                                  Interpolation interpolation,
                                                  double multiplier = 1);

// returns a type C IesFile (LM-63-2002, absolute photometry) holding grid, for
// writing distributions that did not come from an LM-63 file.
IesFile ies_from_grid(const PhotometricGrid& grid, const std::vector<std::string>& label_lines);

}  // namespace penumbra::photometry
