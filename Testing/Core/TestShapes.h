#pragma once
/// \file TestShapes.h
/// \brief Collections of models with one connectivity for the alignment,
///        PCA and blending tests: smooth deformations and similarity
///        motions of one mesh, and their split over ranks.

#include <cmp/analysis/ProcrustesAlignment.h>
#include <cmp/analysis/ShapeCollection.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <random>
#include <vector>

namespace cmp::test
{

/// \brief A torus (genus 1) made of an n-by-m grid: n*m vertices.
TriangleMesh torus(int n, int m);

/// \brief A smooth displacement field over `points`: a product of sine
///        waves of the coordinates, different for every `seed`, of largest
///        component about `amplitude`.
std::vector<Vec3> smoothField(const std::vector<Vec3>& points, double amplitude, unsigned seed);

/// \brief `modelCount` models `base + sum_j a_ij * fields[j]`, with a_ij
///        drawn uniformly from [-1, 1] (seeded by `seed`).
ShapeList deformedCopies(
  const std::vector<Vec3>& base, const std::vector<std::vector<Vec3>>& fields, int modelCount, unsigned seed);

/// \brief A rotation drawn uniformly from `random`.
Eigen::Matrix3d randomRotation(std::mt19937& random);

/// \brief A similarity with a random rotation, translation up to
///        `translation` per axis and scale in [minScale, maxScale].
SimilarityTransform randomSimilarity(std::mt19937& random, double translation, double minScale, double maxScale);

/// \brief `points` moved by `transform`.
std::vector<Vec3> moved(const std::vector<Vec3>& points, const SimilarityTransform& transform);

/// \brief The models rank `rank` holds when `models` are spread
///        `modelsPerRank[r]` to rank r in order.
ShapeList partForRank(const ShapeList& models, const std::vector<int>& modelsPerRank, int rank);

/// \brief The mean of `points`.
Vec3 centroid(const std::vector<Vec3>& points);

/// \brief Largest distance between corresponding vertices (infinite when
///        the vertex counts differ).
double maxDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

} // namespace cmp::test
