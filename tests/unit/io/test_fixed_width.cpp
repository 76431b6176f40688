/// Tests of the fixed-width number fields of the .frd and .dat writers. References: glibc's
/// snprintf for the C fields; for the Fortran fields, what gfortran 12.2 prints for the edit
/// descriptors of CalculiX's printout.f (program written out in each test's comment), and
/// lines of the .dat ccx 2.20 wrote (tests/data/calculix_results/two_blocks_dat.dat).

#include "io/fixed_width.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

namespace feticon::io
{
namespace
{
std::string c_exponential(double value, int width, int precision)
{
  std::string out;
  append_c_exponential(out, value, width, precision);
  return out;
}

std::string fortran_1pe(double value)
{
  std::string out;
  append_fortran_1pe(out, value, 13, 6);
  return out;
}

std::string fortran_e(double value)
{
  std::string out;
  append_fortran_e(out, value, 14, 7);
  return out;
}

TEST(FixedWidth, CExponentialIsPrintf)
{
  // Reference: snprintf("%12.5E") and ("%13.6E"), over values of every magnitude and sign,
  // including the float-rounded values the .frd writer passes.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int i = 0; i < 20000; ++i)
  {
    double value = mantissa(random) * std::pow(10.0, exponent(random));
    if (i % 2)
      value = static_cast<float>(value);
    for (const auto& [width, precision] : {std::pair{12, 5}, std::pair{13, 6}})
    {
      char expected[64];
      std::snprintf(expected, sizeof expected, "%*.*E", width, precision, value);
      ASSERT_EQ(c_exponential(value, width, precision), expected) << value;
    }
  }
  for (const double value : {0.0, -0.0, 1.0, 0.5, 9.999995, 9.999994999, 1e-45, 3.4e38})
  {
    char expected[64];
    std::snprintf(expected, sizeof expected, "%12.5E", value);
    EXPECT_EQ(c_exponential(value, 12, 5), expected);
  }
  EXPECT_EQ(c_exponential(std::numeric_limits<double>::infinity(), 12, 5), "         INF");
}

TEST(FixedWidth, FortranFieldsAreGfortrans)
{
  // Reference: gfortran 12.2, write(*,'(1p,e13.6)') v and write(*,'(e14.7)') v, for
  // v = 0, -0, 1, -1e-100, 1.234567891e150, 0.99999996, 1.147944e-41, -6.219018e-9, 1e300,
  // 0.5, -0.5, 123456.7.
  EXPECT_EQ(fortran_1pe(0.0), " 0.000000E+00");
  EXPECT_EQ(fortran_1pe(-0.0), "-0.000000E+00");
  EXPECT_EQ(fortran_1pe(1.0), " 1.000000E+00");
  EXPECT_EQ(fortran_1pe(-1e-100), "-1.000000-100");
  EXPECT_EQ(fortran_1pe(1.234567891e150), " 1.234568+150");
  EXPECT_EQ(fortran_1pe(0.99999996), " 1.000000E+00");
  EXPECT_EQ(fortran_1pe(1.147944e-41), " 1.147944E-41");
  EXPECT_EQ(fortran_1pe(-6.219018e-9), "-6.219018E-09");
  EXPECT_EQ(fortran_1pe(1e300), " 1.000000+300");
  EXPECT_EQ(fortran_1pe(123456.7), " 1.234567E+05");

  EXPECT_EQ(fortran_e(0.0), " 0.0000000E+00");
  EXPECT_EQ(fortran_e(-0.0), "-0.0000000E+00");
  EXPECT_EQ(fortran_e(1.0), " 0.1000000E+01");
  EXPECT_EQ(fortran_e(-1e-100), "-0.1000000E-99");
  EXPECT_EQ(fortran_e(1.234567891e150), " 0.1234568+151");
  EXPECT_EQ(fortran_e(0.99999996), " 0.1000000E+01");
  EXPECT_EQ(fortran_e(1.147944e-41), " 0.1147944E-40");
  EXPECT_EQ(fortran_e(-6.219018e-9), "-0.6219018E-08");
  EXPECT_EQ(fortran_e(1e300), " 0.1000000+301");
  EXPECT_EQ(fortran_e(0.5), " 0.5000000E+00");
  EXPECT_EQ(fortran_e(-0.5), "-0.5000000E+00");
  EXPECT_EQ(fortran_e(123456.7), " 0.1234567E+06");
  // The time of ccx's headers: "... for set NBIGCUBE and time  0.2000000E+01".
  EXPECT_EQ(fortran_e(2.0), " 0.2000000E+01");
}

TEST(FixedWidth, IntegersAreRightJustified)
{
  // Reference: printf("%10lld") / Fortran I10 of the .dat and .frd label columns.
  std::string out;
  append_integer(out, 101, 10);
  append_integer(out, 9'999'999'999, 10);
  append_integer(out, 3, 3);
  EXPECT_EQ(out, "       1019999999999  3");
}
} // namespace
} // namespace feticon::io
