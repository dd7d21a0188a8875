#include "penumbra/base/csv.h"
#include "penumbra/io/shadow_drawing.h"

namespace penumbra::io {

void ShadowCsvWriter::begin(const nlohmann::json&, std::size_t) {
  csv_ = std::make_unique<CsvWriter>(
      out_,
      std::vector<std::string>{"object", "face", "light", "face_area", "shadow_area", "lit_area",
                               "shadow_percent", "faces_away", "beyond_range", "occluders",
                               "umbra_area", "penumbra_area", "joint_occlusion"});
}

void ShadowCsvWriter::face(const nlohmann::json& face) {
  CsvWriter& csv = *csv_;
  const double area = face.at("area");
  for (const auto& light : face.at("lights")) {
    const bool beyond = light.value("beyond_range", false);
    csv.text(face.at("object")).integer(face.at("face").get<int>()).text(light.at("light"));
    csv.number(area);
    if (beyond) {
      csv.blank().blank().blank();
    } else {
      const double shadow = light.at("shadow").at("area");
      csv.number(shadow).number(light.at("lit").at("area").get<double>());
      csv.number(area > 0 ? 100 * shadow / area : 0.0);
    }
    csv.boolean(light.at("faces_away").get<bool>()).boolean(beyond);
    // Occluder names separated by spaces in one field.
    std::string names;
    if (!beyond)
      for (const auto& occluder : light.at("occluders"))
        names += (names.empty() ? "" : " ") + occluder.at("object").get<std::string>();
    csv.text(names);
    if (beyond)
      csv.blank().blank();
    else
      csv.number(light.at("umbra").at("area").get<double>())
          .number(light.at("penumbra").at("area").get<double>());
    csv.boolean(light.value("joint_occlusion", false));
    csv.end_row();
  }
}

void write_shadow_csv(std::ostream& out, const nlohmann::json& document) {
  ShadowCsvWriter writer(out);
  feed_shadow_document(writer, document);
}

}  // namespace penumbra::io
