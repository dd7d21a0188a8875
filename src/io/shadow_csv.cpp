#include "penumbra/base/csv.h"
#include "penumbra/io/shadow_drawing.h"
#include "penumbra/shadow/exact_umbra.h"

namespace penumbra::io {

void ShadowCsvWriter::begin(const nlohmann::json&, std::size_t) {
  csv_ = std::make_unique<CsvWriter>(
      out_,
      std::vector<std::string>{"object", "face", "light", "face_area", "shadow_area", "lit_area",
                               "shadow_percent", "faces_away", "beyond_range", "occluders",
                               "umbra_area", "penumbra_area", "joint_occlusion"});
}

void ShadowCsvWriter::faces(const ShadowFaceBlock& block) {
  CsvWriter& csv = *csv_;
  const Scene& scene = block.scene();
  const ShadowResult& result = block.result();
  for (std::size_t r = block.first(); r < block.first() + block.size(); ++r) {
    const ReceivingFace face = receiving_face(scene, result, r);
    // The areas the JSON document gives (world_area of each region).
    const double area = world_area(face.area, face.frame);
    for (const LightShadows& light : result.lights) {
      const FaceShadow& shadow = light.faces[r];
      csv.text(face.object).integer(static_cast<long long>(face.face));
      csv.text(scene.lights[light.light].name).number(area);
      if (shadow.beyond_range) {
        csv.blank().blank().blank();
      } else {
        const double shadowed = world_area(shadow.shadow, face.frame);
        csv.number(shadowed).number(world_area(shadow.lit, face.frame));
        csv.number(area > 0 ? 100 * shadowed / area : 0.0);
      }
      csv.boolean(shadow.faces_away).boolean(shadow.beyond_range);
      // Occluder names separated by spaces in one field.
      std::string names;
      for (const OccluderShadow& occluder : shadow.occluders)
        names += (names.empty() ? "" : " ") + scene.objects[occluder.occluder].name;
      csv.text(names);
      if (shadow.beyond_range)
        csv.blank().blank();
      else if (shadow.curved)  // the exact umbra with joint parts (--joint-umbrae)
        csv.number(world_area(shadow.curved->area(), face.frame))
            .number(world_area(shadow.curved->penumbra_area(), face.frame));
      else
        csv.number(world_area(shadow.extended ? shadow.umbra : shadow.shadow, face.frame))
            .number(shadow.extended ? world_area(shadow.penumbra, face.frame) : 0.0);
      csv.boolean(shadow.joint_occlusion);
      csv.end_row();
    }
  }
}

}  // namespace penumbra::io
