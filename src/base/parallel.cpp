#include "penumbra/base/parallel.h"

#include <tbb/global_control.h>

#include <cstdlib>

namespace penumbra {

void apply_thread_limit() {
  // never destroyed: the limit holds until the process ends, past static destruction
  static const tbb::global_control* const limit = []() -> tbb::global_control* {
    const char* text = std::getenv("PENUMBRA_THREADS");
    if (text == nullptr) return nullptr;
    char* end = nullptr;
    const long threads = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || threads < 1) return nullptr;
    return new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                   static_cast<std::size_t>(threads));
  }();
  (void)limit;
}

}  // namespace penumbra
