#pragma once
// Reading an area light (DESIGN.md, "Scene file"; docs/area-sources.md): a planar convex
// Lambertian polygon with its luminance, or the exitance or luminous flux it implies.

#include "json_cursor.h"
#include "penumbra/scene/scene.h"

namespace penumbra::detail {

// reads {"area": [[x,y,z], ...], "luminance" | "exitance" | "lumens": v, "two_sided": b}.
// Fails at the offending path when the polygon is not planar, not convex, has repeated
// points or no area, or when not exactly one of the three quantities is given.
AreaLight read_area_light(const JsonCursor& cursor);

}  // namespace penumbra::detail
