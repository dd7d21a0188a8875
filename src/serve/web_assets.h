#pragma once
// The page's files (web/), embedded at build time by embed_web.cmake.

#include <cstddef>
#include <vector>

namespace penumbra::serve {

struct WebAsset {
  const char* path;  // relative to web/, e.g. "main.js"
  const char* data;
  std::size_t size;
};

// returns every embedded file of the page.
const std::vector<WebAsset>& web_assets();

}  // namespace penumbra::serve
