#pragma once
// The photometric frame of a point source in the world: its illumination axis
// (gamma = 0) and its C = 0 reference direction c0 (scene keys `axis`, `c0`).
//
// A world direction d has gamma = angle(d, axis) and C measured from c0 toward
// c90 = c0 x axis: counter-clockwise as seen from behind the lamp looking along the
// axis (for a downlight with axis (0,0,-1) and c0 = +x, C = 90 is +y: counter-clockwise
// seen from above). This is LM-63 type C (C = 0 along the luminaire's length, C = 90
// to its left seen from above) and EULUMDAT.

#include "penumbra/base/vec3d.h"
#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry {

// returns the photometric angles of direction (any length > 0). Preconditions: axis
// and c0 are unit vectors, orthogonal to each other.
PhotometricDirection photometric_angles(const Vec3d& axis, const Vec3d& c0, const Vec3d& direction);

// returns the unit world direction of the photometric angles (the inverse).
Vec3d world_direction(const Vec3d& axis, const Vec3d& c0, const PhotometricDirection& angles);

// returns the intensity in candela that distribution, oriented by axis and c0, sends
// toward the world direction.
double intensity_toward(const Distribution& distribution, const Vec3d& axis, const Vec3d& c0,
                        const Vec3d& direction);

}  // namespace penumbra::photometry
