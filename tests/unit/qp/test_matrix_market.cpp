/// Matrix Market reading and writing (la/matrix_market.hpp), the input format of `feticon qp`.
/// (It tests a la function; it lives here because `feticon qp` is its only user so far.)

#include "common/error.hpp"
#include "la/matrix_market.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace feticon;

namespace
{
using la::infinity;

/// A fresh directory per test, removed at the end.
class MatrixMarket : public testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "feticon_mm_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    _directory = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(_directory); }

  std::string write(const std::string& name, const std::string& text) const
  {
    const std::string path = (_directory / name).string();
    std::ofstream(path) << text;
    return path;
  }

  /// The message of the feticon::Error thrown when `text` is read as a sparse matrix or a
  /// vector; fails the test if nothing is thrown.
  std::string error_of(const std::string& text, bool sparse) const
  {
    const std::string path = write("bad.mtx", text);
    try
    {
      if (sparse)
        la::read_matrix_market_sparse(path);
      else
        la::read_matrix_market_dense(path);
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
      EXPECT_EQ(message.rfind(path, 0), 0u) << "starts with the file name: " << message;
      return message;
    }
    ADD_FAILURE() << "accepted malformed file:\n" << text;
    return "";
  }

  std::filesystem::path _directory;
};
} // namespace

// Reference: %.17g round-trips every double (IEEE 754: 17 significant digits suffice).
TEST_F(MatrixMarket, DenseRoundTripIsExact)
{
  la::Vector v(7);
  v << 1.0 / 3.0, -2.5e-300, 6.02214076e23, 0.0, -infinity, infinity, std::nextafter(1.0, 2.0);
  const std::string path = (_directory / "v.mtx").string();
  la::write_matrix_market_dense(path, v);
  const la::Vector back = la::read_matrix_market_dense(path);
  ASSERT_EQ(back.size(), v.size());
  for (la::Index i = 0; i < v.size(); ++i)
    EXPECT_EQ(back[i], v[i]) << i;
  EXPECT_EQ(la::read_matrix_market_dense(write("empty.mtx",
                                               "%%MatrixMarket matrix array "
                                               "real general\n0 1\n"))
                .size(),
            0);
}

// Reference: the NIST Matrix Market specification: a symmetric file stores one triangle;
// duplicates of a coordinate file are summed (as Eigen's setFromTriplets does).
TEST_F(MatrixMarket, SparseGeneralAndSymmetric)
{
  const la::SparseMatrix general =
      la::read_matrix_market_sparse(write("g.mtx",
                                          "%%MatrixMarket matrix coordinate real general\n% comment\n\n2 3 4\n"
                                          "1 1 1.5\n2 3 -2\n1 3 4e1\n1 1 0.5\n"));
  la::Matrix expected(2, 3);
  expected << 2.0, 0.0, 40.0, 0.0, 0.0, -2.0;
  EXPECT_EQ(la::Matrix(general), expected);

  const la::SparseMatrix lower =
      la::read_matrix_market_sparse(write("s.mtx",
                                          "%%MatrixMarket matrix coordinate integer symmetric\r\n3 3 4\r\n"
                                          "1 1 4\r\n2 1 -1\r\n3 2 -1\r\n3 3 4\r\n"));
  la::Matrix symmetric(3, 3);
  symmetric << 4, -1, 0, -1, 0, -1, 0, -1, 4;
  EXPECT_EQ(la::Matrix(lower), symmetric);
  const la::SparseMatrix upper =
      la::read_matrix_market_sparse(write("u.mtx",
                                          "%%MATRIXMARKET Matrix Coordinate Real Symmetric\n3 3 3\n1 1 4\n1 2 -1\n"
                                          "2 3 -1\n"));
  symmetric(2, 2) = 0.0;
  EXPECT_EQ(la::Matrix(upper), symmetric);
}

