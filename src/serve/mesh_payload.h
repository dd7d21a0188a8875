#pragma once
// The binary bodies of the API (docs/serve.md, "Binary formats"): little-endian, 4-byte
// words, so that the page reads them as typed arrays without copying.

#include <string>

#include "penumbra/basis/patch_mesh.h"
#include "penumbra/serve/lighting_session.h"

namespace penumbra::serve {

// returns the mesh for drawing and picking:
//   u32 vertices V, u32 triangles T, u32 patches P, u32 0 (reserved)
//   f32 positions [V x 3]
//   u32 triangle vertex indices [T x 3]  (the patches' fans, counter-clockwise outside)
//   u32 patch of each triangle [T]       (the ID buffer's values, section 4.2)
//   f32 patch centre and unit normal [P x 6]
//   u32 object index of each patch [P]
std::string mesh_payload(const basis::PatchMesh& mesh);

// returns the relit values: f32 luminance RGB per vertex [V x 3] (cd/m^2), f32 lux per
// vertex [V].
std::string relit_payload(const RelitScene& relit);

// returns an edit's answer with its relit values, one round trip instead of two: u32 byte
// length L of the JSON, the JSON (UTF-8) padded with spaces to a multiple of 4 bytes, then
// relit_payload(relit).
std::string edited_payload(const std::string& json, const RelitScene& relit);

}  // namespace penumbra::serve
