#include "penumbra/shadow/shadow_map.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <numeric>

#include "back_pieces.h"
#include "mesh_face_shadow.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/parallel.h"
#include "penumbra/shadow/area_face_shadow.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "penumbra/shadow/shadow_polygon.h"
#include "penumbra/visibility/lighting_sphere.h"
#include "penumbra/visibility/swept_region.h"
#include "receiver_clip.h"

namespace penumbra {
namespace {

std::optional<LightPosition> position_of(const Light& light) {
  if (const auto* point = std::get_if<PointLight>(&light.source))
    return LightPosition::at(to_exact(point->position));
  if (const auto* sun = std::get_if<DirectionalLight>(&light.source))
    return LightPosition::toward(to_exact_vector(sun->direction));
  return std::nullopt;
}

// The threshold illuminance of the partial sphere of lighting of photometry/figures.h
// (Nishita section 3.1): light below range_fraction of the display's full scale is
// insignificant. 0: no range culling.
double range_threshold(const ShadowOptions& options) {
  return options.range_lux ? *options.range_lux : options.range_fraction * options.full_scale_lux;
}

// The per-light work shared by point, directional and linear sources: the receivers, the
// objects, their canonical rank and the options.
class LightShading {
 public:
  LightShading(const Scene& scene, const std::vector<Receiver>& receivers,
               const std::vector<std::size_t>& rank, std::size_t light_index,
               const ShadowOptions& options)
      : scene_(scene), receivers_(receivers), rank_(rank), options_(options) {
    result_.light = light_index;
    result_.faces.resize(receivers.size());
    result_.stats.faces = receivers.size();
    result_.stats.pairs_possible = receivers.size() * (scene.objects.size() - 1);
    for (const Object& object : scene.objects) solids_.push_back(&object.solid);
  }

  const Light& light() const { return scene_.lights[result_.light]; }
  const Face& face(const Receiver& receiver) const {
    return scene_.objects[receiver.object].solid.faces()[receiver.face];
  }

  // Culling (Nishita 1985 section 3.1): calls away(r) for each receiver r wholly unlit
  // because it faces away, marks those outside the sphere of lighting, and keeps the rest
  // as the active ones to compute.
  template <class FacesAway>
  void cull(const std::optional<LightingSphere>& sphere, bool extended, FacesAway&& away) {
    if (sphere) result_.stats.radius = sphere->radius();
    std::vector<std::size_t> far;
    for (std::size_t r = 0; r < receivers_.size(); ++r) {
      const Face& receiving = face(receivers_[r]);
      if (away(r, receiving)) continue;
      if (sphere && sphere->beyond(receiving))
        far.push_back(r);
      else
        active_.push_back(r);
    }
    // The pieces of a mesh face are computed alike: all of them when one is within range.
    std::vector<char> face_active(scene_.mesh_faces.size(), 0);
    for (std::size_t r : active_) {
      const std::size_t m = mesh_face_of(receivers_[r]);
      if (m != kNoMeshFace) face_active[m] = 1;
    }
    for (std::size_t r : far) {
      const std::size_t m = mesh_face_of(receivers_[r]);
      if (m != kNoMeshFace && face_active[m]) {
        active_.push_back(r);
        continue;
      }
      result_.faces[r].beyond_range = true;
      result_.faces[r].extended = extended;
      ++result_.stats.beyond_range;
      far_.push_back(r);
    }
    std::sort(active_.begin(), active_.end());
  }

  std::size_t mesh_face_of(const Receiver& receiver) const {
    const Object& object = scene_.objects[receiver.object];
    return object.mesh_faces.empty() ? kNoMeshFace : object.mesh_faces[receiver.face];
  }

  // returns, for each receiver slot in slots, its candidate occluders: the broad phase's
  // (through candidates_of) or every other object.
  template <class Candidates>
  std::vector<std::vector<std::size_t>> candidates(const std::vector<std::size_t>& slots,
                                                   Candidates&& candidates_of) const {
    std::vector<Receiver> chosen;
    for (std::size_t r : slots) chosen.push_back(receivers_[r]);
    if (options_.broad_phase) return candidates_of(solids_, chosen);
    std::vector<std::vector<std::size_t>> all(chosen.size());
    for (std::size_t a = 0; a < chosen.size(); ++a)
      for (std::size_t o = 0; o < scene_.objects.size(); ++o)
        if (o != chosen[a].object) all[a].push_back(o);
    return all;
  }

