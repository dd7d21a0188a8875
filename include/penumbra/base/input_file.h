#pragma once
// The files penumbra reads, and the limits on them (docs/reliability.md, "Limits"): a file
// must exist, be a regular file (not a directory, a device such as /dev/zero, or a pipe)
// and be no larger than the limit for its kind, which is checked before anything is
// allocated for its content. Every refusal is an InputError naming the file.

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace penumbra {

// The largest file of each kind, in bytes. Each is far above any real file of its kind (the
// largest real ones we know are in docs/reliability.md) and keeps the memory of reading it
// within a few times its size.
namespace file_limits {
inline constexpr std::uintmax_t scene = std::uintmax_t{256} << 20;       // scene JSON
inline constexpr std::uintmax_t photometric = std::uintmax_t{16} << 20;  // IES, EULUMDAT
inline constexpr std::uintmax_t patches = std::uintmax_t{256} << 20;     // .bpt
inline constexpr std::uintmax_t model = std::uintmax_t{4} << 30;         // meshes (Assimp)
inline constexpr std::uintmax_t table = std::uintmax_t{1} << 30;         // CSV of points
inline constexpr std::uintmax_t document = std::uintmax_t{4} << 30;      // JSON we wrote
inline constexpr std::uintmax_t basis = std::uintmax_t{64} << 30;        // .pbl
}  // namespace file_limits

// The deepest nesting of arrays and objects a JSON input may have (scene files, lighting
// files, golden documents, a basis file's header). Scene files nest 5 deep.
inline constexpr int max_json_depth = 64;

// checks that path names a regular file of at most limit bytes; what names the kind of file
// in messages ("scene file"). Returns its size.
std::uintmax_t check_input_file(const std::filesystem::path& path, const std::string& what,
                                std::uintmax_t limit);

// returns the content of the file at path after check_input_file.
std::string read_input_file(const std::filesystem::path& path, const std::string& what,
                            std::uintmax_t limit);

// parses JSON text read from file (a name for messages), refusing arrays and objects nested
// deeper than max_json_depth (copying or printing such a value would exhaust the stack).
// Throws InputError naming the file (and the line and column of a syntax error).
nlohmann::json parse_input_json(const std::string& text, const std::string& file);

}  // namespace penumbra
