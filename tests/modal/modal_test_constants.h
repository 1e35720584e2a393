#pragma once
// Constants of several modal tests, defined once: the test files share one translation unit in
// a unity build (docs/ci.md).

namespace modaltyre::modal::test {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;
/// The ring of data/README: mass per unit length [kg/m] and radius [m].
inline constexpr double kMu = 2.5, kR = 0.2948;

}  // namespace modaltyre::modal::test
