#pragma once
// One fuzz target (docs/reliability.md, "Fuzzing"): a function that feeds arbitrary bytes
// to one of penumbra's readers. Bad input must end in penumbra::InputError, the error the
// command line prints with exit status 2; anything else (another exception, a crash, a
// sanitizer report, a hang) is a bug.
//
// Each target file says PENUMBRA_FUZZ_TARGET(name) { ...body using data and size... }.
// Built with -DPENUMBRA_LIBFUZZER (scripts/fuzz, clang's -fsanitize=fuzzer) the body is
// libFuzzer's LLVMFuzzerTestOneInput; otherwise the target registers itself with the
// replay program (replay_main.cpp), which CTest runs over the kept corpus and every input
// that once failed (tests/fuzz/regressions/).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "penumbra/base/input_error.h"

namespace penumbra::fuzz {

using TargetFunction = void (*)(const std::uint8_t* data, std::size_t size);

// adds a target to the replay program's table; returns true.
bool register_target(const char* name, TargetFunction function);

// runs function on the bytes; InputError (a refusal, the expected answer to bad input) is
// swallowed, anything else propagates.
inline int run(TargetFunction function, const std::uint8_t* data, std::size_t size) {
  try {
    function(data, size);
  } catch (const InputError&) {
  }
  return 0;
}

// returns the bytes as text.
inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// writes the bytes to a file of this process's scratch directory with the given name (its
// extension chooses the reader) and returns its path. The directory is kept per process,
// so that parallel fuzzing jobs do not share files.
std::filesystem::path scratch_file(const std::string& name, const std::uint8_t* data,
                                   std::size_t size);

}  // namespace penumbra::fuzz

#ifdef PENUMBRA_LIBFUZZER
#define PENUMBRA_FUZZ_ENTRY(name)                                                     \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return penumbra::fuzz::run(penumbra_fuzz_##name, data, size);                     \
  }
#else
#define PENUMBRA_FUZZ_ENTRY(name)                                      \
  [[maybe_unused]] static const bool penumbra_fuzz_registered_##name = \
      penumbra::fuzz::register_target(#name, penumbra_fuzz_##name);
#endif

#define PENUMBRA_FUZZ_TARGET(name)                                              \
  static void penumbra_fuzz_##name(const std::uint8_t* data, std::size_t size); \
  PENUMBRA_FUZZ_ENTRY(name)                                                     \
  static void penumbra_fuzz_##name(const std::uint8_t* data, std::size_t size)
