#pragma once
// Number formatting shared by written files and messages: one place for "%.10g" (the digits of
// an augmented config, a sweep CSV, a note) and for rounding to significant digits (JSON output,
// notes), so that a value printed twice is printed the same way.
#include <string>

namespace modaltyre {

/// `v` with 10 significant digits, shortest form ("%.10g"): 0.97678, 1.465481793, 1e-05.
std::string number_text(double v);

/// `v` rounded to `digits` significant digits (0, inf and NaN unchanged).
double round_sig(double v, int digits = 10);

}  // namespace modaltyre
