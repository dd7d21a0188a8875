#pragma once
// The mathematical constants penumbra uses, named once.

namespace penumbra {

inline constexpr double pi = 3.14159265358979323846;

}  // namespace penumbra
