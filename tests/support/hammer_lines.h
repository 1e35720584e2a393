#pragma once
// Builders of small hammer CSV files for the reader and CLI tests: a valid file as lines, and a
// helper that corrupts one field.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace modaltyre_test {

/// Lines of a valid file: `modes` modes of order 2 at N equally spaced points (line 1 = header,
/// mode m point i on line 2 + m*N + i).
inline std::vector<std::string> hammer_lines(int N = 12, int modes = 2) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<std::string> l = {"mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential"};
  for (int m = 0; m < modes; ++m) {
    for (int i = 0; i < N; ++i) {
      const double th = 2 * kPi * i / N;
      std::ostringstream s;
      s << m + 1 << ',' << 100 + 20 * m << ",0.03," << i + 1 << ',' << 360.0 * i / N << ','
        << 0.6 * std::cos(2 * th) << ',' << 0.3 * std::sin(2 * th);
      l.push_back(s.str());
    }
  }
  return l;
}

/// Replaces field `col` (0-based) of line `line` (1-based).
inline void set_field(std::vector<std::string>& l, int line, int col, const std::string& v) {
  std::vector<std::string> f;
  std::stringstream in(l[line - 1]);
  for (std::string c; std::getline(in, c, ',');) f.push_back(c);
  f[col] = v;
  std::string out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i) out.push_back(',');
    out.append(f[i]);
  }
  l[line - 1] = out;
}

}  // namespace modaltyre_test