  // puts each active receiver's occluders in canonical order (by object name: rank),
  // whatever the input order, and counts the pairs tested.
  void rank(std::vector<std::vector<std::size_t>>& candidates) {
    for (auto& list : candidates) {
      std::sort(list.begin(), list.end(),
                [&](std::size_t a, std::size_t b) { return rank_[a] < rank_[b]; });
      result_.stats.pairs_tested += list.size();
    }
  }

  // With options.occluders_beyond_range: lists for each face beyond the sphere of lighting
  // the objects that may shadow it from the source q1 q2 (q1 = q2 for a point source).
  template <class Candidates>
  void list_far_occluders(const Point3& q1, const Point3& q2, Candidates&& candidates_of) {
    if (!options_.occluders_beyond_range || far_.empty()) return;
    const auto far_candidates = candidates(far_, candidates_of);
    for_each_index(far_.size(), options_.parallel, [&](std::size_t a) {
      const std::size_t r = far_[a];
      const SweptRegion swept(face(receivers_[r]), q1, q2);
      for (std::size_t o : far_candidates[a])
        if (!swept.separated_from(*solids_[o])) result_.faces[r].possible_occluders.push_back(o);
    });
  }

  // returns the ranked candidate occluders of each active receiver (see shade).
  template <class Candidates>
  std::vector<std::vector<std::size_t>> active_candidates(Candidates&& candidates_of) {
    auto candidates_of_active = candidates(active_, candidates_of);
    rank(candidates_of_active);
    return candidates_of_active;
  }

  // computes shade(receiver, occluders) for every active receiver, in parallel, with its
  // candidates from active_candidates, and finishes the statistics.
  template <class Shade>
  LightShadows shade(const std::vector<std::vector<std::size_t>>& candidates, Shade&& shade_one) {
    for_each_index(active_.size(), options_.parallel, [&](std::size_t a) {
      result_.faces[active_[a]] = shade_one(receivers_[active_[a]], candidates[a]);
    });
    for (const FaceShadow& face : result_.faces) {
      result_.stats.faces_away += face.faces_away;
      result_.stats.pairs_shadowing += face.occluders.size();
    }
    return std::move(result_);
  }

  LightShadows& result() { return result_; }

