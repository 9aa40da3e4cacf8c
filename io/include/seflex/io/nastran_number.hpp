#pragma once
// Numbers as Nastran writes them in bulk-data fields (MSC Nastran QRG, "Format of Bulk Data Entries"):
//   integers   12  -3  +7
//   reals      1.  .5  -2.5  1.E4  1.0D3  7.1+10  3.60-4  -2-3  1E4
// A real has a decimal point or an exponent; the exponent letter may be E or D or left out when the
// exponent's sign follows the mantissa directly ("7.1+10" = 7.1e10, "-2-3" = -2e-3).
// Fields are passed already trimmed of surrounding blanks; embedded blanks make a field invalid.
#include <string>
#include <string_view>

namespace seflex::io::nastran {

enum class FieldKind { Blank, Integer, Real, Text, Invalid };

/// What a trimmed field holds. Text starts with a letter; Invalid is neither number nor text
/// ("1.2.3", "12a", "1 0").
FieldKind classify(std::string_view field);

/// Integer field: [+-]digits fitting in an int. False if the text is anything else.
bool parse_int(std::string_view field, int& value);

/// Real field in any of the forms above (an integer is not accepted: use classify first when a field
/// may hold either). False if the text is not a real or overflows a double.
bool parse_real(std::string_view field, double& value);

/// `field` quoted for an error message: non-printable bytes as \xNN, long text shortened.
std::string quote_field(std::string_view field);

}  // namespace seflex::io::nastran
