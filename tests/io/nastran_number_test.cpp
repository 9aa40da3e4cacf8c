// Nastran number formats (MSC Nastran QRG, "Format of Bulk Data Entries": reals need a decimal point
// or an exponent, the exponent letter may be E, D or omitted when the sign follows the mantissa).
#include <gtest/gtest.h>

#include "seflex/io/nastran_number.hpp"

using namespace seflex::io::nastran;

namespace {
double real(const char* s) {
  double x = -999;
  EXPECT_TRUE(parse_real(s, x)) << s;
  return x;
}
bool is_real(const char* s) {
  double x = 0;
  return parse_real(s, x);
}
}  // namespace

TEST(NastranNumber, RealsInEveryNastranForm) {
  // The values are the decimal meaning of each form, written out by hand.
  EXPECT_DOUBLE_EQ(real("7.1+10"), 7.1e10);
  EXPECT_DOUBLE_EQ(real("3.60-4"), 3.60e-4);
  EXPECT_DOUBLE_EQ(real(".5"), 0.5);
  EXPECT_DOUBLE_EQ(real("1.E4"), 1.0e4);
  EXPECT_DOUBLE_EQ(real("-2-3"), -2.0e-3);
  EXPECT_DOUBLE_EQ(real("1.0D3"), 1.0e3);
  EXPECT_DOUBLE_EQ(real("1.0d-3"), 1.0e-3);
  EXPECT_DOUBLE_EQ(real("10.+06"), 1.0e7);
  EXPECT_DOUBLE_EQ(real("1."), 1.0);
  EXPECT_DOUBLE_EQ(real("+1.5"), 1.5);
  EXPECT_DOUBLE_EQ(real("-.25E+2"), -25.0);
  EXPECT_DOUBLE_EQ(real("1E4"), 1.0e4);
  EXPECT_DOUBLE_EQ(real("0."), 0.0);
  EXPECT_DOUBLE_EQ(real("-0.0"), 0.0);
  EXPECT_DOUBLE_EQ(real("1.234567890123456"), 1.234567890123456);
}

TEST(NastranNumber, NotReals) {
  for (const char* s : {"", "12", "-3", ".", "1.E", "1.2.3", "E4", "1.0E+", "1..", "1 0", "1.0 ", "abc", "1.0X",
                        "1.0E4.5", "inf", "nan", "--1.", "1.-", "1.E400"})
    EXPECT_FALSE(is_real(s)) << "'" << s << "'";
}

TEST(NastranNumber, Integers) {
  int i = 0;
  EXPECT_TRUE(parse_int("12", i));
  EXPECT_EQ(i, 12);
  EXPECT_TRUE(parse_int("-3", i));
  EXPECT_EQ(i, -3);
  EXPECT_TRUE(parse_int("+7", i));
  EXPECT_EQ(i, 7);
  EXPECT_TRUE(parse_int("2147483647", i));
  EXPECT_EQ(i, 2147483647);
  for (const char* s : {"", "1.", "1.0", "2147483648", "+-3", "-", "+", "1 2", "12a", "1E4", "0x10"})
    EXPECT_FALSE(parse_int(s, i)) << "'" << s << "'";
}

TEST(NastranNumber, Classify) {
  EXPECT_EQ(classify(""), FieldKind::Blank);
  EXPECT_EQ(classify("12"), FieldKind::Integer);
  EXPECT_EQ(classify("1."), FieldKind::Real);
  EXPECT_EQ(classify("-2-3"), FieldKind::Real);
  EXPECT_EQ(classify("GGG"), FieldKind::Text);
  EXPECT_EQ(classify("THRU"), FieldKind::Text);
  EXPECT_EQ(classify("1.2.3"), FieldKind::Invalid);
  EXPECT_EQ(classify("+C1"), FieldKind::Invalid);
}

TEST(NastranNumber, QuoteFieldEscapesBinary) {
  EXPECT_EQ(quote_field("AB"), "'AB'");
  EXPECT_EQ(quote_field(std::string_view("A\0B", 3)), "'A\\x00B'");
  EXPECT_EQ(quote_field(std::string(100, 'x')), "'" + std::string(40, 'x') + "...'");
}
