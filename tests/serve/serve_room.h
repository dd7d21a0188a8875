#pragma once
// The serve tests' scene: fixtures/scenes/serve-room.json, a closed room with a table, a
// cos^2 downlight and a tabulated spot, cut into 0.5 m patches; its basis luminances are
// computed once per test process, at degree 4 (enough for cos^2, and quick).

#include "penumbra/basis/basis_luminances.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/scene.h"
#include "support/fixtures.h"

namespace penumbra::test {

inline constexpr int serve_room_degree = 4;

inline const Scene& serve_room_scene() {
  static const Scene scene = load_scene(fixture("scenes/serve-room.json"));
  return scene;
}

inline const basis::BasisLuminances& serve_room_basis() {
  static const basis::BasisLuminances basis = [] {
    basis::BasisOptions options;
    options.degree = serve_room_degree;
    options.patch_size = 0.5;
    return basis::compute_basis(serve_room_scene(), options);
  }();
  return basis;
}

}  // namespace penumbra::test
