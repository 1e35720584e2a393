#pragma once
// A small writer of UFF dataset 58 in the specification's fixed columns (ASCII) and of the
// binary variant 58b, for the reader tests: records 6-11 with the Fortran formats of the
// specification, record 12 as 6E13.5 (single precision), 4E20.12 (double, even spacing),
// 2(E13.5,E20.12) (real double, uneven) or E13.5,2E20.12 (complex double, uneven).
#include <bit>
#include <complex>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre_test {

struct UffOptions {
  bool binary = false;
  bool double_precision = true;
  bool even = true;
  bool complex = true;
  bool big_endian = false;          ///< binary only
  bool blank_after_binary = false;  ///< a newline between the data bytes and "    -1"
  int numerator_type = 12;          ///< record 9 field 1: 12 accel., 11 velocity, 8 displacement
  int function_type = 4;            ///< record 6 field 1: 4 FRF, 6 coherence ...
  bool negative_response = false;   ///< write the response direction as -3 / -1 (values negated)
  /// The direction codes written for radial and tangential DOFs: 3 and 1 in the implied local
  /// frame; 1 and 2 (r, theta) in a cylindrical displacement system of a file's geometry.
  int radial_code = 3, tangential_code = 1;
};

inline std::string fmt(const char* f, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}

/// The values of record 12 in order (abscissa interleaved when uneven).
inline std::vector<double> uff_values(const std::vector<double>& f,
                                      const std::vector<std::complex<double>>& h, double sign,
                                      const UffOptions& o) {
  std::vector<double> v;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!o.even) v.push_back(f[i]);
    v.push_back(sign * h[i].real());
    if (o.complex) v.push_back(sign * h[i].imag());
  }
  return v;
}

inline std::string uff58_dataset(const modaltyre::ema::FrfChannel& ch, const std::vector<double>& f,
                                 const UffOptions& o) {
  using modaltyre::ema::Direction;
  const int rdir = (ch.response.dir == Direction::radial ? o.radial_code : o.tangential_code) *
                   (o.negative_response ? -1 : 1);
  const int fdir = ch.reference.dir == Direction::radial ? o.radial_code : o.tangential_code;
  const int ord = o.complex ? (o.double_precision ? 6 : 5) : (o.double_precision ? 4 : 2);
  const auto v = uff_values(f, ch.values, o.negative_response ? -1.0 : 1.0, o);
  std::string s = "    -1\n";
  s += o.binary ? fmt("%6d%1s%6d%6d%12d%12d%6d%6d%12d%12d\n", 58, "b", o.big_endian ? 2 : 1, 2, 11,
                      int(v.size() * (o.double_precision ? 8 : 4)), 0, 0, 0, 0)
                : fmt("%6d\n", 58);
  s += "hammer FRF\nNONE\n01-Jan-24 00:00:00\nmodaltyre test writer\nNONE\n";
  s += fmt("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", o.function_type, 1, 0, 0, "NONE",
           ch.response.point, rdir, "NONE", ch.reference.point, fdir);
  s += fmt("%10d%10d%10d%13.5e%13.5e%13.5e\n", ord, int(f.size()), o.even ? 1 : 0,
           o.even ? f[0] : 0.0, o.even ? f[1] - f[0] : 0.0, 0.0);
  s += fmt("%10d%5d%5d%5d %-20s %-20s\n", 18, 0, 0, 0, "Frequency", "Hz");
  s += fmt("%10d%5d%5d%5d %-20s %-20s\n", o.numerator_type, 1, 0, 0, "Response", "m/s^2");
  s += fmt("%10d%5d%5d%5d %-20s %-20s\n", 13, 0, 1, 0, "Force", "N");
  s += fmt("%10d%5d%5d%5d %-20s %-20s\n", 0, 0, 0, 0, "NONE", "NONE");
  if (o.binary) {
    for (double x : v) {
      unsigned char b[8];
      std::size_t n = o.double_precision ? 8 : 4;
      if (o.double_precision) {
        std::memcpy(b, &x, 8);
      } else {
        const float y = static_cast<float>(x);
        std::memcpy(b, &y, 4);
      }
      if (o.big_endian == (std::endian::native == std::endian::little)) {
        for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
      }
      s.append(reinterpret_cast<const char*>(b), n);
    }
    if (o.blank_after_binary) s += "\n";
    return s + "    -1\n";
  }
  const std::size_t per = !o.double_precision ? 6 : o.even ? 4 : o.complex ? 3 : 4;
  for (std::size_t i = 0; i < v.size(); ++i) {
    int w = 20;
    if (!o.double_precision) {
      w = 13;
    } else if (!o.even) {
      w = (i % (o.complex ? 3 : 2) == 0) ? 13 : 20;
    }
    s += w == 13 ? fmt("%13.5e", v[i]) : fmt("%20.12e", v[i]);
    if ((i + 1) % per == 0 || i + 1 == v.size()) s += "\n";
  }
  return s + "    -1\n";
}

/// A whole file: every channel of the set, in order.
inline std::string uff58_file(const modaltyre::ema::FrfSet& set, const UffOptions& o = {}) {
  std::string s;
  for (const auto& ch : set.channels) s += uff58_dataset(ch, set.freq_hz, o);
  return s;
}

}  // namespace modaltyre_test
