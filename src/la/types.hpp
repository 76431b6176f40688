#pragma once
/// @file Eigen aliases used throughout feticon.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cstdint>
#include <limits>

namespace feticon::la
{
using Index = Eigen::Index;
using Vector = Eigen::VectorXd;
/// An absent bound (+infinity) and the start of a minimum search.
inline constexpr double infinity = std::numeric_limits<double>::infinity();
using Matrix = Eigen::MatrixXd;
/// Column-major with 32-bit indices: what Eigen's CHOLMOD wrapper and METIS expect.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
} // namespace feticon::la
