#pragma once
// Tabulated luminous intensity distributions: the paper's rotationally symmetric
// curves given every few degrees (Nishita 1985 section 3.1) and full photometric
// grids of asymmetric luminaires (LM-63 types C, B and A; EULUMDAT C-gamma).

#include <memory>
#include <optional>
#include <vector>

#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry {

// How intensities between the tabulated gamma angles are found.
enum class Interpolation {
  // linear in the angle gamma (the default).
  linear,
  // Nishita 1985 section 3.1, eq. (1) with the cosine approximation of t: linear in
  // cos(gamma), t = (cos g - cos g_i) / (cos g_i+1 - cos g_i). Differs from linear near
  // gamma = 0 and 180 degrees; docs/photometry.md gives the error.
  cosine,
};

// The goniometer system of a grid (LM-63 photometric types 1, 2, 3).
enum class PhotometricType {
  c,  // vertical polar axis: blocks are C planes, values run over gamma
  b,  // horizontal polar axis (floodlights): blocks are lateral angles H, values over V
  a,  // vertical polar axis, elevation angles (automotive): blocks are H, values over V
};

// A measured grid as a photometric file stores it, candela already scaled.
// candela[h][v] is the intensity at horizontal angle horizontal_deg[h] and vertical
// angle vertical_deg[v]; both lists strictly increase.
struct PhotometricGrid {
  PhotometricType type = PhotometricType::c;
  // type C: the C angles as stored, which also fix the symmetry (LM-63): {0} axial,
  // 0..90 quadrant, 0..180 bilateral to C0-C180, 90..270 bilateral to C90-C270,
  // 0..360 (or 0..<360, closed periodically) none. Types A and B: -90..90, or 0..90
  // for a laterally symmetric luminaire.
  std::vector<double> horizontal_deg;
  // type C: gamma angles within 0..180 (0-90, 0-180, 90-180 or any sub-range; outside
  // it the intensity is zero). Types A and B: -90..90 or a sub-range.
  std::vector<double> vertical_deg;
  std::vector<std::vector<double>> candela;
};

// A distribution interpolated bilinearly in its grid (gamma optionally by eq. (1)).
class TableDistribution final : public Distribution {
 public:
  // builds the distribution of grid. Precondition: the grid is well formed (the
  // parsers check files and report InputError; programming errors throw
  // std::invalid_argument). Cosine interpolation requires a type C grid.
  TableDistribution(PhotometricGrid grid, Interpolation interpolation);

  double intensity(double gamma, double c) const override;
  double max_intensity() const override { return max_candela_; }
  PhotometricDirection max_direction() const override { return max_direction_; }
  // integrates the interpolant exactly, cell by cell (closed forms of the integrals of
  // a linear function times sin or cos over each interval).
  double flux() const override;
  Symmetry symmetry() const override { return symmetry_; }

  // returns the grid as it was given.
  const PhotometricGrid& grid() const { return grid_; }
  Interpolation interpolation() const { return interpolation_; }

 private:
  // returns the intensity at native grid angles (radians).
  double native(double horizontal, double vertical) const;
  double along_vertical(std::size_t block, std::size_t i, double vertical,
                        double cos_vertical) const;

  PhotometricGrid grid_;
  Interpolation interpolation_;
  Symmetry symmetry_;
  // The grid unfolded by its symmetry: horizontal angles in radians covering the whole
  // range (type C: 0..2 pi inclusive), with the index of the stored block each uses.
  std::vector<double> horizontal_;
  std::vector<std::size_t> block_of_;
  std::vector<double> vertical_;
  // whether the table reaches the end of the physical range on each side.
  bool vertical_open_low_ = false, vertical_open_high_ = false;
  bool horizontal_open_low_ = false, horizontal_open_high_ = false;
  // Eq. (1)'s two look-up tables: cos g_i and 1 / (cos g_i+1 - cos g_i).
  std::vector<double> cos_vertical_;
  std::vector<double> inverse_cos_step_;
  double max_candela_ = 0;
  PhotometricDirection max_direction_;
};

// builds a rotationally symmetric distribution from gamma angles (degrees, strictly
// increasing within 0..180) and their intensities: the paper's Fig. 1 curve.
std::shared_ptr<const TableDistribution> make_axial_table(const std::vector<double>& gamma_deg,
                                                          const std::vector<double>& candela,
                                                          Interpolation interpolation);

// returns the symmetry LM-63 gives a grid's horizontal angles (see PhotometricGrid),
// or nullopt when the range is not one the format allows.
std::optional<Symmetry> horizontal_symmetry(const std::vector<double>& horizontal_deg,
                                            PhotometricType type);

}  // namespace penumbra::photometry
