#pragma once
// The page's files by URL path: only the embedded files exist, so no request can reach
// the file system; a path that tries to climb out (.., backslashes, NUL) is refused.

#include <optional>
#include <string>
#include <string_view>

#include "web_assets.h"

namespace penumbra::serve {

enum class PathCheck { ok, not_found, forbidden };

struct StaticFile {
  PathCheck check = PathCheck::not_found;
  const WebAsset* asset = nullptr;
  std::string mime_type;
};

// looks up a decoded URL path ("/" is index.html).
StaticFile find_static_file(std::string_view path);

}  // namespace penumbra::serve
