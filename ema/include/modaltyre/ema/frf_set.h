#pragma once
// Frequency response functions of a hammer test, as the readers (UFF 58, long CSV) deliver
// them to the identification: one shared frequency grid, one complex series per
// (response DOF, reference DOF) pair, every DOF a point of the tyre in its local radial or
// tangential direction (docs/ema.md: UFF direction +-3 radial, +-1 tangential; a negative
// direction is turned into the positive one by a sign change on reading).
#include <complex>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace modaltyre::ema {

/// What the FRF measures per newton of force; the value is the power of (j omega) that turns
/// receptance into it: mobility = j omega x receptance, accelerance = (j omega)^2 x receptance.
enum class FrfType { receptance = 0, mobility = 1, accelerance = 2 };

const char* to_string(FrfType type);
/// "accelerance", "mobility" or "receptance"; anything else is an InputError naming `where`.
FrfType parse_frf_type(const std::string& text, const std::string& where);

enum class Direction { radial, tangential };
const char* to_string(Direction d);

/// A degree of freedom: a measurement point and its local direction.
struct Dof {
  int point = 0;  ///< point number as in the file, 1 ... kMaxPointNumber
  Direction dir = Direction::radial;
  bool operator==(const Dof&) const = default;
};
std::string to_string(const Dof& d);  ///< e.g. "point 3 radial"

/// Point numbers are written to the hammer CSV, whose reader takes 1 ... 1e6.
inline constexpr int kMaxPointNumber = 1000000;

struct FrfChannel {
  Dof response;
  Dof reference;
  std::vector<std::complex<double>> values;  ///< H at FrfSet::freq_hz, SI units
  int line = 0;  ///< line of the file where this FRF starts (UFF: its dataset; CSV: first row)
};

/// Bounds every reader enforces (a hammer test has tens of FRFs of a few thousand lines).
struct FrfLimits {
  std::size_t max_bytes = std::size_t{128} << 20;  ///< file size
  std::size_t max_channels = 4096;
  std::size_t max_lines = 200000;     ///< spectral lines per FRF
  std::size_t max_values = 20000000;  ///< channels x lines (16 bytes each)
};

struct FrfSet {
  std::string path;
  FrfType type = FrfType::accelerance;
  bool type_from_file = false;  ///< the file stated the type (UFF records 9-10)
  std::vector<double> freq_hz;  ///< strictly increasing, >= 0
  std::vector<FrfChannel> channels;
  /// Angle of each point around the tyre from the file's geometry (UFF datasets 15/2411, 0 at
  /// the lowest-numbered point); empty without one (points then equally spaced in number order).
  std::map<int, double> point_angle_deg;
};

/// Multiplies every value by (j omega)^(to - from): receptance -> mobility -> accelerance and
/// back. Lowering the power divides by j omega, so a line at 0 Hz is then an InputError.
FrfSet convert_frf_type(const FrfSet& set, FrfType to);

/// Checks a finished set (shared grid strictly increasing, sizes within limits, no duplicate
/// DOF pair, finite values) and throws InputError naming the channel's line otherwise. Both
/// readers end with it.
void check_frf_set(const FrfSet& set, const FrfLimits& limits);

}  // namespace modaltyre::ema
