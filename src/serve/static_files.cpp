// The page's files by URL path (static_files.h).

#include "static_files.h"

namespace penumbra::serve {
namespace {

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::string mime_type_of(std::string_view path) {
  if (ends_with(path, ".html")) return "text/html; charset=utf-8";
  if (ends_with(path, ".js")) return "text/javascript; charset=utf-8";
  if (ends_with(path, ".css")) return "text/css; charset=utf-8";
  return "application/octet-stream";
}

// returns whether the path tries to leave the page's directory or is not a plain path.
bool is_traversal(std::string_view path) {
  if (path.find("..") != std::string_view::npos) return true;
  for (char c : path)
    if (c == '\\' || c == '\0' || c == ':' || static_cast<unsigned char>(c) < 0x20) return true;
  return path.find("//") != std::string_view::npos;
}

}  // namespace

StaticFile find_static_file(std::string_view path) {
  StaticFile file;
  if (path.empty() || path.front() != '/' || is_traversal(path)) {
    file.check = PathCheck::forbidden;
    return file;
  }
  const std::string_view relative = path == "/" ? std::string_view("index.html") : path.substr(1);
  for (const WebAsset& asset : web_assets())
    if (relative == asset.path) {
      file.check = PathCheck::ok;
      file.asset = &asset;
      file.mime_type = mime_type_of(relative);
      return file;
    }
  file.check = PathCheck::not_found;
  return file;
}

}  // namespace penumbra::serve
