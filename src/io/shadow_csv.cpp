#include <iomanip>

#include "penumbra/io/shadow_drawing.h"

namespace penumbra::io {

namespace {

// quotes a CSV field when it holds a separator, quote or line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

void write_shadow_csv(std::ostream& out, const nlohmann::json& document) {
  out << "object,face,light,face_area,shadow_area,lit_area,shadow_percent,faces_away,"
         "beyond_range,occluders,umbra_area,penumbra_area,joint_occlusion\n";
  out << std::setprecision(12);
  for (const auto& face : document.at("faces")) {
    const double area = face.at("area");
    for (const auto& light : face.at("lights")) {
      const bool beyond = light.value("beyond_range", false);
      out << csv_field(face.at("object")) << "," << face.at("face").get<int>() << ","
          << csv_field(light.at("light")) << "," << area << ",";
      if (beyond) {
        out << ",,,";
      } else {
        const double shadow = light.at("shadow").at("area");
        const double lit = light.at("lit").at("area");
        out << shadow << "," << lit << "," << (area > 0 ? 100 * shadow / area : 0.0) << ",";
      }
      out << (light.at("faces_away").get<bool>() ? "true" : "false") << ","
          << (beyond ? "true" : "false") << ",";
      std::string names;
      if (!beyond)
        for (const auto& occluder : light.at("occluders"))
          names += (names.empty() ? "" : " ") + occluder.at("object").get<std::string>();
      out << csv_field(names) << ",";
      // Added at the end (columns are found by name): umbra and penumbra areas.
      if (beyond)
        out << ",,";
      else
        out << light.at("umbra").at("area").get<double>() << ","
            << light.at("penumbra").at("area").get<double>() << ",";
      out << (light.value("joint_occlusion", false) ? "true" : "false") << "\n";
    }
  }
}

}  // namespace penumbra::io
