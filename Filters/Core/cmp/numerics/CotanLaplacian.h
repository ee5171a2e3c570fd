#pragma once
/// \file CotanLaplacian.h
/// \brief The cotangent Laplacian of a triangle mesh (Pinkall and Polthier
///        1993): the stiffness matrix of piecewise linear functions, the
///        reference system whose factorization the issue measures the
///        pipeline's speed against.

#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/SparseCore>

namespace cmp
{

/// \brief The n x n cotangent Laplacian of `mesh`: entry (i, j) of an edge
///        is -(cot alpha + cot beta) / 2, alpha and beta the angles facing
///        it (one on a boundary edge), and each diagonal entry makes its row
///        sum to 0. Symmetric positive semi-definite, its kernel the
///        constants on each connected part. A degenerate triangle's angles count as cot 0.
Eigen::SparseMatrix<double> cotanLaplacian(const TriangleMesh& mesh);

} // namespace cmp
