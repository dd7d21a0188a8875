#include "penumbra/scene/object_selection.h"

#include <fnmatch.h>

#include "penumbra/base/input_error.h"

namespace penumbra {

std::vector<std::size_t> select_objects(const Scene& scene, const std::string& patterns,
                                        const std::string& option) {
  std::vector<std::string> list;
  for (std::size_t start = 0;;) {
    const std::size_t comma = patterns.find(',', start);
    list.push_back(patterns.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  std::vector<char> chosen(scene.objects.size(), 0);
  for (const std::string& pattern : list) {
    if (pattern.empty()) throw InputError("", option, "an empty object name in '" + patterns + "'");
    bool matched = false;
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
      if (fnmatch(pattern.c_str(), scene.objects[k].face_owner().c_str(), 0) == 0) {
        chosen[k] = 1;
        matched = true;
      }
    if (!matched)
      throw InputError(scene.file.string(), option, "no object matches '" + pattern + "'");
  }
  std::vector<std::size_t> selected;
  for (std::size_t k = 0; k < chosen.size(); ++k)
    if (chosen[k]) selected.push_back(k);
  return selected;
}

}  // namespace penumbra
