#pragma once
// FORMAT_R of IMPR_RESU FORMAT='RESULTAT': a Fortran edit descriptor for real values, as
// code_aster writes them: [kP]Ew.d, [kP]Dw.d, ESw.d, Fw.d (k the scale factor, w the field
// width, d the digits after the point). Ew.d without a scale factor writes 0.ddddE+xx (the
// mantissa in [0.1, 1)); 1PEw.d writes d.dddE+xx. A value wider than w is written whole (Fortran
// would print asterisks), so no number is lost.

#include <optional>
#include <string>

namespace stella {

struct RealEditDescriptor {
  char kind = 'E'; // 'E' (also D and ES), 'F'
  char exponentLetter = 'E';
  int scale = 0; // the kP scale factor of E and D (ES is 1P)
  int width = 21;
  int digits = 14;
};

// The descriptor of `text` ('1PE21.14', 'E12.5', 'F10.3', 'ES15.6'; case-insensitive), or
// nothing when `text` is none of those forms.
std::optional<RealEditDescriptor> parseRealEditDescriptor(const std::string& text);

// `value` written with `d`, right-aligned in d.width characters.
std::string formatReal(const RealEditDescriptor& d, double value);

} // namespace stella