 private:
  const Scene& scene_;
  const std::vector<Receiver>& receivers_;
  const std::vector<std::size_t>& rank_;
  const ShadowOptions& options_;
  std::vector<const ConvexPolyhedron*> solids_;
  LightShadows result_;
  std::vector<std::size_t> active_, far_;  // receiver slots to compute / beyond range
};

// returns make(solid) for each object that is a candidate occluder of some receiver (a
// default T for the others), made across threads.
template <class T, class Make>
std::vector<T> per_candidate(const Scene& scene,
                             const std::vector<std::vector<std::size_t>>& candidates, bool parallel,
                             Make make) {
  std::vector<char> needed(scene.objects.size(), 0);
  for (const auto& list : candidates)
    for (std::size_t occluder : list) needed[occluder] = 1;
  std::vector<T> made(scene.objects.size());
  for_each_index(scene.objects.size(), parallel, [&](std::size_t o) {
    if (needed[o]) made[o] = make(scene.objects[o].solid);
  });
  return made;
}

// removes from each face's candidates the occluders marked in back (back_pieces.h).
void drop_back_pieces(std::vector<std::vector<std::size_t>>& candidates,
                      const std::vector<char>& back) {
  for (auto& list : candidates)
    list.erase(
        std::remove_if(list.begin(), list.end(), [&](std::size_t o) { return back[o] != 0; }),
        list.end());
}

LightShadows shade_scene(const Scene& scene, const std::vector<Receiver>& receivers,
                         const std::vector<std::size_t>& rank, std::size_t light_index,
                         const ShadowOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LightShading shading(scene, receivers, rank, light_index, options);
  const LightPosition position = *position_of(shading.light());
  std::optional<LightingSphere> sphere;
  if (const auto* point = std::get_if<PointLight>(&shading.light().source))
    if (range_threshold(options) > 0)
      sphere = LightingSphere::absolute(position.point(), point->distribution->max_intensity(),
                                        range_threshold(options));

  // Faces turned away are wholly unlit (Nishita 1985 section 3.1); the sun has no sphere.
  shading.cull(sphere, false, [&](std::size_t r, const Face& face) {
    if (!faces_away(face, position)) return false;
    shading.result().faces[r] = unlit_face(face);
    return true;
  });
  const auto candidates_of = [&](const std::vector<const ConvexPolyhedron*>& solids,
                                 const std::vector<Receiver>& chosen) {
    return candidate_occluders(solids, chosen, position);
  };
  if (!position.at_infinity())
    shading.list_far_occluders(position.point(), position.point(), candidates_of);

  auto candidates = shading.active_candidates(candidates_of);
  // Pieces of closed parts turned away from the light add no shadow (back_pieces.h).
  drop_back_pieces(candidates, detail::back_pieces(scene, position));
  // The shadow volume of each occluder depends only on the light: build it once.
  const auto volumes = per_candidate<std::vector<Plane3>>(
      scene, candidates, options.parallel,
      [&](const ConvexPolyhedron& solid) { return shadow_volume(solid, position); });
  LightShadows result = shading.shade(candidates, [&](const Receiver& receiver,
                                                      const std::vector<std::size_t>& occluders) {
    const Face& face = shading.face(receiver);
    if (occluders.empty()) return unite_shadows(face, {}, options.lit_parts);
    // The face's ring and frame, exact and in intervals, once for all its occluders.
    const detail::ReceiverClip clip(face);
    // A face under many occluders (a ground slab under a city) clips them across
    // threads; the shadows keep the occluders' order.
    std::vector<std::optional<Ring2>> polygons(occluders.size());
    for_each_index(occluders.size(), options.parallel && occluders.size() > 64, [&](std::size_t k) {
      polygons[k] =
          detail::shadow_polygon(scene.objects[occluders[k]].solid, volumes[occluders[k]], clip);
    });
    std::vector<OccluderShadow> shadows;
    for (std::size_t k = 0; k < occluders.size(); ++k)
      if (polygons[k]) shadows.push_back({occluders[k], std::move(*polygons[k])});
    return unite_shadows(face, std::move(shadows), options.lit_parts);
  });
  result.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// The end points of a tube in lexicographic order: the loops (which start at C1) must not
// depend on the order the file lists them in.
std::pair<Point3, Point3> tube_ends(const LinearLight& tube) {
  Point3 q1 = to_exact(tube.start), q2 = to_exact(tube.end);
  if (CGAL::compare_xyz(q2, q1) == CGAL::SMALLER) std::swap(q1, q2);
  return {q1, q2};
}

// The same for a linear source (Nishita 1985 section 4.1, docs/linear-shadows.md),
// culled by a sphere around the tube's capsule of lighting.
LightShadows shade_linear(const Scene& scene, const std::vector<Receiver>& receivers,
                          const std::vector<std::size_t>& rank, std::size_t light_index,
                          const ShadowOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LightShading shading(scene, receivers, rank, light_index, options);
  const Light& light = shading.light();
  const auto& tube = std::get<LinearLight>(light.source);
  const std::pair<Point3, Point3> ends = tube_ends(tube);
  const Point3 &q1 = ends.first, &q2 = ends.second;

  std::optional<LightingSphere> sphere;
  if (range_threshold(options) > 0)
    sphere =
        LightingSphere::around_segment(q1, q2, tube.candela_per_metre, range_threshold(options));
  // linear_face_shadow decides faces turned away itself (the S3 clipping of Fig. 7).
  shading.cull(sphere, true, [](std::size_t, const Face&) { return false; });
  const auto candidates_of = [&](const std::vector<const ConvexPolyhedron*>& solids,
                                 const std::vector<Receiver>& chosen) {
    return candidate_occluders(solids, chosen, q1, q2);
  };
  shading.list_far_occluders(q1, q2, candidates_of);

  auto candidates = shading.active_candidates(candidates_of);
  // Pieces of closed parts turned away from the whole tube change neither the shadow nor the
  // exact umbra (back_pieces.h), but a piece turned away may hide the tube alone where the
  // others hide it only together: the single umbrae keep them, the exact umbrae do not.
  if (options.joint_umbrae) drop_back_pieces(candidates, detail::back_pieces(scene, q1, q2));
  // What each occluder does under the whole tube depends only on the tube: made once
  // (the faces whose plane cuts the tube make their own, Fig. 7 S3).
  const auto whole = per_candidate<SourceOcclusion>(
      scene, candidates, options.parallel,
      [&](const ConvexPolyhedron& solid) { return source_occlusion(solid, q1, q2); });
  // The occluders of joint umbrae, prepared once each for all the faces they shadow.
  std::vector<std::shared_ptr<const UmbraSolid>> prepared;
  std::unique_ptr<std::once_flag[]> preparing;
  if (options.joint_umbrae) {
    prepared.resize(scene.objects.size());
    preparing = std::make_unique<std::once_flag[]>(scene.objects.size());
  }
  LightShadows result = shading.shade(
      candidates, [&](const Receiver& receiver, const std::vector<std::size_t>& occluders_of) {
        std::vector<Occluder> occluders;
        for (std::size_t o : occluders_of)
          occluders.push_back({o, &scene.objects[o].solid, &whole[o]});
        try {
          const Face& face = shading.face(receiver);
          FaceShadow shadow = linear_face_shadow(face, q1, q2, std::move(occluders));
          if (options.joint_umbrae && shadow.joint_occlusion) {
            std::vector<UmbraOccluder> solids;
            for (const OccluderShadow& o : shadow.occluders) {
              const ConvexPolyhedron& solid = scene.objects[o.occluder].solid;
              std::call_once(preparing[o.occluder],
                             [&] { prepared[o.occluder] = prepare_umbra_solid(solid, q1, q2); });
              solids.push_back({&solid, o.polygon, o.umbra, prepared[o.occluder]});
            }
            // The flag now says that the umbra has joint parts; without them the straight
            // sets are the exact ones (DESIGN.md, "Shadow loops output").
            auto curved = joint_umbra(face, q1, q2, solids);
            shadow.joint_occlusion = curved && curved->joint();
            if (shadow.joint_occlusion)
              shadow.curved = std::make_shared<const ExactUmbra>(std::move(*curved));
          }
          return shadow;
        } catch (const std::domain_error&) {
          throw InputError(scene.file.string(), light.json_path,
                           "the linear source '" + light.name +
                               "' touches or passes through an object that shadows face " +
                               std::to_string(receiver.face) + " of '" +
                               scene.objects[receiver.object].name +
                               "' (or has an end in the plane of a flat one): not supported "
                               "(docs/linear-shadows.md)");
        }
      });
  result.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// The same for an area source (docs/area-sources.md). No sphere of lighting: an area source
// lights a room, every face of which is within range.
LightShadows shade_area(const Scene& scene, const std::vector<Receiver>& receivers,
                        const std::vector<std::size_t>& rank, std::size_t light_index,
                        const ShadowOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LightShading shading(scene, receivers, rank, light_index, options);
  const Light& light = shading.light();
  const auto& panel = std::get<AreaLight>(light.source);
  const Face& source = panel.polygon->faces()[panel.front];
  // area_face_shadow decides the faces that see none of the source itself.
  shading.cull(std::nullopt, true, [](std::size_t, const Face&) { return false; });
  const auto candidates = shading.active_candidates(
      [&](const std::vector<const ConvexPolyhedron*>& solids, const std::vector<Receiver>& chosen) {
        return candidate_occluders(solids, chosen, source.vertices);
      });
  // What each occluder does under the whole source: made once (the faces whose plane cuts
  // the source make their own).
  const auto whole = per_candidate<AreaOcclusion>(
      scene, candidates, options.parallel,
      [&](const ConvexPolyhedron& solid) { return area_occlusion(solid, source.vertices); });
  LightShadows result = shading.shade(
      candidates, [&](const Receiver& receiver, const std::vector<std::size_t>& occluders_of) {
        std::vector<AreaOccluder> occluders;
        for (std::size_t o : occluders_of)
          occluders.push_back({o, &scene.objects[o].solid, &whole[o]});
        try {
          return area_face_shadow(shading.face(receiver), source, panel.two_sided, occluders);
        } catch (const std::domain_error&) {
          throw InputError(scene.file.string(), light.json_path,
                           "the area source '" + light.name +
                               "' touches or passes through an object that shadows face " +
                               std::to_string(receiver.face) + " of '" +
                               scene.objects[receiver.object].name +
                               "': not supported (docs/area-sources.md)");
        }
      });
  result.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// returns the face as a region of its own frame when it has no holes and all its pieces are
// present (then a union of the pieces' regions that covers the face is this region, and
// unite_pieces need not compute it); nothing otherwise.
std::optional<Region2> whole_face(const MeshFace& face, std::size_t present) {
  if (!face.holes.empty() || present != face.pieces.size()) return std::nullopt;
  return canonical_region({Polygon2{canonical_ring(face.ring), {}}}, face.area);
}

// Documents report a mesh face once (docs/shadows.md, "Faces of real models"): the receivers
// that are pieces of one MeshFace become one slot, its shadow maps united from theirs, and the
// slots are put back in canonical order (by owner name, then face number).
void unite_mesh_faces(const Scene& scene, const std::vector<std::size_t>& rank,
                      const ShadowOptions& options, ShadowResult& result) {
  const std::size_t count = result.receivers.size();
  std::vector<std::size_t> slot_of_face(scene.mesh_faces.size(), kNoMeshFace);
  std::vector<std::vector<std::size_t>> members;  // per new slot, the old receivers
  std::vector<std::size_t> slot_face;             // per new slot, its MeshFace or kNoMeshFace
  for (std::size_t r = 0; r < count; ++r) {
    const Object& object = scene.objects[result.receivers[r].object];
    const std::size_t m =
        object.mesh_faces.empty() ? kNoMeshFace : object.mesh_faces[result.receivers[r].face];
    if (m != kNoMeshFace && slot_of_face[m] != kNoMeshFace) {
      members[slot_of_face[m]].push_back(r);
      continue;
    }
    if (m != kNoMeshFace) slot_of_face[m] = members.size();
    members.push_back({r});
    slot_face.push_back(m);
  }
  // Canonical order: the owner's name, then the face's number.
  const auto owner = [&](std::size_t slot) -> const std::string& {
    return slot_face[slot] != kNoMeshFace
               ? scene.mesh_faces[slot_face[slot]].part
               : scene.objects[result.receivers[members[slot][0]].object].name;
  };
  const auto number = [&](std::size_t slot) {
    return slot_face[slot] != kNoMeshFace ? scene.mesh_faces[slot_face[slot]].index
                                          : result.receivers[members[slot][0]].face;
  };
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const int c = owner(a).compare(owner(b));
    return c != 0 ? c < 0 : number(a) < number(b);
  });

  std::vector<Receiver> receivers;
  std::vector<std::size_t> mesh_faces;
  for (std::size_t slot : order) {
    receivers.push_back(result.receivers[members[slot][0]]);
    mesh_faces.push_back(slot_face[slot]);
  }
  for (LightShadows& light : result.lights) {
    std::vector<FaceShadow> faces(order.size());
    for_each_index(order.size(), true, [&](std::size_t k) {
      const std::size_t slot = order[k];
      if (slot_face[slot] == kNoMeshFace) {
        faces[k] = std::move(light.faces[members[slot][0]]);
        return;
      }
      const MeshFace& face = scene.mesh_faces[slot_face[slot]];
      if (face.pieces.size() == 1 && members[slot].size() == 1) {
        faces[k] = std::move(light.faces[members[slot][0]]);  // the piece is the face
        return;
      }
      std::vector<std::pair<const FaceShadow*, const FaceFrame*>> pieces;
      std::vector<const Face*> piece_faces;
      bool curved = false;
      for (std::size_t r : members[slot]) {
        const Receiver& piece = result.receivers[r];
        piece_faces.push_back(&scene.objects[piece.object].solid.faces()[piece.face]);
        pieces.push_back({&light.faces[r], &piece_faces.back()->frame});
        curved = curved || light.faces[r].curved;
      }
      faces[k] = detail::unite_pieces(pieces, face.frame, whole_face(face, members[slot].size()),
                                      options.lit_parts);
      if (options.joint_umbrae && curved) {
        // joint parts on some piece: the exact umbra of the whole face (issue #17)
        const auto [q1, q2] = tube_ends(std::get<LinearLight>(scene.lights[light.light].source));
        auto umbra = detail::mesh_face_umbra(scene, face, piece_faces, faces[k], q1, q2);
        faces[k].joint_occlusion = umbra->joint();
        if (faces[k].joint_occlusion) faces[k].curved = std::move(umbra);
      }
      std::stable_sort(faces[k].occluders.begin(), faces[k].occluders.end(),
                       [&](const OccluderShadow& a, const OccluderShadow& b) {
                         return rank[a.occluder] < rank[b.occluder];
                       });
    });
    light.faces = std::move(faces);
    light.stats.faces = order.size();
    light.stats.faces_away = 0;
    for (const FaceShadow& face : light.faces) light.stats.faces_away += face.faces_away;
  }
  result.receivers = std::move(receivers);
  result.mesh_faces = std::move(mesh_faces);
}

}  // namespace

std::vector<Receiver> faces_of_objects(const Scene& scene,
                                       const std::vector<std::size_t>& objects) {
  std::vector<Receiver> faces;
  for (std::size_t object : objects)
    for (std::size_t face = 0; face < scene.objects[object].solid.faces().size(); ++face)
      if (scene.objects[object].receives(face)) faces.push_back({object, face});
  return faces;
}

ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options) {
  ShadowResult result;
  // Canonical order: objects by name (names are unique), faces by canonical index.
  std::vector<std::size_t> by_name(scene.objects.size());
  std::iota(by_name.begin(), by_name.end(), 0);
  std::sort(by_name.begin(), by_name.end(), [&](std::size_t a, std::size_t b) {
    return scene.objects[a].name < scene.objects[b].name;
  });
  std::vector<std::size_t> rank(scene.objects.size());
  for (std::size_t k = 0; k < by_name.size(); ++k) rank[by_name[k]] = k;
  if (options.receivers) {
    for (const Receiver& receiver : *options.receivers)
      if (receiver.object >= scene.objects.size() ||
          receiver.face >= scene.objects[receiver.object].solid.faces().size())
        throw InputError(scene.file.string(), "objects",
                         "no receiving face " + std::to_string(receiver.face) + " of object " +
                             std::to_string(receiver.object));
    result.receivers = *options.receivers;
    std::sort(result.receivers.begin(), result.receivers.end(),
              [&](const Receiver& a, const Receiver& b) {
                return rank[a.object] != rank[b.object] ? rank[a.object] < rank[b.object]
                                                        : a.face < b.face;
              });
    result.receivers.erase(std::unique(result.receivers.begin(), result.receivers.end(),
                                       [](const Receiver& a, const Receiver& b) {
                                         return a.object == b.object && a.face == b.face;
                                       }),
                           result.receivers.end());
  } else {
    result.receivers = faces_of_objects(scene, by_name);
  }

  std::vector<std::size_t> lights;
  if (options.light) {
    const Light* light = scene.find_light(*options.light);
    if (!light)
      throw InputError(scene.file.string(), "lights",
                       "there is no light named '" + *options.light + "'");
    lights.push_back(static_cast<std::size_t>(light - scene.lights.data()));
  } else {
    for (std::size_t k = 0; k < scene.lights.size(); ++k) lights.push_back(k);
  }
  // Lights in name order, for the same reason as objects.
  std::sort(lights.begin(), lights.end(), [&](std::size_t a, std::size_t b) {
    return scene.lights[a].name < scene.lights[b].name;
  });
  // The lights are independent: computed side by side (each also parallel across faces),
  // which is what keeps both cores busy through the many suns of a sun study.
  result.lights.resize(lights.size());
  for_each_index(lights.size(), options.parallel && lights.size() > 1, [&](std::size_t k) {
    const std::size_t light = lights[k];
    const auto& source = scene.lights[light].source;
    result.lights[k] = position_of(scene.lights[light])
                           ? shade_scene(scene, result.receivers, rank, light, options)
                       : std::holds_alternative<AreaLight>(source)
                           ? shade_area(scene, result.receivers, rank, light, options)
                           : shade_linear(scene, result.receivers, rank, light, options);
  });
  if (options.unite_mesh_faces && !scene.mesh_faces.empty())
    unite_mesh_faces(scene, rank, options, result);
  return result;
}

ReceivingFace receiving_face(const Scene& scene, const ShadowResult& result, std::size_t r) {
  const std::size_t m = result.mesh_faces.empty() ? kNoMeshFace : result.mesh_faces[r];
  if (m != kNoMeshFace) {
    const MeshFace& face = scene.mesh_faces[m];
    return {face.part,  face.index, face.plane,  face.frame,
            face.outer, face.ring,  &face.holes, face.area};
  }
  const Object& object = scene.objects[result.receivers[r].object];
  const Face& face = object.solid.faces()[result.receivers[r].face];
  return {object.name,   result.receivers[r].face,
          face.plane,    face.frame,
          face.vertices, face.ring,
          nullptr,       face.area};
}

}  // namespace penumbra
