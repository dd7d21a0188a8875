#pragma once
// The basis file (.pbl): basis luminances written once by `penumbra basis` and read by
// `penumbra relight` and `penumbra serve` (docs/basis.md, "Basis file").
//
// Layout, little-endian:
//   8 bytes   magic "PNBRPBL1"
//   8 bytes   header length h (uint64)
//   h bytes   header: UTF-8 JSON (format version, scene file, options, timings, camera,
//             lights with their columns, distributions and compression, the array table)
//   arrays    raw, back to back, in the order of header["arrays"], each
//             {"name", "type": "f32"|"f64"|"u32", "rows", "cols"}, row-major.
// The patch mesh (vertices, patches with their vertex lists) and every light's blocks are
// arrays. Reading checks the magic, the version, every size against the file's length,
// and that every index is in range, and names the file and the field on error.

#include <filesystem>

#include "penumbra/basis/basis_luminances.h"

namespace penumbra::basis {

// writes basis to path (atomically: whole or not at all). Throws InputError.
void write_basis(const std::filesystem::path& path, const BasisLuminances& basis);

// reads a basis file. Throws InputError naming the file and the field.
BasisLuminances read_basis(const std::filesystem::path& path);

}  // namespace penumbra::basis