// Reference: strtod accepts inf, -inf, Inf, -Infinity (C standard 7.22.1.3); bounds use -inf
// for unbounded components.
TEST_F(MatrixMarket, InfinitiesAndCoordinateVectors)
{
  const la::Vector v =
      la::read_matrix_market_dense(write("l.mtx",
                                         "%%MatrixMarket matrix array real general\n5 1\ninf\n-inf\nInf\n"
                                         "-Infinity\n  -1.25  \n"));
  ASSERT_EQ(v.size(), 5);
  EXPECT_EQ(v[0], infinity);
  EXPECT_EQ(v[1], -infinity);
  EXPECT_EQ(v[2], infinity);
  EXPECT_EQ(v[3], -infinity);
  EXPECT_EQ(v[4], -1.25);

  const la::Vector c =
      la::read_matrix_market_dense(write("c.mtx",
                                         "%%MatrixMarket matrix coordinate real general\n4 1 2\n2 1 -inf\n"
                                         "4 1 3\n"));
  la::Vector expected(4);
  expected << 0.0, -infinity, 0.0, 3.0;
  EXPECT_EQ(c, expected);
}

// Reference: STYLE.md, Errors: every malformed input throws one line naming the file, the
// line and what is wrong.
TEST_F(MatrixMarket, MalformedFilesAreRejectedNamingTheLine)
{
  const std::string sparse_header = "%%MatrixMarket matrix coordinate real general\n";
  const std::string dense_header = "%%MatrixMarket matrix array real general\n";
  struct Case
  {
    std::string text;
    bool sparse;
    std::string expected;
  };
  const Case cases[] = {
      {"", true, ":1: empty file"},
      {"%MatrixMarket matrix coordinate real general\n1 1 1\n1 1 1\n", true, ":1: expected"},
      {"%%MatrixMarket matrix coordinate complex general\n", true, ":1: unsupported field"},
      {"%%MatrixMarket matrix coordinate pattern general\n", true, ":1: unsupported field"},
      {"%%MatrixMarket matrix coordinate real hermitian\n", true, ":1: unsupported symmetry"},
      {"%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n4\n", true, ":1: a sparse"},
      {sparse_header, true, ":2: file ends before the size line"},
      {sparse_header + "2 2\n", true, ":2: expected an integer entry count"},
      {sparse_header + "2 2 3\n1 1 1\n2 2 1\n", true, ":5: file ends after 2 of 3 entries"},
      {sparse_header + "2 2 1\n1 1 1\n2 2 1\n", true, ":4: more entries than the 1 declared"},
      {sparse_header + "2 2 1\n3 1 1\n", true, ":3: row index 3 out of range 1..2"},
      {sparse_header + "2 2 1\n1 0 1\n", true, ":3: column index 0 out of range 1..2"},
      {sparse_header + "2 2 1\n1 1 abc\n", true, ":3: expected a number value, found 'abc'"},
      {sparse_header + "2 2 1\n1 1 1.5x\n", true, ":3: expected a number value, found '1.5x'"},
      {sparse_header + "2 2 1\n1 1 1 7\n", true, ":3: unexpected text '7'"},
      {sparse_header + "2 2 1\n1.5 1 1\n", true, ":3: expected an integer row index"},
      {sparse_header + "-2 2 0\n", true, ":2: row count = -2"},
      {sparse_header + "2 2 5\n", true, ":2: entry count 5 must be in 0..rows*columns"},
      {"%%MatrixMarket matrix coordinate real symmetric\n2 3 1\n", true, ":2: a symmetric"},
      {"%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n2 1 1\n1 2 1\n", true,
       ":4: symmetric file stores entries of both triangles"},
      {dense_header + "3 1\n1\n2\n", false, ":5: file ends after 2 of 3 values"},
      {dense_header + "2 1\n1\n2\n3\n", false, ":5: more values than the 2 declared"},
      {dense_header + "2 2\n1\n2\n3\n4\n", false, ":2: expected a column vector"},
      {dense_header + "2 1\n1\nnope\n", false, ":4: expected a number value, found 'nope'"},
      {dense_header + "2 1\n1 2\n", false, ":3: unexpected text '2'"},
      {sparse_header + "2 2 1\n1 1 1\n", false, ":2: expected a column vector"},
      {"%%MatrixMarket matrix array real symmetric\n1 1\n1\n", false, ":1: a vector file"},
  };
  for (const Case& c : cases)
  {
    const std::string message = error_of(c.text, c.sparse);
    EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
  }

  const std::string missing = (_directory / "missing.mtx").string();
  EXPECT_THROW(la::read_matrix_market_sparse(missing), Error);
  EXPECT_THROW(la::read_matrix_market_dense(missing), Error);
  EXPECT_THROW(la::write_matrix_market_dense((_directory / "no/such/dir.mtx").string(), la::Vector::Zero(1)), Error);
}
