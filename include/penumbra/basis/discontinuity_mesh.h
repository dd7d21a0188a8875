#pragma once
// Discontinuity meshing for the radiosity mesh (issue #18; docs/basis.md, "Discontinuity
// meshing"; Heckbert 1992, Lischinski et al. 1992): the lines across which a light's direct
// illuminance jumps on a face are the edges of its exact shadow regions (and, for a tube, of
// its umbrae, where the slope jumps). The mesh is cut along them (patch_mesh.h, MeshBreaks),
// so relit images and the browser tool show a sharp shadow edge where Gouraud shading over a
// uniform grid ramps across a whole patch.
//
// A point lamp's shadows depend on its position only: re-aiming it or changing its
// distribution (relight --aim, --lid; the browser's controls) leaves the mesh exact. The sun's
// shadows depend on its direction, fixed in a basis.

#include "penumbra/basis/patch_mesh.h"

namespace penumbra::basis {

// returns the exact shadow (and umbra) regions of every light of scene on every face, as
// breaks for PatchMesh::subdivide: compute_shadows with the mesh's pieces kept apart and the
// sphere of lighting of `penumbra shadows`. A light whose shadows compute_shadows refuses (a
// tube touching an occluder) adds no breaks.
MeshBreaks shadow_breaks(const Scene& scene, bool parallel = true);

}  // namespace penumbra::basis
